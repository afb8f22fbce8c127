#!/usr/bin/env python3
"""Lossless PNG tools for the manual's figures (standard library only).

  png_panels.py recompress IN.png OUT.png
      the same picture, with per-row PNG filters and maximum zlib compression (the renderer
      writes uncompressed PNGs);
  png_panels.py panels OUT.png X0 X1 IN1.png IN2.png ...
      columns X0 to X1 of each input (all of the same height), side by side.
"""
import struct
import sys
import zlib

SIGNATURE = b'\x89PNG\r\n\x1a\n'


def paeth(a, b, c):
    p = a + b - c
    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
    return a if pa <= pb and pa <= pc else b if pb <= pc else c


def predictor(kind, a, b, c):
    return (0, a, b, (a + b) // 2, paeth(a, b, c))[kind]


def read_png(path):
    """Width, height and the RGB rows (bytearrays) of an 8-bit RGB, non-interlaced PNG."""
    data = open(path, 'rb').read()
    if data[:8] != SIGNATURE:
        raise ValueError(path + ': not a PNG file')
    position, chunks = 8, []
    while position < len(data):
        length, = struct.unpack('>I', data[position:position + 4])
        chunks.append((data[position + 4:position + 8], data[position + 8:position + 8 + length]))
        position += 12 + length
    header = dict(chunks)[b'IHDR']
    width, height, depth, colour, _, _, interlace = struct.unpack('>IIBBBBB', header)
    if (depth, colour, interlace) != (8, 2, 0):
        raise ValueError(path + ': only 8-bit RGB non-interlaced PNG files are supported')
    raw = zlib.decompress(b''.join(body for kind, body in chunks if kind == b'IDAT'))
    stride, rows, previous, i = 3 * width, [], bytearray(3 * width), 0
    for _ in range(height):
        kind, row = raw[i], bytearray(raw[i + 1:i + 1 + stride])
        i += 1 + stride
        for x in range(stride):
            a = row[x - 3] if x >= 3 else 0
            c = previous[x - 3] if x >= 3 else 0
            row[x] = (row[x] + predictor(kind, a, previous[x], c)) & 255
        rows.append(row)
        previous = row
    return width, height, rows


def write_png(path, width, height, rows):
    """Each row with the filter that minimises the sum of absolute differences."""
    stride, out, previous = 3 * width, bytearray(), bytearray(3 * width)
    for row in rows:
        best = None
        for kind in range(5):
            filtered = bytearray(stride)
            for x in range(stride):
                a = row[x - 3] if x >= 3 else 0
                c = previous[x - 3] if x >= 3 else 0
                filtered[x] = (row[x] - predictor(kind, a, previous[x], c)) & 255
            cost = sum(v if v < 128 else 256 - v for v in filtered)
            if best is None or cost < best[0]:
                best = (cost, kind, filtered)
        out.append(best[1])
        out += best[2]
        previous = row

    def chunk(kind, body):
        return struct.pack('>I', len(body)) + kind + body + struct.pack('>I', zlib.crc32(kind + body))

    header = struct.pack('>IIBBBBB', width, height, 8, 2, 0, 0, 0)
    with open(path, 'wb') as f:
        f.write(SIGNATURE + chunk(b'IHDR', header) + chunk(b'IDAT', zlib.compress(bytes(out), 9))
                + chunk(b'IEND', b''))


def main(arguments):
    if len(arguments) == 3 and arguments[0] == 'recompress':
        write_png(arguments[2], *read_png(arguments[1]))
    elif len(arguments) >= 5 and arguments[0] == 'panels':
        out, x0, x1 = arguments[1], int(arguments[2]), int(arguments[3])
        panels = [read_png(path) for path in arguments[4:]]
        height = panels[0][1]
        if any(h != height or not 0 <= x0 < x1 <= w for w, h, _ in panels):
            raise ValueError('the inputs must have the same height and at least X1 columns')
        rows = [bytearray() for _ in range(height)]
        for _, _, panel_rows in panels:
            for y in range(height):
                rows[y] += panel_rows[y][3 * x0:3 * x1]
        write_png(out, (x1 - x0) * len(panels), height, rows)
    else:
        sys.exit(__doc__)


if __name__ == '__main__':
    main(sys.argv[1:])
