# SPDX-License-Identifier: MIT
# tests/optics/optics.awk: the predictions of tests/optics/optics.sh,
# written from textbook optics and the reference data in data/, not from
# iris's code. Loaded with awk -f optics.awk -f - (the caller's program).

# n of N-BK7 at lambda nm: Sellmeier, n^2 = 1 + sum B_i l^2/(l^2 - C_i),
# l in um; coefficients from data/glass_sellmeier.csv (SCHOTT catalogue).
function n_bk7(lnm,   u) {
    u = (lnm / 1000) ^ 2
    return sqrt(1 + 1.03961212 * u / (u - 0.00600069867) + \
        0.231792344 * u / (u - 0.0200179144) + \
        1.01046945 * u / (u - 103.560653))
}

# n of distilled water at 20 C (Daimon & Masumura 2007, 4-term
# Sellmeier, data/glass_sellmeier.csv row water_20C).
function n_water(lnm,   u) {
    u = (lnm / 1000) ^ 2
    return sqrt(1 + 0.5684027565 * u / (u - 0.005101829712) + \
        0.1726177391 * u / (u - 0.01821153936) + \
        0.02086189578 * u / (u - 0.02620722293) + \
        0.1130748688 * u / (u - 10.69792721))
}

# Unpolarised Fresnel reflectance at incidence angle ti (radians) from
# index n1 into n2: the mean of the s and p reflectances; 1 beyond the
# critical angle.
function fresnel(ti, n1, n2,   st, ct, ci, rs, rp) {
    st = n1 / n2 * sin(ti)
    if (st >= 1) return 1
    ci = cos(ti); ct = sqrt(1 - st * st)
    rs = (n1 * ci - n2 * ct) / (n1 * ci + n2 * ct)
    rp = (n1 * ct - n2 * ci) / (n1 * ct + n2 * ci)
    return (rs * rs + rp * rp) / 2
}

# 2D ray state in the plane of a lens axis (x across, y along the axis):
# point (PX, PY), unit direction (DX, DY).
# refract2(eta, mx, my): Snell's law in vector form at the unit normal
# (mx, my) facing against the ray, eta = n_from / n_to.
function refract2(eta, mx, my,   c, k) {
    c = -(DX * mx + DY * my)
    k = 1 - eta * eta * (1 - c * c)
    DX = eta * DX + (eta * c - sqrt(k)) * mx
    DY = eta * DY + (eta * c - sqrt(k)) * my
}

# Moves the ray to its near (far = 0) or far (far = 1) crossing of the
# circle of centre (0, cy) and radius r.
function to_circle(cy, r, far,   ox, oy, b, c, t) {
    ox = PX; oy = PY - cy
    b = ox * DX + oy * DY; c = ox * ox + oy * oy - r * r
    t = far ? -b + sqrt(b * b - c) : -b - sqrt(b * b - c)
    PX += t * DX; PY += t * DY
}

# A ray parallel to the axis at height a (coming down from y = 10)
# through the biconvex lens of tests/optics/scenes/lens_spectrum.pov:
# top surface radius r on centre (0, c1) (c1 + r = top vertex), bottom
# surface radius r on centre (0, c2) (c2 - r = bottom vertex), index n.
# Leaves the ray below the lens; returns where it crosses the axis.
function lens_trace(a, n, c1, c2, r) {
    PX = a; PY = 10; DX = 0; DY = -1
    to_circle(c1, r, 0); refract2(1 / n, PX / r, (PY - c1) / r)
    to_circle(c2, r, 1); refract2(n, -PX / r, -(PY - c2) / r)
    return PY - PX * DY / DX
}

# Back focal distance of a thick lens (paraxial): radii r1, r2 (signed,
# light from +y: r1 > 0 convex), thickness t, index n in air.
#   1/f = (n - 1) (1/r1 - 1/r2 + (n - 1) t / (n r1 r2)),
#   BFD = f (1 - (n - 1) t / (n r1)).
function thick_bfd(n, r1, r2, t,   p, f) {
    p = (n - 1) * (1 / r1 - 1 / r2 + (n - 1) * t / (n * r1 * r2))
    f = 1 / p
    return f * (1 - (n - 1) * t / (n * r1))
}

