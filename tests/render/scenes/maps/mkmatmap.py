# Writes the two material_map test images of parity scene 110:
# matmap_palette.png (8-bit palette, 8x6: index (x/2 + y/2) % 5 in 2x2
# blocks; the palette's colours run against the indices, so reading the
# colours instead of the indices picks other textures) and matmap_grey.png
# (8-bit grey, 6x4: the levels 0 1 2 4 7 8 9 along the diagonals, past
# the texture count so POV-Ray 3.7.0's modulo and clamp show; levels such
# as 3, 5, 6 are left out because POV-Ray's gamma round trip reads them
# one lower, src/image/indices.h).
import struct, zlib, sys
def chunk(t, d):
    return struct.pack('>I', len(d)) + t + d + struct.pack('>I', zlib.crc32(t + d) & 0xffffffff)
def png(path, w, h, ctype, rows, plte=None):
    raw = b''.join(b'\0' + bytes(r) for r in rows)
    out = b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', w, h, 8, ctype, 0, 0, 0))
    if plte: out += chunk(b'PLTE', plte)
    out += chunk(b'IDAT', zlib.compress(raw, 9)) + chunk(b'IEND', b'')
    open(path, 'wb').write(out)
rows = [[(x // 2 + y // 2) % 5 for x in range(8)] for y in range(6)]
plte = b''.join(bytes([255 - 50 * i, 40 * i, 128]) for i in range(5))
png(sys.argv[1] + '/matmap_palette.png', 8, 6, 3, rows, plte)
levels = [0, 1, 2, 4, 7, 8, 9]
rows = [[levels[(x + y) % 7] for x in range(6)] for y in range(4)]
png(sys.argv[1] + '/matmap_grey.png', 6, 4, 0, rows)
