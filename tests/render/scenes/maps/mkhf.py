# Writes the two height_field test images of parity scene 47:
# hf_palette.png (8-bit palette; the palette's colours run against the
# indices, so grey levels and indices disagree) and hf_rg.png (8-bit RGB:
# red a smooth hill, green a fine ripple, blue the hill reversed).
import math, struct, zlib, sys
def chunk(t, d):
    return struct.pack('>I', len(d)) + t + d + struct.pack('>I', zlib.crc32(t + d) & 0xffffffff)
def png(path, w, h, ctype, rows, plte=None):
    raw = b''.join(b'\0' + bytes(r) for r in rows)
    out = b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', w, h, 8, ctype, 0, 0, 0))
    if plte: out += chunk(b'PLTE', plte)
    out += chunk(b'IDAT', zlib.compress(raw, 9)) + chunk(b'IEND', b'')
    open(path, 'wb').write(out)
W, H = 40, 30
def hill(x, y):
    d = math.hypot((x - W * 0.45) / W, (y - H * 0.5) / H)
    return max(0.0, math.cos(min(d * 2.6, math.pi / 2)))
rows = []
for y in range(H):
    rows.append([int(round(hill(x, y) * 200 + 30 * (math.sin(x * 0.9) * 0.5 + 0.5))) for x in range(W)])
plte = b''.join(bytes([255 - i, 255 - i, (i * 7) & 255]) for i in range(256))
png(sys.argv[1] + '/hf_palette.png', W, H, 3, rows, plte)
rows = []
for y in range(H):
    r = []
    for x in range(W):
        v = int(round(hill(x, y) * 230))
        r += [v, int(127 + 120 * math.sin(x * 1.7 + y * 1.3)), 255 - v]
    rows.append(r)
png(sys.argv[1] + '/hf_rg.png', W, H, 2, rows)