# The centroid wavelength of the emission line of CIE F11 near c nm, the
# SPD interpolated linearly between the 5 nm rows of F (an array indexed
# by wavelength) over c - 5 .. c + 5 nm.
function line_centroid(F, c,   l, i, f, v, sw, sl) {
    sw = 0; sl = 0
    for (l = c - 5; l <= c + 5 + 1e-9; l += 0.1) {
        i = int(l / 5) * 5; f = (l - i) / 5
        v = F[i] * (1 - f) + F[i + 5] * f
        sw += v; sl += v * l
    }
    return sl / sw
}

# The centre of the peak of column col (2 = R, 3 = G, 4 = B) of a profile
# PROF[row, col] of nrows rows: the mean row, weighted by value, over the
# contiguous rows around the maximum that hold at least half of it (a
# symmetric spot gives its centre to a fraction of a row whatever its
# blur).
function peak_row(col, nrows,   r, m, best, lo, hi, sw, sr) {
    best = 0; m = -1
    for (r = 0; r < nrows; r++)
        if (PROF[r, col] > m) { m = PROF[r, col]; best = r }
    lo = best; hi = best
    while (lo > 0 && PROF[lo - 1, col] >= m / 2) lo--
    while (hi < nrows - 1 && PROF[hi + 1, col] >= m / 2) hi++
    sw = 0; sr = 0
    for (r = lo; r <= hi; r++) { sw += PROF[r, col]; sr += r * PROF[r, col] }
    return sr / sw
}

# Linear sRGB -> CIE 1931 xy (the D65 matrix of data/srgb.md); sets CX,
# CY and returns the luminance Y.
function rgb_xy(r, g, b,   X, Y, Z) {
    X = 0.4123907992659592 * r + 0.3575843393838780 * g + 0.1804807884018343 * b
    Y = 0.2126390058715102 * r + 0.7151686787677560 * g + 0.0721923153607337 * b
    Z = 0.0193308187155918 * r + 0.1191947797946260 * g + 0.9505321522496607 * b
    CX = X / (X + Y + Z); CY = Y / (X + Y + Z)
    return Y
}

# Planck's law at lambda nm and kelvin T (arbitrary scale), c2 = hc/k.
function planck(lnm, T) {
    return lnm ^ -5 / (exp(1.438776877e7 / (lnm * T)) - 1)
}

# xy of a blackbody at T over 380..780 nm (iris's spectral domain), 1 nm
# sums with the CIE 1931 functions XB, YB, ZB (arrays by wavelength, read
# from data/cie1931_2deg_cmf.csv); sets CX, CY.
function planck_xy(T,   l, p, X, Y, Z) {
    X = Y = Z = 0
    for (l = 380; l <= 780; l++) {
        p = planck(l, T)
        X += p * XB[l]; Y += p * YB[l]; Z += p * ZB[l]
    }
    CX = X / (X + Y + Z); CY = Y / (X + Y + Z)
}

# xy of a tabulated spectral power distribution S (an array by
# wavelength, rows every `step` nm: 1 for illuminant A, 5 for the F
# lamps; linear between rows, as the CIE tables are read) over 380..780
# nm, 1 nm sums with XB, YB, ZB as in planck_xy; sets CX, CY.
function spd_xy(S, step,   l, i, f, p, X, Y, Z) {
    X = Y = Z = 0
    for (l = 380; l <= 780; l++) {
        i = int(l / step) * step; f = (l - i) / step
        p = f > 0 ? S[i] * (1 - f) + S[i + step] * f : S[i]
        X += p * XB[l]; Y += p * YB[l]; Z += p * ZB[l]
    }
    CX = X / (X + Y + Z); CY = Y / (X + Y + Z)
}

# A ray travelling -z at x = b (0 < b < 1) through a circle of radius 1
# at the origin (the water cylinder's cross-section, in the xz plane:
# PX = x, PY = z), index n: refracted in, reflected once inside,
# refracted out; returns the x where it meets the plane z = zs (on the
# light's side).
function bow_x(b, n, zs,   c, mx, my) {
    PX = b; PY = 10; DX = 0; DY = -1
    to_circle(0, 1, 0); refract2(1 / n, PX, PY)
    to_circle(0, 1, 1)
    c = DX * PX + DY * PY             # reflect on the inner wall
    DX -= 2 * c * PX; DY -= 2 * c * PY
    to_circle(0, 1, 1); refract2(n, -PX, -PY)
    return PX + (zs - PY) * DX / DY
}

