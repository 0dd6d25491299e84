#!/usr/bin/python3
"""Converts an X window dump (XWD, as Xvfb -fbdir keeps its screen) to PNG: a screenshot of a
headless X server. Usage: xwd_to_png.py SCREEN.xwd OUT.png (24/32-bit TrueColor dumps only)."""
import struct
import sys
import zlib


def read_xwd(path):
    data = open(path, "rb").read()
    header = struct.unpack(">25I", data[:100])
    header_size, _, _, depth, width, height = header[:6]
    byte_order, bits_per_pixel, bytes_per_line = header[7], header[11], header[12]
    colour_count = header[19]
    if bits_per_pixel != 32 or depth not in (24, 32):
        sys.exit(f"{path}: {bits_per_pixel}-bit pixels at depth {depth}; only 32-bit TrueColor is read")
    pixels = header_size + 12 * colour_count
    rows = []
    for y in range(height):
        line = data[pixels + y * bytes_per_line: pixels + y * bytes_per_line + 4 * width]
        rgb = bytearray(3 * width)
        # 32-bit TrueColor pixels are 0x00RRGGBB in the server's byte order.
        blue, green, red = (0, 1, 2) if byte_order == 0 else (3, 2, 1)
        rgb[0::3], rgb[1::3], rgb[2::3] = line[red::4], line[green::4], line[blue::4]
        rows.append(bytes(rgb))
    return width, height, rows


def write_png(path, width, height, rows):
    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))
    raw = b"".join(b"\x00" + row for row in rows)
    with open(path, "wb") as out:
        out.write(b"\x89PNG\r\n\x1a\n")
        out.write(chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)))
        out.write(chunk(b"IDAT", zlib.compress(raw, 6)))
        out.write(chunk(b"IEND", b""))


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    write_png(sys.argv[2], *read_xwd(sys.argv[1]))
