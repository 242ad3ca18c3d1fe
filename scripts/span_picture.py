#!/usr/bin/env python3
"""Shows a span picture as two monitors side by side: a dark bezel put
between its halves (each monitor shows every pixel of its half).
Usage: span_picture.py IN.png OUT.png   (8-bit RGB, as `mountains render` writes)"""
import struct
import sys
import zlib

BEZEL = 10
BEZEL_COLOUR = bytes((24, 24, 28))


def chunks(data):
    at = 8
    while at < len(data):
        (length,) = struct.unpack(">I", data[at:at + 4])
        yield data[at + 4:at + 8], data[at + 8:at + 8 + length]
        at += 12 + length


def unfilter(raw, width, height, bpp=3):
    stride, rows, prev, at = width * bpp, [], bytearray(width * bpp), 0
    for _ in range(height):
        kind, line = raw[at], bytearray(raw[at + 1:at + 1 + stride])
        at += 1 + stride
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b, c = prev[i], prev[i - bpp] if i >= bpp else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line))
        prev = line
    return rows


def main(src, dst):
    data = open(src, "rb").read()
    parts = list(chunks(data))
    width, height, depth, colour = struct.unpack(">IIBB", parts[0][1][:10])
    assert (depth, colour) == (8, 2), "8-bit RGB only"
    raw = zlib.decompress(b"".join(body for kind, body in parts if kind == b"IDAT"))
    half = width // 2 * 3
    rows = [r[:half] + BEZEL_COLOUR * BEZEL + r[half:] for r in unfilter(raw, width, height)]
    body = zlib.compress(b"".join(b"\0" + r for r in rows), 9)

    def chunk(kind, payload):
        crc = zlib.crc32(kind + payload)
        return struct.pack(">I", len(payload)) + kind + payload + struct.pack(">I", crc)

    header = struct.pack(">IIBBBBB", width + BEZEL, height, 8, 2, 0, 0, 0)
    out = data[:8] + chunk(b"IHDR", header) + chunk(b"IDAT", body) + chunk(b"IEND", b"")
    open(dst + ".tmp", "wb").write(out)
    import os
    os.replace(dst + ".tmp", dst)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