# The fold of bow_x over b, the rainbow's edge on the screen: the ray of
# minimum deviation lands farthest out (least x: the bow is on the -x
# side); found on a 1e-4 grid of b refined by a parabola. BOW_B holds
# its impact parameter, BOW_DEV its deviation in degrees.
function bow_edge(n, zs,   b, x, best, bb, x0, x1, x2, h) {
    best = 1e9
    for (b = 0.5; b < 0.999; b += 1e-4) {
        x = bow_x(b, n, zs)
        if (x < best) { best = x; bb = b }
    }
    h = 1e-4
    x0 = bow_x(bb - h, n, zs); x1 = bow_x(bb, n, zs); x2 = bow_x(bb + h, n, zs)
    BOW_B = bb + (x0 - x2) / (2 * (x0 - 2 * x1 + x2)) * h
    x = bow_x(BOW_B, n, zs)
    BOW_DEV = 180 - atan2(-DX, DY) * 45 / atan2(1, 1)
    return x
}

# The row of the largest 3-row mean of column col of PROF within
# lo..hi: the position of a peak in a noisy profile, to a row.
function smooth_peak(col, lo, hi,   r, v, m, best) {
    m = -1; best = lo
    for (r = lo; r <= hi; r++) {
        v = PROF[r - 1, col] + PROF[r, col] + PROF[r + 1, col]
        if (v > m) { m = v; best = r }
    }
    return best
}

# n of SCHOTT F2 (flint), Sellmeier coefficients from
# data/glass_sellmeier.csv.
function n_f2(lnm,   u) {
    u = (lnm / 1000) ^ 2
    return sqrt(1 + 1.34533359 * u / (u - 0.00997743871) + \
        0.209073176 * u / (u - 0.0470450767) + \
        0.937357162 * u / (u - 111.886764))
}

# Moves the 2D ray to the line through (qx, qy) with normal (nx, ny).
function to_line(qx, qy, nx, ny,   t) {
    t = ((qx - PX) * nx + (qy - PY) * ny) / (DX * nx + DY * ny)
    PX += t * DX; PY += t * DY
}

# A ray from (x0, y0) along (dx, dy) through the equilateral prism of
# tests/optics/scenes/prism_spectrum.pov (base corners (-1, 0.2) and
# (1, 0.2), apex (0, 1.932)) of index n, to the screen x = xs; returns
# the y where it lands.
function prism_y(n, x0, y0, dx, dy, xs,   s3) {
    s3 = sqrt(3) / 2
    PX = x0; PY = y0; DX = dx / sqrt(dx * dx + dy * dy)
    DY = dy / sqrt(dx * dx + dy * dy)
    to_line(-1, 0.2, -s3, 0.5); refract2(1 / n, -s3, 0.5)
    to_line(1, 0.2, s3, 0.5); refract2(n, -s3, -0.5)
    to_line(xs, 0, 1, 0)
    return PY
}

# Camera rays of tests/optics/scenes/fringe.pov: parallel, along
# (3.654, 1.628), starting at (-4.154, -0.562) + s (-0.4069, 0.9135)
# (s the image offset along the camera's up). Returns the s at which the
# ray of index n lands on the wall x = 4 at height yl (the landing height
# is linear in s: flat faces keep a parallel beam parallel).
function fringe_s(n, yl,   ux, uy, a, b) {
    ux = -1.628 / sqrt(3.654 ^ 2 + 1.628 ^ 2)
    uy = 3.654 / sqrt(3.654 ^ 2 + 1.628 ^ 2)
    a = prism_y(n, -4.154, -0.562, 3.654, 1.628, 4)
    b = prism_y(n, -4.154 + 0.01 * ux, -0.562 + 0.01 * uy, 3.654, 1.628, 4)
    return (yl - a) / ((b - a) / 0.01)
}

# The dispersion laws of an interior besides Sellmeier, as POV-Ray and
# DESIGN.md define them (lambda in nm):
# POV-Ray's 'ior n dispersion D': n(lambda) = n D^((555 - lambda)/350).
function n_povdisp(n, D, lnm) { return n * D ^ ((555 - lnm) / 350) }
# 'cauchy A, B': n = A + B / lambda^2, lambda in um.
function n_cauchy(A, B, lnm) { return A + B / (lnm / 1000) ^ 2 }
# 'abbe n_d, V_d': the Cauchy curve with n(d) = n_d and
# (n_d - 1)/(n_F - n_C) = V_d, at the d, F and C Fraunhofer lines
# (587.5618, 486.1327, 656.2725 nm; ISO 7944).
function n_abbe(nd, vd, lnm,   lf, lc, ld, B) {
    lf = 0.4861327; lc = 0.6562725; ld = 0.5875618
    B = (nd - 1) / (vd * (1 / lf ^ 2 - 1 / lc ^ 2))
    return nd - B / ld ^ 2 + B / (lnm / 1000) ^ 2
}
# 'ior_decay n1, n2, spread': n = (n1 - n2) e^(-(lambda - 380)/spread) + n2.
function n_decay(n1, n2, s, lnm) { return (n1 - n2) * exp(-(lnm - 380) / s) + n2 }

