# Writes the density files of parity scene 113: ring16.df3 (16-bit,
# 6 x 5 x 3 voxels: sizes that are not powers of two, so POV-Ray's
# unsigned index wrap in tricubic interpolation shows) and blob8.df3
# (8-bit, 8 x 8 x 8, a soft ball off the centre).
import math, struct, sys
def df3(path, nx, ny, nz, bytes_, f):
    out = struct.pack('>HHH', nx, ny, nz)
    mx = (1 << (8 * bytes_)) - 1
    fmt = {1: '>B', 2: '>H'}[bytes_]
    for z in range(nz):
        for y in range(ny):
            for x in range(nx):
                out += struct.pack(fmt, int(round(max(0.0, min(1.0, f(x, y, z))) * mx)))
    open(path, 'wb').write(out)
df3(sys.argv[1] + '/ring16.df3', 6, 5, 3, 2,
    lambda x, y, z: 0.5 + 0.5 * math.sin(1.3 * x + 2.1 * y) * math.cos(0.9 * z + 0.4 * x))
df3(sys.argv[1] + '/blob8.df3', 8, 8, 8, 1,
    lambda x, y, z: math.exp(-((x - 4.5) ** 2 + (y - 3.5) ** 2 + (z - 4) ** 2) / 6.0))
