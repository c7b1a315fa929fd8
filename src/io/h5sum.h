/*
** h5sum.h - the checksum in front of mvmpm's HDF5 files.
**
** Every file mvmpm writes (snapshots and checkpoints) starts with a
** 512-byte HDF5 user block, which HDF5 and its tools (h5py, h5dump,
** ParaView) skip.  Once the image is complete its first line says
**   mvmpm checksum 1: blake2b-256 of the NNNNNNNNNNNNNNNNNNNN bytes after the first 512:\n
**   HHHH...(64 lower-case hex digits)\n
** with NNN the length of the rest of the file in 20 decimal digits and
** HHH its BLAKE2b-256 (hash.h); NUL bytes fill the block.  Readers load
** the whole file, rebuild the block from what follows it and compare all
** 512 bytes before HDF5 parses anything, then open the checked bytes
** from memory (never the file again: it could change in between).
** tests/tools/h5sum.py writes and checks the same block.
*/
#ifndef mvmpm_h5sum_h
#define mvmpm_h5sum_h

#include <stddef.h>

#define H5SUM_BLOCK 512

enum { H5SUM_OK, H5SUM_NONE };

/* put the block into the first H5SUM_BLOCK bytes of a whole image */
void h5sum_seal(unsigned char *img, size_t size);

/* Read the file at path whole into *img (malloc'ed, *size bytes) and
** check its block.  H5SUM_OK: sealed and intact; H5SUM_NONE: an HDF5
** file without the block (an older mvmpm, or rewritten by another tool):
** the caller decides; -1: err says why, naming the file ("checksum
** mismatch (damaged or edited; ...)", or that it cannot be read or is
** not HDF5), and *img is NULL. */
int h5sum_load(const char *path, void **img, size_t *size, char *err,
               size_t errlen);

#endif