# A ray travelling -y at x = b (0 <= b < 1) through the ball of radius 1
# at the origin (a plane through its centre; the ball is symmetric about
# the y axis), index n, refracted in and out (no internal reflection);
# returns the signed x where it meets the floor y = yf (rays that crossed
# the axis land at x < 0), or 1e9 if it leaves upwards. BALL_T is the
# unpolarised Fresnel transmittance of its two crossings, (1 - R(i))^2
# (the inner crossing meets the surface at the refraction angle, whose
# reflectance from inside equals R(i)).
function ball_x(b, n, yf) {
    PX = b; PY = 10; DX = 0; DY = -1
    to_circle(0, 1, 0)
    BALL_T = (1 - fresnel(atan2(b, sqrt(1 - b * b)), 1, n)) ^ 2
    refract2(1 / n, PX, PY); to_circle(0, 1, 1); refract2(n, -PX, -PY)
    return DY < 0 ? PX + (yf - PY) * DX / DY : 1e9
}

# The caustic ring on the floor y = yf in front of the paraxial focus:
# the fold where the uncrossed rays' landing x stops growing with b (the
# spherical aberration turns the outer zones back towards the axis).
function ball_fold(n, yf,   b, x, best) {
    best = 0
    for (b = 0.05; b < 0.95; b += 5e-5)
        if ((x = ball_x(b, n, yf)) > best && x < 1e9) best = x
    return best
}

# The mean irradiance over the floor's annulus r0 <= rho < r1 under the
# ball, the light's irradiance being 1: the fan of impact parameters b
# (1e5 zones of area 2 pi b db, each carrying BALL_T) binned by where it
# lands.
function ball_mean(n, yf, r0, r1,   k, nb, b, x, p) {
    nb = 100000; p = 0
    for (k = 0; k < nb; k++) {
        b = (k + 0.5) / nb; x = ball_x(b, n, yf)
        if (x < 0) x = -x
        if (x >= r0 && x < r1) p += BALL_T * 2 * b / nb
    }
    return p / (r1 * r1 - r0 * r0)
}

# A ray from (x0, y0) along (dx, dy) through the prism pair of
# tests/optics/scenes/prism_pair.pov: the prism of prism_spectrum.pov
# and the same prism turned 180 degrees about z, placed so that its
# first face is parallel to the first prism's exit face, g beyond it
# (the pair is a parallel plate split by an air gap); to the screen
# x = xs, returns the y where it lands.
# PAIR_T is the unpolarised Fresnel transmittance of its four faces.
function pair_y(n, x0, y0, dx, dy, g, xs,   s3, tx, ty) {
    s3 = sqrt(3) / 2; tx = 1 + s3 * g; ty = 2.132 + 0.5 * g
    PX = x0; PY = y0; DX = dx / sqrt(dx * dx + dy * dy)
    DY = dy / sqrt(dx * dx + dy * dy)
    PAIR_T = 1
    to_line(-1, 0.2, -s3, 0.5); face_t(1, n, -s3, 0.5)
    to_line(1, 0.2, s3, 0.5); face_t(n, 1, -s3, -0.5)
    to_line(1 + s3 * g, 0.2 + 0.5 * g, s3, 0.5); face_t(1, n, -s3, -0.5)
    to_line(1 + tx, -0.2 + ty, s3, -0.5); face_t(n, 1, -s3, 0.5)
    to_line(xs, 0, 1, 0)
    return PY
}

# Refracts the 2D ray from index n1 into n2 at the unit normal (mx, my)
# facing against it, multiplying PAIR_T by the face's 1 - R.
function face_t(n1, n2, mx, my,   c) {
    c = -(DX * mx + DY * my)
    PAIR_T *= 1 - fresnel(atan2(sqrt(1 - c * c), c), n1, n2)
    refract2(n1 / n2, mx, my)
}

