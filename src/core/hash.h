/*
** hash.h - BLAKE2b (RFC 7693), unkeyed, over a buffer in memory.
** The checksum of mvmpm's HDF5 files (h5sum.h).  Python's
** hashlib.blake2b(data, digest_size=n) and coreutils' b2sum -l 8n give
** the same digest, so a file can be checked without mvmpm.
*/
#ifndef mvmpm_hash_h
#define mvmpm_hash_h

#include <stddef.h>

#define HASH_MAXLEN 64

/* the BLAKE2b digest of n bytes at p, outlen (1..64) bytes into out */
void hash_blake2b(const void *p, size_t n, unsigned char *out, size_t outlen);

#endif
