#!/usr/bin/env python3
"""Writes the damaged pictures of issue 20 into this folder (they are
committed; run again to remake them, with no arguments, from anywhere):

  png-truncated.png      a 16x16 PNG cut in the middle of its IDAT data
  png-0x0.png            a PNG whose IHDR says 0x0 pixels (libpng refuses to
                         write one: made here, with a correct CRC)
  png-100000x100000.png  a PNG whose IHDR says 100000x100000 pixels (CRC
                         correct), followed by the 16x16 picture's data
  png-interlaced-16384x16384.png  an interlaced PNG (which is reserved
                         whole before its data is read) of 16384x16384
                         pixels, 4 rows of data: far more than a file of
                         its size can inflate to
  jpg-truncated.jpg      scenes/textures/stone.jpg cut in the middle of its
                         entropy-coded data
  jpg-0x0.jpg            stone.jpg with 0x0 pixels in its frame header
  jpg-65535x65535.jpg    stone.jpg with 65535x65535 pixels in its frame
                         header: the most a JPEG can say (16-bit fields, so
                         100000x100000 cannot be written), past libjpeg's
                         65500
  jpg-65500x65500.jpg    stone.jpg with 65500x65500 pixels, as much as libjpeg
                         decodes, far past what hstrace reads (2^28 pixels)

Python 3's standard library only.
"""
import os
import struct
import zlib

here = os.path.dirname(os.path.abspath(__file__))
top = os.path.dirname(os.path.dirname(os.path.dirname(here)))


def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)


def png(width, height, rows, interlace=0):
    ihdr = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, interlace)  # 8-bit RGB
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b"")


def write(name, data):
    with open(os.path.join(here, name), "wb") as f:
        f.write(data)


# A 16x16 picture of noise-like bytes (so that deflate leaves it long
# enough to cut), each row with filter type 0.
rows = b"".join(b"\0" + bytes((x * 37 + y * 91 + (x * y) % 13) & 0xFF for x in range(48)) for y in range(16))
whole = png(16, 16, rows)
idat = whole.index(b"IDAT")
idat_len = struct.unpack(">I", whole[idat - 4:idat])[0]
write("png-truncated.png", whole[:idat + 4 + idat_len // 2])
write("png-0x0.png", png(0, 0, b""))
write("png-100000x100000.png", png(100000, 100000, rows))
write("png-interlaced-16384x16384.png", png(16384, 16384, bytes(4 * (1 + 3 * 16384)), 1))

with open(os.path.join(top, "scenes", "textures", "stone.jpg"), "rb") as f:
    jpeg = f.read()


def segment(data, marker):
    """The offset of the first segment with this marker (its 0xFF byte)."""
    i = 2
    while i + 4 <= len(data):
        if data[i] != 0xFF:
            raise ValueError("not at a marker")
        if data[i + 1] == marker:
            return i
        i += 2 + struct.unpack(">H", data[i + 2:i + 4])[0]
    raise ValueError("no marker %02x" % marker)


sos = segment(jpeg, 0xDA)
scan = sos + 2 + struct.unpack(">H", jpeg[sos + 2:sos + 4])[0]  # entropy-coded data from here
write("jpg-truncated.jpg", jpeg[:scan + (len(jpeg) - scan) // 2])
sof = segment(jpeg, 0xC0)  # baseline frame: FF C0, length, precision, height, width


def resized(width, height):
    return jpeg[:sof + 5] + struct.pack(">HH", height, width) + jpeg[sof + 9:]


write("jpg-0x0.jpg", resized(0, 0))
write("jpg-65535x65535.jpg", resized(65535, 65535))
write("jpg-65500x65500.jpg", resized(65500, 65500))