# As bow_x, with two internal reflections (the secondary bow), which
# leaves towards +x; returns the x where the ray meets the plane z = zs,
# or 1e9 if it leaves away from it.
function bow2_x(b, n, zs,   c, k) {
    PX = b; PY = 10; DX = 0; DY = -1
    to_circle(0, 1, 0); refract2(1 / n, PX, PY)
    for (k = 0; k < 2; k++) {
        to_circle(0, 1, 1)
        c = DX * PX + DY * PY
        DX -= 2 * c * PX; DY -= 2 * c * PY
    }
    to_circle(0, 1, 1); refract2(n, -PX, -PY)
    return DY > 0 ? PX + (zs - PY) * DX / DY : 1e9
}

# The secondary bow's edge on the screen z = zs: the ray of minimum
# deviation lands nearest the axis (least x); a 1e-4 grid of b refined by
# a parabola, as bow_edge. BOW_DEV is its deviation in degrees, measured
# from the light's direction the other way round (360 - D2).
function bow2_edge(n, zs,   b, x, best, bb, x0, x1, x2, h) {
    best = 1e9
    for (b = 0.85; b < 0.999; b += 1e-4) {
        x = bow2_x(b, n, zs)
        if (x < best) { best = x; bb = b }
    }
    h = 1e-4
    x0 = bow2_x(bb - h, n, zs); x1 = bow2_x(bb, n, zs)
    x2 = bow2_x(bb + h, n, zs)
    bb += (x0 - x2) / (2 * (x0 - 2 * x1 + x2)) * h
    x = bow2_x(bb, n, zs)
    BOW_DEV = 180 - atan2(DX, DY) * 45 / atan2(1, 1)
    return x
}

# The transmittance of a stack of flat parallel layers, the light
# falling at angle a (radians) in the first medium: indices NN[0] (where
# the light comes from), NN[1], ..., NN[k] (where it leaves), k
# interfaces. Each interface transmits 1 - R (unpolarised Fresnel at the
# angle Snell's law gives in its medium, n sin = const); the light
# reflected back and forth between them adds incoherently: two lossless
# elements of transmittance T1 and T2 (reflectance 1 - T, the same from
# either side) pass T1 T2 / (1 - R1 R2) together.
function stack_t(a, k,   i, s, T, T2, st) {
    s = NN[0] * sin(a); T = 1
    for (i = 0; i < k; i++) {
        st = s / NN[i]
        T2 = 1 - fresnel(atan2(st, sqrt(1 - st * st)), NN[i], NN[i + 1])
        T = T * T2 / (1 - (1 - T) * (1 - T2))
    }
    return T
}

# n of the glass 'name' at lambda nm from the Sellmeier coefficients of
# data/glass_sellmeier.csv (read into GB[name, 1..4], GC[name, 1..4] by
# the caller; C in um^2): n^2 = 1 + sum B_i l^2/(l^2 - C_i), l in um.
function n_sellmeier(name, lnm,   u, k, s) {
    u = (lnm / 1000) ^ 2; s = 1
    for (k = 1; k <= 4; k++)
        if (GB[name, k] != 0) s += GB[name, k] * u / (u - GC[name, k])
    return sqrt(s)
}

# POV-Ray's reflectivity of 'reflection { min, max falloff fo }' at
# incidence angle a: F = (1 - cos a)^fo, F max + (1 - F) min.
function refl_falloff(mn, mx, fo, a,   F) {
    F = (1 - cos(a)) ^ fo
    return F * mx + (1 - F) * mn
}

# POV-Ray's 'reflection { ... metallic M }' factor on a channel of
# pigment p at incidence a (semantics §3.3): 1 + M (1 - Fm) (p - 1), Fm
# its empirical Fresnel curve of x = a / 90 degrees.
function metallic_factor(M, p, a,   x, Fm) {
    x = a / (2 * atan2(1, 1))
    Fm = 0.014567225 / (x - 1.12) ^ 2 - 0.011612903
    if (Fm < 0) Fm = 0
    if (Fm > 1) Fm = 1
    return 1 + M * (1 - Fm) * (p - 1)
}

# A ray (PX, PY, DX, DY) carrying power wt meets the floor y = yf if it
# goes down: binned by |x| (the ray lies in a meridian plane of an
# axisymmetric scene, so |x| is its distance from the axis) into BIN[]
# (bins w wide, nb of them).
function ball_land(wt, yf, w, nb,   x, j) {
    if (DY >= 0) return
    x = PX + (yf - PY) * DX / DY; if (x < 0) x = -x
    j = int(x / w); if (j < nb) BIN[j] += wt
}

