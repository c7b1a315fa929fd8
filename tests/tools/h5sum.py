#!/usr/bin/python3
"""tests/tools/h5sum.py - the checksum block of mvmpm's HDF5 files.

    h5sum.py check FILE...   0 when every FILE's block matches its bytes
    h5sum.py seal FILE...    write the block for the bytes as they are now

The block (docs/stability.md, src/io/h5sum.h): the first 512 bytes, an
HDF5 user block, hold
    mvmpm checksum 1: blake2b-256 of the NNNNNNNNNNNNNNNNNNNN bytes after the first 512:\\n
    <64 hex digits>\\n
and NUL bytes to the end of the block; NNN is the length of the rest of
the file, the hex digits its BLAKE2b-256.  Sealing an edited file makes
it pass the checksum again: the tests use it to reach mvmpm's field
checks with files edited by h5py.
"""
import hashlib
import sys

BLOCK = 512


def block(rest):
    head = "mvmpm checksum 1: blake2b-256 of the %020d bytes after the first %d:\n%s\n" % (
        len(rest), BLOCK, hashlib.blake2b(rest, digest_size=32).hexdigest())
    return head.encode().ljust(BLOCK, b"\0")


def main(argv):
    if len(argv) < 3 or argv[1] not in ("check", "seal"):
        sys.stderr.write(__doc__)
        return 2
    bad = 0
    for path in argv[2:]:
        with open(path, "rb") as f:
            data = f.read()
        want = block(data[BLOCK:])
        if argv[1] == "seal":
            with open(path, "r+b") as f:
                f.write(want)
        elif data[:BLOCK] != want:
            print("%s: checksum mismatch" % path)
            bad = 1
    return bad


if __name__ == "__main__":
    sys.exit(main(sys.argv))
