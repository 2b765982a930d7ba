# Writes the GIF height_field images of parity scene 102 (python3
# mkgif.py DIR), with a real LZW encoder (dictionary codes, growing code
# size, a clear code when the table is full):
# hf_index.gif: 40x30, 256-colour palette whose colours run
#   against the indices (POV-Ray takes the index * 256 as the height, so
#   a reader that used the colours would draw the terrain upside down);
# hf_16.pot: Fractint's 16-bit "potential" file, a GIF 80x30 whose left
#   half holds each height's high byte and right half its low byte; the
#   low byte carries a fine ripple of 1/256 of a step.
import math, struct, sys

def lzw(pixels, min_size):
    clear, end = 1 << min_size, (1 << min_size) + 1
    table = {bytes([i]): i for i in range(clear)}
    size, nxt = min_size + 1, end + 1
    out, acc, nbits = bytearray(), 0, 0
    def emit(code):
        nonlocal acc, nbits
        acc |= code << nbits
        nbits += size
        while nbits >= 8:
            out.append(acc & 255)
            acc >>= 8
            nbits -= 8
    emit(clear)
    w = b''
    for p in pixels:
        wc = w + bytes([p])
        if wc in table:
            w = wc
            continue
        emit(table[w])
        if nxt < 4096:
            table[wc] = nxt
            nxt += 1
            if nxt > (1 << size) and size < 12:
                size += 1
        else:
            emit(clear)
            table = {bytes([i]): i for i in range(clear)}
            size, nxt = min_size + 1, end + 1
        w = bytes([p])
    if w:
        emit(table[w])
    emit(end)
    if nbits:
        out.append(acc & 255)
    return bytes(out)

def gif(path, w, h, rows, palette, interlace=False):
    order = list(range(h))
    if interlace:
        order = [y for s, st in ((0, 8), (4, 8), (2, 4), (1, 2)) for y in range(s, h, st)]
    pixels = [v for y in order for v in rows[y]]
    data = lzw(pixels, 8)
    out = bytearray(b'GIF87a' + struct.pack('<HHBBB', w, h, 0xF7, 0, 0))
    out += palette
    out += b',' + struct.pack('<HHHHB', 0, 0, w, h, 0x40 if interlace else 0)
    out += bytes([8])
    for i in range(0, len(data), 255):
        out += bytes([len(data[i:i + 255])]) + data[i:i + 255]
    out += b'\0;'
    open(path, 'wb').write(out)

W, H = 40, 30
def hill(x, y):
    d = math.hypot((x - W * 0.4) / W, (y - H * 0.6) / H)
    return max(0.0, math.cos(min(d * 2.4, math.pi / 2)))

pal = b''.join(bytes([255 - i, 255 - i, (i * 7) & 255]) for i in range(256))
rows = [[int(round(hill(x, y) * 180 + 40 * (math.sin(x * 0.7) * 0.5 + 0.5)))
         for x in range(W)] for y in range(H)]
gif(sys.argv[1] + '/hf_index.gif', W, H, rows, pal)

rows = []
for y in range(H):
    hi, lo = [], []
    for x in range(W):
        v = int(round(hill(W - 1 - x, y) * 50000 + 3000 * math.sin(y * 0.9)
                      + 8000))
        hi.append(v >> 8)
        lo.append(v & 255)
    rows.append(hi + lo)
grey = b''.join(bytes([i, i, i]) for i in range(256))
gif(sys.argv[1] + '/hf_16.pot', 2 * W, H, rows, grey)