# Every ray of a parallel beam coming down the y axis onto a sphere of
# radius 1 (centre 0) and relative index n, followed through each branch
# with its unpolarised Fresnel weight: the outer reflection (total for
# n < 1 beyond the critical impact parameter b = n), the refraction in,
# and at each of up to K internal reflections the part that leaves
# (inside a sphere every crossing meets the surface at the same angle,
# so the internal reflectance is the same at each). Each branch that
# leaves downwards lands on the floor y = yf; BIN[j] ends as the mean
# irradiance over the annulus j w <= rho < (j + 1) w, the beam's being
# 1. nz zones of b, each of area 2 pi b db.
function ball_bins(n, yf, w, nb, K, nz,   z, b, db, wt, R0, Ri, ci, k, px, py, dx, dy, j) {
    for (j = 0; j < nb; j++) BIN[j] = 0
    db = 1 / nz
    for (z = 0; z < nz; z++) {
        b = (z + 0.5) * db; wt = 2 * b * db
        PX = b; PY = 10; DX = 0; DY = -1; to_circle(0, 1, 0)
        R0 = fresnel(atan2(b, sqrt(1 - b * b)), 1, n)
        px = PX; py = PY
        # the mirror image of (0, -1) in the normal (px, py)
        DX = 2 * py * px; DY = -1 + 2 * py * py
        ball_land(wt * R0, yf, w, nb)
        if (R0 >= 1) continue
        PX = px; PY = py; DX = 0; DY = -1
        refract2(1 / n, PX, PY)
        wt *= 1 - R0
        for (k = 0; k <= K; k++) {
            to_circle(0, 1, 1)
            ci = DX * PX + DY * PY   # cosine to the outward normal
            Ri = fresnel(atan2(sqrt(1 - ci * ci), ci), n, 1)
            px = PX; py = PY; dx = DX; dy = DY
            refract2(n, -PX, -PY); ball_land(wt * (1 - Ri), yf, w, nb)
            PX = px; PY = py; DX = dx - 2 * ci * px; DY = dy - 2 * ci * py
            wt *= Ri
        }
    }
    for (j = 0; j < nb; j++) BIN[j] /= (2 * j + 1) * w * w
}

# The floor inside a mirror ring (tests/optics/scenes/cup.pov: inner
# radius 1, rim at height H, floor y = 0) under a parallel light at
# elevation alt degrees coming from -x (D = 0) or a point light at
# (-D, D tan alt, 0). The wall is sampled on a grid of nphi x nh points
# (phi in [-1.25, 1.25] rad from the far wall's x = 1, h in [0, H]), each
# carrying the light's |d.n| per area (over dist^2 for the point light)
# if the incoming ray clears the near rim (its height where it entered
# the cylinder r = 1, traced back, is at least H); the mirror image of
# the ray in the wall's normal goes to the floor. CUP[row] sums what
# lands in the strip |z| < 0.01, rows 0.01 wide from x = 1 (the image's
# rows); rays that would meet the wall again are dropped.
function cup_profile(alt, D, H, nphi, nh,   a, i, k, phi, h, cx, cz, lx, ly, dx, dy, dz, l, dn, t, rx, rz, fx, fz, w, row) {
    a = alt * atan2(1, 1) / 45
    for (row = 0; row < 200; row++) CUP[row] = 0
    lx = -D; ly = D * sin(a) / cos(a)
    for (i = 0; i < nphi; i++) {
        phi = (-1 + (2 * i + 1) / nphi) * 1.25
        cx = cos(phi); cz = sin(phi)
        for (k = 0; k < nh; k++) {
            h = (k + 0.5) * H / nh
            if (D == 0) { dx = cos(a); dy = -sin(a); dz = 0; w = 1 }
            else {
                dx = cx - lx; dy = h - ly; dz = cz
                l = sqrt(dx * dx + dy * dy + dz * dz)
                dx /= l; dy /= l; dz /= l; w = 1 / (l * l)
            }
            dn = -(dx * cx + dz * cz)   # d . the inward normal (-cx, 0, -cz)
            if (dn >= 0) continue
            # back along -d to the other crossing of the cylinder r = 1
            t = 2 * (cx * dx + cz * dz) / (dx * dx + dz * dz)
            if (h - t * dy < H) continue
            rx = dx + 2 * dn * cx; rz = dz + 2 * dn * cz
            t = h / -dy; fx = cx + rx * t; fz = cz + rz * t
            if (fx * fx + fz * fz > 1 || fz < -0.01 || fz > 0.01) continue
            CUP[int((1 - fx) / 0.01)] += -dn * w
        }
    }
}
