#!/usr/bin/env python3
"""gallery_png.py - convert binary PPM (P6, maxval 255) images to PNG with the standard
library only (zlib, struct): the README's gallery (examples/gallery.c writes the PPMs).

usage: python3 examples/gallery_png.py OUTDIR IN.ppm [IN.ppm ...]
Writes OUTDIR/<name>.png for each input. Deterministic: per row the PNG filter with the
smallest sum of absolute residuals (the libpng heuristic), zlib level 9.
"""
import os
import struct
import sys
import zlib


def read_ppm(path):
    with open(path, "rb") as fh:
        data = fh.read()
    fields, pos = [], 0
    while len(fields) < 4:  # magic, width, height, maxval; '#' comments allowed
        while data[pos:pos + 1].isspace():
            pos += 1
        if data[pos:pos + 1] == b"#":
            while data[pos:pos + 1] not in (b"\n", b""):
                pos += 1
            continue
        start = pos
        while not data[pos:pos + 1].isspace():
            pos += 1
        fields.append(data[start:pos])
    pos += 1  # the single whitespace byte after maxval
    if fields[0] != b"P6" or int(fields[3]) != 255:
        raise ValueError("%s: not a P6 PPM with maxval 255" % path)
    w, h = int(fields[1]), int(fields[2])
    px = data[pos:pos + 3 * w * h]
    if len(px) != 3 * w * h:
        raise ValueError("%s: truncated" % path)
    return w, h, px


def paeth(a, b, c):
    p = a + b - c
    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
    if pa <= pb and pa <= pc:
        return a
    return b if pb <= pc else c


def filter_rows(w, h, px):
    stride, bpp = 3 * w, 3
    out = bytearray()
    prev = bytes(stride)
    for y in range(h):
        row = px[y * stride:(y + 1) * stride]
        cands = [bytes(row)]
        sub = bytearray(stride)
        up = bytearray(stride)
        avg = bytearray(stride)
        pae = bytearray(stride)
        for i in range(stride):
            a = row[i - bpp] if i >= bpp else 0
            b = prev[i]
            c = prev[i - bpp] if i >= bpp else 0
            x = row[i]
            sub[i] = (x - a) & 255
            up[i] = (x - b) & 255
            avg[i] = (x - ((a + b) >> 1)) & 255
            pae[i] = (x - paeth(a, b, c)) & 255
        cands += [bytes(sub), bytes(up), bytes(avg), bytes(pae)]
        costs = [sum(v if v < 128 else 256 - v for v in cnd) for cnd in cands]
        best = costs.index(min(costs))
        out.append(best)
        out += cands[best]
        prev = row
    return bytes(out)


def chunk(kind, body):
    return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF)


def write_png(path, w, h, px):
    raw = filter_rows(w, h, px)
    png = b"\x89PNG\r\n\x1a\n"
    png += chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
    png += chunk(b"sRGB", b"\x00")
    png += chunk(b"IDAT", zlib.compress(raw, 9))
    png += chunk(b"IEND", b"")
    with open(path, "wb") as fh:
        fh.write(png)
    return len(png)


def main(argv):
    if len(argv) < 3 or argv[1] in ("-h", "--help"):
        print(__doc__.strip())
        return 0 if len(argv) > 1 and argv[1] in ("-h", "--help") else 2
    outdir = argv[1]
    os.makedirs(outdir, exist_ok=True)
    for path in argv[2:]:
        w, h, px = read_ppm(path)
        name = os.path.splitext(os.path.basename(path))[0] + ".png"
        n = write_png(os.path.join(outdir, name), w, h, px)
        print("wrote %s (%dx%d, %d bytes)" % (os.path.join(outdir, name), w, h, n))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
