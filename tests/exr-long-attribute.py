#!/usr/bin/env python3
"""exr-long-attribute.py IN.exr OUT.exr: copies a single-part scanline EXR
with one more string attribute of hstrace's, whose name is 40 bytes long (the file's
long-names flag set, the chunk offsets moved by what the header grew). OpenEXR reads such a file; a writer asked to copy that
attribute into a file of its own must refuse it with a message (names of
32 bytes or more need the long-names flag, which hstrace's writer does not
set). Python 3's standard library only."""
import struct
import sys

data = open(sys.argv[1], "rb").read()
magic, version = struct.unpack_from("<II", data, 0)
if magic != 20000630 or version & 0x1000:
    sys.exit("exr-long-attribute.py: not a single-part EXR: " + sys.argv[1])
pos = 8
out = bytearray(data[:8])
struct.pack_into("<I", out, 4, version | 0x400)
long_name = b"hstrace.a-name-of-forty-bytes-for-writer"
assert len(long_name) == 40
grown = 0
while data[pos] != 0:
    end = data.index(b"\0", pos)
    name = data[pos:end]
    tend = data.index(b"\0", end + 1)
    kind = data[end + 1 : tend]
    (size,) = struct.unpack_from("<i", data, tend + 1)
    value = data[tend + 5 : tend + 5 + size]
    out += name + b"\0" + kind + b"\0" + struct.pack("<i", size) + value
    pos = tend + 5 + size
extra = long_name + b"\0string\0" + struct.pack("<i", 4) + b"long"
out += extra + b"\0"
grown = len(extra)
pos += 1
(first,) = struct.unpack_from("<Q", data, pos)
count = (first - pos) // 8
for i in range(count):
    (off,) = struct.unpack_from("<Q", data, pos + 8 * i)
    out += struct.pack("<Q", off + grown)
out += data[pos + 8 * count :]
open(sys.argv[2], "wb").write(out)
