/* SPDX-License-Identifier: MIT */
/*
** wf_kernel.h: the wavefront tracer's lanes (wavefront.c), included once
** per lane width: WF_W = 8 (256-bit vectors, the AVX2 kernel) and 4
** (128-bit vectors: SSE2, which every x86-64 has, or another
** architecture's; the 8-lane code in 128-bit registers was scalarised in
** part and ran at the scalar tracer's speed). Each inclusion names its
** functions with the width (WF_NAME); wavefront.c compiles the 8-lane
** body inside a target("avx2,fma") function.
*/
#define vf WF_NAME(vf)
#define vi WF_NAME(vi)
#define vu WF_NAME(vu)
#define bits WF_NAME(bits)
#define bounce WF_NAME(bounce)
#define emit WF_NAME(emit)
#define fresnel_body WF_NAME(fresnel_body)
#define fresnel_lanes WF_NAME(fresnel_lanes)
#define hash WF_NAME(hash)
#define tab_lookup WF_NAME(tab_lookup)
#define lane_keys WF_NAME(lane_keys)
#define ld WF_NAME(ld)
#define ldi WF_NAME(ldi)
#define ldu WF_NAME(ldu)
#define pack WF_NAME(pack)
#define packi WF_NAME(packi)
#define permute WF_NAME(permute)
#define pick WF_NAME(pick)
#define picki WF_NAME(picki)
#define rnd WF_NAME(rnd)
#define sel WF_NAME(sel)
#define seli WF_NAME(seli)
#define smoothstep01 WF_NAME(smoothstep01)
#define splat WF_NAME(splat)
#define splati WF_NAME(splati)
#define st WF_NAME(st)
#define sti WF_NAME(sti)
#define trace_body WF_NAME(trace_body)
#define vmax WF_NAME(vmax)
#define vmin WF_NAME(vmin)
#define vsincos WF_NAME(vsincos)
#define vsqrt WF_NAME(vsqrt)

#if WF_W == 8
typedef float vf __attribute__((vector_size(32)));
typedef int32_t vi __attribute__((vector_size(32)));
typedef uint32_t vu __attribute__((vector_size(32)));
#define WF_IOTA { 0, 1, 2, 3, 4, 5, 6, 7 }
#define WF_PERM(ws) ((ws)->perm8)
#else
typedef float vf __attribute__((vector_size(16)));
typedef int32_t vi __attribute__((vector_size(16)));
typedef uint32_t vu __attribute__((vector_size(16)));
#define WF_IOTA { 0, 1, 2, 3 }
#define WF_PERM(ws) ((ws)->perm4)
#endif

/* ---- vector helpers ---------------------------------------------------- */

AI vf splat(float x)
{
    return (vf){ 0 } + x;
}

AI vi splati(int32_t x)
{
    return (vi){ 0 } + x;
}

AI vf sel(vi m, vf a, vf b)
{
    return (vf)(((vi)a & m) | ((vi)b & ~m));
}

AI vi seli(vi m, vi a, vi b)
{
    return (a & m) | (b & ~m);
}

AI vf vmax(vf a, vf b)
{
    return sel(a > b, a, b);
}

AI vf vmin(vf a, vf b)
{
    return sel(a < b, a, b);
}

/* (one sqrtps per half or one vsqrtps: -fno-math-errno) */
AI vf vsqrt(vf x)
{
    vf r;
    for (int i = 0; i < WF_W; i++)
        r[i] = sqrtf(x[i]);
    return r;
}

AI vf ld(const float *p)
{
    vf v;
    memcpy(&v, p, sizeof v);
    return v;
}

AI vi ldi(const int32_t *p)
{
    vi v;
    memcpy(&v, p, sizeof v);
    return v;
}

AI vu ldu(const uint32_t *p)
{
    vu v;
    memcpy(&v, p, sizeof v);
    return v;
}

AI void st(float *p, vf v)
{
    memcpy(p, &v, sizeof v);
}

AI void sti(int32_t *p, vi v)
{
    memcpy(p, &v, sizeof v);
}

/* Entry k of the 8-entry table 'tab' for each lane's k in 0..7 (one
** permutation: of one 8-lane vector, or of two 4-lane ones). */
AI vf pick(const float *tab, vi k)
{
#if defined(__clang__)
    vf r;
    for (int i = 0; i < WF_W; i++)
        r[i] = tab[k[i] & 7];
    return r;
#elif WF_W == 8
    return __builtin_shuffle(ld(tab), k);
#else
    return __builtin_shuffle(ld(tab), ld(tab + 4), k);
#endif
}

AI vi picki(const int32_t *tab, vi k)
{
#if defined(__clang__)
    vi r;
    for (int i = 0; i < WF_W; i++)
        r[i] = tab[k[i] & 7];
    return r;
#elif WF_W == 8
    return __builtin_shuffle(ldi(tab), k);
#else
    return __builtin_shuffle(ldi(tab), ldi(tab + 4), k);
#endif
}

/* The lanes of 'v' in the order 'perm' (compaction). */
AI vi permute(vi v, vi perm)
{
#if defined(__clang__)
    vi r;
    for (int i = 0; i < WF_W; i++)
        r[i] = v[perm[i] & (WF_W - 1)];
    return r;
#else
    return __builtin_shuffle(v, perm);
#endif
}

/* The lanes set in 'm' as bits. */
AI unsigned bits(vi m)
{
    unsigned b = 0;
    for (int i = 0; i < WF_W; i++)
        b |= (unsigned)(m[i] & 1) << i;
    return b;
}

/* The counter-based random numbers' hash, lane by lane (WF_LOWBIAS32,
** wavefront.c). */
AI vu hash(vu x)
{
    WF_LOWBIAS32(x);
    return x;
}

/* Uniform on [0, 1) in steps of 2^-24: draw 'k' of the lanes' keys. */
AI vf rnd(vu key, uint32_t k)
{
    vu x = hash(key + (k + 1) * 0x9e3779b9U);
    return __builtin_convertvector((vi)(x >> 8), vf) * (1.0f / 16777216.0f);
}

/* sin and cos of 'x' (|x| < 1e4): x = j·pi/2 + r with |r| <= pi/4 (pi/2
** in three parts, so r is exact to float), the minimax polynomials of
** sin and cos on [-pi/4, pi/4] (Cephes' sinf/cosf coefficients), and the
** quadrant j mod 4 swapping and negating them. Error ~1e-7. */
AI void vsincos(vf x, vf *s, vf *c)
{
    vf jf = x * (float)(2.0 / M_PI);
    jf = jf + sel(jf >= 0.0f, splat(0.5f), splat(-0.5f));
    vi j = __builtin_convertvector(jf, vi); /* truncation: rounded */
    vf y = __builtin_convertvector(j, vf);
    vf r = ((x - y * 1.5703125f) - y * 4.837512969970703125e-4f) -
            y * 7.54978995489188216e-8f;
    vf z = r * r;
    vf sp = r + r * z * (-1.6666654611e-1f +
                          z * (8.3321608736e-3f + z * -1.9515295891e-4f));
    vf cp = 1.0f - 0.5f * z +
             z * z * (4.166664568298827e-2f +
                      z * (-1.388731625493765e-3f +
                           z * 2.443315711809948e-5f));
    vi q = j & 3;
    vi swap = (q & 1) != 0;
    vf ss = sel(swap, cp, sp), cc = sel(swap, sp, cp);
    vi neg_s = (q & 2) != 0, neg_c = ((q + 1) & 2) != 0;
    *s = sel(neg_s, -ss, ss);
    *c = sel(neg_c, -cc, cc);
}

AI vf smoothstep01(vf t)
{
    t = vmin(vmax(t, splat(0.0f)), splat(1.0f));
    return t * t * (3.0f - 2.0f * t);
}

/* The exact unpolarised Fresnel reflectance of trace.c's fresnel(), in
** lanes: 1 (and cos_t 0) at and past the critical angle, and for a NaN. */
AI vf fresnel_lanes(vf cos_i, vf eta, vf *cos_t)
{
    cos_i = vmin(cos_i, splat(1.0f));
    cos_i = sel(cos_i >= 0.0f, cos_i, splat(0.0f)); /* also a NaN */
    /* cos^2 t = 1 - eta^2 (1 - cos^2 i), as (1 - eta^2) + eta^2 cos^2 i:
    ** exact at eta 1, where float's 1 - cos^2 i rounds to 1 at grazing
    ** and made an index-matched surface totally reflecting there */
    vf e2 = eta * eta;
    vf cos2_t = (1.0f - e2) + e2 * (cos_i * cos_i);
    vi tir = ~(cos2_t > 0.0f);
    vf ct = vsqrt(vmax(cos2_t, splat(0.0f)));
    vf a = eta * cos_i;
    vf b = eta * ct;
    vf rs = (a - ct) / (a + ct);
    vf rp = (cos_i - b) / (cos_i + b);
    vf f = 0.5f * (rs * rs + rp * rp);
    vi bad = tir | (f != f);
    *cos_t = sel(tir, splat(0.0f), ct);
    return sel(bad, splat(1.0f), f);
}

/* Packs the lanes set in 'm' of 'v' to the front of 'dst' (8 stores,
** of which the first popcount(m) count). */
AI void pack(float *dst, vf v, vi perm)
{
    st(dst, (vf)permute((vi)v, perm));
}

AI void packi(int32_t *dst, vi v, vi perm)
{
    sti(dst, permute(v, perm));
}

/* ---- the kernel ------------------------------------------------------- */

/* The key of each lane's random stream: its photon index under the
** (seed, pass) mix. */
AI vu lane_keys(const struct wf_run *run, int i, uint32_t mix)
{
    vu lo = ldu(run->idx_lo + i), hi = ldu(run->idx_hi + i);
    return hash(lo ^ hash(hi ^ mix));
}

/* Emits the run's photons into the lanes (shoot.c's shoot_one()); returns
** how many live. */
AI int emit(const struct wf_scene *ws, const struct wf_light *L,
            const struct wf_run *run, struct wf_state *S)
{
    const vi iota = WF_IOTA;
    uint32_t mix = hash1((uint32_t)L->seed ^
                         hash1((uint32_t)(L->seed >> 32) ^
                               hash1((uint32_t)L->pass + 0x632be5abU)));
    const float dth = (float)L->dtheta, jit = (float)L->jitter;
    const float ax = (float)L->axis.x, ay = (float)L->axis.y,
                az = (float)L->axis.z;
    const float aax = (float)L->a.x, aay = (float)L->a.y, aaz = (float)L->a.z;
    const float bx = (float)L->b.x, by = (float)L->b.y, bz = (float)L->b.z;
    int w = 0;
    for (int i = 0; i < run->n; i += WF_W) {
        vi alive = (iota + i) < run->n;
        vu key = lane_keys(run, i, mix);
        vf theta = ld(run->theta + i), dphi = ld(run->dphi + i);
        vf kphi = ld(run->kphi + i);
        vf cth, sth, ph, th = splat(0.0f);
        if (L->pass == 0) {
            vf r0 = rnd(key, 0), r1 = rnd(key, 1), r2 = rnd(key, 2);
            th = theta + dth * (r0 - 0.5f) * jit;
            th = sel(th < 0.0f, -th, th);
            ph = -(float)M_PI + dphi * (kphi + 0.5f) +
                 dphi * (r1 - 0.5f) * jit;
            /* the central cell: any phi */
            ph = sel(theta == 0.0f, (float)(2.0 * M_PI) * r2, ph);
            if (!L->parallel)
                vsincos(th, &sth, &cth);
        } else {
            /* uniform by area (solid angle) inside the whole cell */
            vf r0 = rnd(key, 3), r1 = rnd(key, 4);
            vf lo = vmax(theta - 0.5f * dth, splat(0.0f));
            vf hi = theta + 0.5f * dth;
            if (L->parallel) {
                th = vsqrt(lo * lo + r0 * (hi * hi - lo * lo));
            } else {
                hi = vmin(hi, splat((float)M_PI));
                vf sl, cl, sh, ch;
                vsincos(lo, &sl, &cl);
                vsincos(hi, &sh, &ch);
                vf z = cl + r0 * (ch - cl);
                cth = vmin(vmax(z, splat(-1.0f)), splat(1.0f));
                sth = vsqrt(vmax(1.0f - cth * cth, splat(0.0f)));
            }
            ph = -(float)M_PI + dphi * (kphi + r1);
        }
        vf sp, cp;
        vsincos(ph, &sp, &cp);
        vf rx = aax * cp + bx * sp, ry = aay * cp + by * sp,
            rz = aaz * cp + bz * sp;
        vf ox, oy, oz, dx, dy, dz;
        if (L->parallel) {
            dx = splat(ax);
            dy = splat(ay);
            dz = splat(az);
            ox = (float)L->base.x + rx * th;
            oy = (float)L->base.y + ry * th;
            oz = (float)L->base.z + rz * th;
        } else {
            dx = ax * cth + rx * sth;
            dy = ay * cth + ry * sth;
            dz = az * cth + rz * sth;
            vf inv = 1.0f / vsqrt(dx * dx + dy * dy + dz * dz);
            dx *= inv;
            dy *= inv;
            dz *= inv;
            ox = splat((float)L->origin.x);
            oy = splat((float)L->origin.y);
            oz = splat((float)L->origin.z);
        }
        vf a = splat(1.0f);
        if (L->atten == WF_ATTEN_SPOT) {
            vf k = (float)L->beam.x * dx + (float)L->beam.y * dy +
                    (float)L->beam.z * dz;
            float cr = (float)L->spot_cr, cf = (float)L->spot_cf;
            vf sm = cr <= cf ? splat(0.0f)
                              : smoothstep01((k - cf) / (cr - cf));
            vf out = sel(k <= cf, splat(0.0f), sm);
            a = sel(k <= 0.0f, splat(0.0f), sel(k < cr, out, a));
        } else if (L->atten == WF_ATTEN_CYLINDER) {
            vf relx = ox - (float)L->location.x,
                rely = oy - (float)L->location.y,
                relz = oz - (float)L->location.z;
            vf bb = relx * (float)L->beam.x + rely * (float)L->beam.y +
                     relz * (float)L->beam.z;
            vf px = relx - bb * (float)L->beam.x,
                py = rely - bb * (float)L->beam.y,
                pz = relz - bb * (float)L->beam.z;
            vf d2 = px * px + py * py + pz * pz;
            float fo = (float)L->falloff, ra = (float)L->radius;
            float core = ra > 0.0f && ra < fo ? ra : fo;
            vf dist = vsqrt(d2);
            vf x = 1.0f - dist / fo;
            vf att = splat(1.0f);
            if (ra > 0.0f)
                att = sel(dist > ra, smoothstep01(x / (1.0f - ra / fo)),
                          att);
            att = sel(dist >= fo, splat(0.0f), att);
            a = fo > 0.0f ? sel(d2 < 0.999f * core * core, splat(1.0f), att)
                          : splat(0.0f);
        }
        vf pw = ld(run->cell + i) * a * ld(run->emission + i);
        alive &= (a >= 1e-5f) & (pw > 0.0f);
        unsigned m = bits(alive);
        vi perm = ldi(WF_PERM(ws)[m]);
        pack(S->ox + w, ox, perm);
        pack(S->oy + w, oy, perm);
        pack(S->oz + w, oz, perm);
        pack(S->dx + w, dx, perm);
        pack(S->dy + w, dy, perm);
        pack(S->dz + w, dz, perm);
        pack(S->pw + w, pw, perm);
        pack(S->lam + w, ld(run->lambda + i), perm);
        pack(S->depth + w, splat(0.0f), perm);
        if (ws->prims[run->combo].any_tspec) /* else every white is 1 */
            pack(S->white + w, ld(run->white + i), perm);
        packi((int32_t *)S->key + w, (vi)key, perm);
        packi(S->last + w, splati(-1), perm);
        packi(S->inside + w, splati(-1), perm);
        packi(S->chroma + w, splati(L->chromatic ? 1 : 0), perm);
        w += __builtin_popcount(m);
    }
    return w;
}

/* A spectral value of each lane's primitive 'id' in the lanes set in
** 'use' (n(lambda) of a dispersive interior, a coloured filter's
** transmittance) from its table 'tab'; 'plain' in the others. */
AI vf tab_lookup(const float (*tab)[WF_IOR_N], vi id, vf lam, vf plain,
                 vi use)
{
    unsigned m = bits(use);
    if (!m)
        return plain;
    vf r = plain;
    for (int l = 0; l < WF_W; l++) {
        if (!(m >> l & 1))
            continue;
        float x = (lam[l] - SPEC_LAMBDA_MIN) *
                  ((WF_IOR_N - 1) / (float)SPEC_LAMBDA_RANGE);
        x = x < 0.0f ? 0.0f : x > WF_IOR_N - 1.001f ? WF_IOR_N - 1.001f : x;
        int k = (int)x;
        const float *t = tab[id[l] & 7];
        r[l] = t[k] + (x - (float)k) * (t[k + 1] - t[k]);
    }
    return r;
}

/* One step of every live lane: the nearest hit, the deposit, the event.
** Returns the lanes still live. */
AI int bounce(const struct wf_scene *ws, const struct wf_prims *P,
              struct wf_state *S, int n, int level, struct ptrace_out *out)
{
    const vi iota = WF_IOTA;
    const vf inf = splat(INFINITY), one = splat(1.0f), zero = splat(0.0f);
    bool last_level = level >= P->max_level;
    int w = 0;
    for (int i = 0; i < n; i += WF_W) {
        vf ox = ld(S->ox + i), oy = ld(S->oy + i), oz = ld(S->oz + i);
        vf dx = ld(S->dx + i), dy = ld(S->dy + i), dz = ld(S->dz + i);
        vi last = ldi(S->last + i);
        /* the nearest crossing */
        vf tb = inf;
        vi id = splati(-1);
        for (int k = 0; k < P->ns; k++) {
            vf cx = ox - P->sc[k][0], cy = oy - P->sc[k][1],
                cz = oz - P->sc[k][2];
            vf b = cx * dx + cy * dy + cz * dz;
            /* r^2 - |oc - b d|^2: no cancellation of b^2 - |oc|^2 */
            vf qx = cx - b * dx, qy = cy - b * dy, qz = cz - b * dz;
            vf disc = P->sr2[k] - (qx * qx + qy * qy + qz * qz);
            vf h = vsqrt(vmax(disc, zero));
            vf t0 = -b - h, t1 = -b + h;
            vf t = sel(t0 > 0.0f, t0, t1);
            /* the sphere just left: its far side, going in only */
            t = sel(last == k, sel(b < 0.0f, t1, inf), t);
            vi hit = (disc >= 0.0f) & (t > 0.0f) & (t < tb);
            tb = sel(hit, t, tb);
            id = seli(hit, splati(k), id);
        }
        for (int k = 0; k < P->np; k++) {
            vf dn = dx * P->pn[k][0] + dy * P->pn[k][1] + dz * P->pn[k][2];
            vf on = ox * P->pn[k][0] + oy * P->pn[k][1] + oz * P->pn[k][2];
            vf t = (P->pd[k] - on) / dn;
            int kk = P->ns + k;
            vi hit = (t > 0.0f) & (t < tb) & (last != kk);
            tb = sel(hit, t, tb);
            id = seli(hit, splati(kk), id);
        }
        /* convex objects: the ray's span inside each, the latest entry
        ** and the first exit over its half-spaces and balls, each end
        ** with its constituent's normal (the (p·ka - c)·s of the tables);
        ** a lane on its surface going in (last = k) takes the far end,
        ** one going out (last = k + WF_OUT) none of it */
        vf gcx = zero, gcy = zero, gcz = zero, gka = zero, gsc = one;
        vf gax = zero, gay = zero, gaz = zero;
        for (int k = 0; k < P->nc; k++) {
            vf tn = -inf, tf = inf;
            vi miss = splati(0);
            vf ecx = zero, ecy = zero, ecz = zero, eka = zero, esc = one;
            vf xcx = zero, xcy = zero, xcz = zero, xka = zero, xsc = one;
            vf eax = zero, eay = zero, eaz = zero;
            vf xax = zero, xay = zero, xaz = zero;
            int j0 = P->cfirst[k], j1 = j0 + P->ccount[k];
            for (int j = j0; j < j1; j++) {
                vf t0, t1;
                vi en, ex;
                if (P->hkind[j] == WF_HALF_CYL) {
                    /* an infinite cylinder: the sphere's solve in the
                    ** plane across its axis */
                    const float ax = P->hax[j], ay = P->hay[j],
                                az = P->haz[j];
                    vf cx = ox - P->hc[j][0], cy = oy - P->hc[j][1],
                        cz = oz - P->hc[j][2];
                    vf oa = cx * ax + cy * ay + cz * az;
                    vf da = dx * ax + dy * ay + dz * az;
                    vf bx = cx - oa * ax, by = cy - oa * ay,
                        bz = cz - oa * az;
                    vf ex_ = dx - da * ax, ey = dy - da * ay,
                        ez = dz - da * az;
                    vf A = ex_ * ex_ + ey * ey + ez * ez;
                    /* along the axis: inside for all t, or never */
                    vi par = A < 1e-12f;
                    vf As = sel(par, one, A);
                    vf tc = -(bx * ex_ + by * ey + bz * ez) / As;
                    vf qx = bx + tc * ex_, qy = by + tc * ey,
                        qz = bz + tc * ez;
                    vf disc = P->hd[j] - (qx * qx + qy * qy + qz * qz);
                    vf h = vsqrt(vmax(disc, zero) / As);
                    vf b2 = bx * bx + by * by + bz * bz;
                    miss |= seli(par, b2 > P->hd[j], disc < 0.0f);
                    t0 = sel(par, -inf, tc - h);
                    t1 = sel(par, inf, tc + h);
                    en = t0 > tn;
                    ex = t1 < tf;
                } else if (P->hkind[j] == WF_HALF_BALL) {
                    vf cx = ox - P->hc[j][0], cy = oy - P->hc[j][1],
                        cz = oz - P->hc[j][2];
                    vf b = cx * dx + cy * dy + cz * dz;
                    vf qx = cx - b * dx, qy = cy - b * dy, qz = cz - b * dz;
                    vf disc = P->hd[j] - (qx * qx + qy * qy + qz * qz);
                    vf h = vsqrt(vmax(disc, zero));
                    miss |= disc < 0.0f;
                    t0 = -b - h;
                    t1 = -b + h;
                    en = t0 > tn;
                    ex = t1 < tf;
                } else {
                    vf dn = dx * P->hc[j][0] + dy * P->hc[j][1] +
                             dz * P->hc[j][2];
                    vf on = ox * P->hc[j][0] + oy * P->hc[j][1] +
                             oz * P->hc[j][2];
                    vf t = (P->hd[j] - on) / dn;
                    /* parallel to it and outside: never inside */
                    miss |= (dn == 0.0f) & (on > P->hd[j]);
                    t0 = t1 = t;
                    en = (dn < 0.0f) & (t > tn);
                    ex = (dn > 0.0f) & (t < tf);
                }
                tn = sel(en, t0, tn);
                ecx = sel(en, splat(P->hnx[j]), ecx);
                ecy = sel(en, splat(P->hny[j]), ecy);
                ecz = sel(en, splat(P->hnz[j]), ecz);
                eka = sel(en, splat(P->hka[j]), eka);
                esc = sel(en, splat(P->hsc[j]), esc);
                tf = sel(ex, t1, tf);
                xcx = sel(ex, splat(P->hnx[j]), xcx);
                xcy = sel(ex, splat(P->hny[j]), xcy);
                xcz = sel(ex, splat(P->hnz[j]), xcz);
                xka = sel(ex, splat(P->hka[j]), xka);
                xsc = sel(ex, splat(P->hsc[j]), xsc);
                if (P->any_cyl) {
                    eax = sel(en, splat(P->hax[j]), eax);
                    eay = sel(en, splat(P->hay[j]), eay);
                    eaz = sel(en, splat(P->haz[j]), eaz);
                    xax = sel(ex, splat(P->hax[j]), xax);
                    xay = sel(ex, splat(P->hay[j]), xay);
                    xaz = sel(ex, splat(P->haz[j]), xaz);
                }
            }
            int kk = P->ns + P->np + k;
            vi self_in = last == kk;
            vi far = self_in | (tn <= 0.0f);
            vf t = sel(far, tf, tn);
            vi hit = (self_in | (~miss & (tn <= tf))) & (t > 0.0f) &
                     (t < tb) & (last != kk + WF_OUT);
            tb = sel(hit, t, tb);
            id = seli(hit, splati(kk), id);
            gcx = sel(hit, sel(far, xcx, ecx), gcx);
            gcy = sel(hit, sel(far, xcy, ecy), gcy);
            gcz = sel(hit, sel(far, xcz, ecz), gcz);
            gka = sel(hit, sel(far, xka, eka), gka);
            gsc = sel(hit, sel(far, xsc, esc), gsc);
            if (P->any_cyl) {
                gax = sel(hit, sel(far, xax, eax), gax);
                gay = sel(hit, sel(far, xay, eay), gay);
                gaz = sel(hit, sel(far, xaz, eaz), gaz);
            }
        }
        vi alive = ((iota + i) < n) & (id >= 0) & (tb < inf);
        vi idc = seli(alive, id, splati(0));
        vf px = ox + tb * dx, py = oy + tb * dy, pz = oz + tb * dz;
        vf depth = ld(S->depth + i) + tb;
        vi flags = picki(P->flags, idc);
        vf ka = pick(P->nka, idc), sc = pick(P->nsc, idc);
        vf ncx = pick(P->ncx, idc), ncy = pick(P->ncy, idc),
           ncz = pick(P->ncz, idc);
        vi convex = splati(0);
        if (P->nc > 0) {
            convex = idc >= P->ns + P->np;
            ka = sel(convex, gka, ka);
            sc = sel(convex, gsc, sc);
            ncx = sel(convex, gcx, ncx);
            ncy = sel(convex, gcy, ncy);
            ncz = sel(convex, gcz, ncz);
        }
        vf nx = (px * ka - ncx) * sc;
        vf ny = (py * ka - ncy) * sc;
        vf nz = (pz * ka - ncz) * sc;
        if (P->any_cyl) {
            /* a cylinder's: less the part along its axis (0 elsewhere) */
            vi cyl = convex & ((gax != 0.0f) | (gay != 0.0f) | (gaz != 0.0f));
            vf na = nx * gax + ny * gay + nz * gaz;
            nx = sel(cyl, nx - na * gax, nx);
            ny = sel(cyl, ny - na * gay, ny);
            nz = sel(cyl, nz - na * gaz, nz);
        }
        vf dn = dx * nx + dy * ny + dz * nz;
        vi entering = dn < 0.0f;
        vf sg = sel(entering, one, -one);
        vf nfx = nx * sg, nfy = ny * sg, nfz = nz * sg;
        vf cos_i = -dn * sg;
        if (level == 1)
            alive &= (flags & WF_TARGET) != 0;
        vf pw = ld(S->pw + i), lam = ld(S->lam + i);
        vi chroma = ldi(S->chroma + i);
        /* the deposit, after at least one bounce */
        if (level > 1) {
            vi store = alive & ((flags & WF_STORE) != 0);
            vf wh = one;
            if (P->any_tspec) {
                /* a white record: the siblings' summed power from sibling
                ** 0 (white S, the others 0), trace.c's one white record */
                wh = sel(chroma != 0, one, ld(S->white + i));
                store &= wh > 0.0f;
            }
            unsigned m = bits(store);
            if (m) {
                vf lf = P->parallel ? one : depth * depth;
                vf e = P->any_tspec ? pw * lf * wh : pw * lf;
                for (int l = 0; l < WF_W && !out->failed; l++)
                    if (m >> l & 1)
                        ptrace_out_push(out, v3(px[l], py[l], pz[l]), e[l],
                                        chroma[l] ? lam[l] : -1.0f,
                                        v3(-dx[l], -dy[l], -dz[l]));
            }
        }
        if (last_level)
            continue;
        vu key = ldu(S->key + i);
        vf u = rnd(key, 8 + (uint32_t)level);
        vi refr = (flags & WF_REFR) != 0;
        vi inside = ldi(S->inside + i);
        /* refraction: the index on both sides from the lane's medium */
        vi in_this = inside == id;
        vf n_obj = pick(P->ior, idc);
        if (P->any_disp)
            n_obj = tab_lookup(P->ior_tab, idc, lam, n_obj,
                               alive & refr & ((flags & WF_DISP) != 0));
        vf eta = sel(in_this | ~entering, n_obj, one / n_obj);
        vf cos_t;
        vf f = fresnel_lanes(cos_i, eta, &cos_t);
        vi r_refl = refr & (u < f);
        vi r_refr = refr & ~r_refl;
        alive &= ~(r_refl & entering & ((flags & WF_REFL_OK) == 0));
        /* mirrors and filters without an interior */
        vf p = pick(P->pm, idc), q = pick(P->qm, idc);
        vf tr = pick(P->transm, idc);
        vi tspec = splati(0);
        if (P->any_tspec) {
            tspec = (flags & WF_TSPEC) != 0;
            /* a coloured filter at the lane's lambda: the refraction's
            ** gain, or q (> 0 at every lambda, wf_build) */
            tr = tab_lookup(P->tr_tab, idc, lam, tr, alive & tspec);
            q = sel(tspec & ~refr, tr, q);
        }
        vi other = ~refr;
        vi q_none = q <= 0.0f, p_none = p <= 0.0f;
        vi both = ~q_none & ~p_none;
        vi mirror = other & ((q_none & (u < p)) | (both & (u * (p + q) < p)));
        alive &= ~(other & q_none & ~(u < p));
        vf gain = sel(r_refr, tr, one);
        gain = sel(other & both, p + q, gain);
        gain = sel(other & p_none & ~q_none, q, gain);
        pw *= gain;
        /* the new direction */
        vi refl = r_refl | mirror;
        vf k2 = -2.0f * (dx * nfx + dy * nfy + dz * nfz);
        vf tt = eta * cos_i - cos_t;
        vf ndx = sel(refl, dx + k2 * nfx, sel(r_refr, eta * dx + tt * nfx, dx));
        vf ndy = sel(refl, dy + k2 * nfy, sel(r_refr, eta * dy + tt * nfy, dy));
        vf ndz = sel(refl, dz + k2 * nfz, sel(r_refr, eta * dz + tt * nfz, dz));
        vf len2 = ndx * ndx + ndy * ndy + ndz * ndz;
        vf inv = 1.0f / vsqrt(len2);
        ndx *= inv;
        ndy *= inv;
        ndz *= inv;
        inside = seli(r_refr & in_this, splati(-1),
                      seli(r_refr & entering, id, inside));
        chroma |= refr & ((flags & WF_DISP) != 0);
        /* trace.c: chromatic once transmitted by a coloured filter with
        ** an interior, or once at one without (either way out) */
        if (P->any_tspec)
            chroma |= tspec & (r_refr | other);
        alive &= (pw > 0.0f) & (len2 > 0.0f) & (len2 < inf);
        unsigned m = bits(alive);
        if (!m)
            continue;
        vi perm = ldi(WF_PERM(ws)[m]);
        pack(S->ox + w, px, perm);
        pack(S->oy + w, py, perm);
        pack(S->oz + w, pz, perm);
        pack(S->dx + w, ndx, perm);
        pack(S->dy + w, ndy, perm);
        pack(S->dz + w, ndz, perm);
        pack(S->pw + w, pw, perm);
        pack(S->lam + w, lam, perm);
        pack(S->depth + w, depth, perm);
        if (P->any_tspec)
            pack(S->white + w, ld(S->white + i), perm);
        packi((int32_t *)S->key + w, (vi)key, perm);
        /* a convex object's lane leaving it outward: last = k + WF_OUT */
        vi nlast = id;
        if (P->nc > 0)
            nlast = seli(convex & (ndx * nx + ndy * ny + ndz * nz >= 0.0f),
                         id + WF_OUT, id);
        packi(S->last + w, nlast, perm);
        packi(S->inside + w, inside, perm);
        packi(S->chroma + w, chroma, perm);
        w += __builtin_popcount(m);
    }
    return w;
}

AI void trace_body(const struct wf_scene *ws, struct wf_state *S,
                   const struct wf_run *run, struct ptrace_out *out)
{
    const struct wf_prims *P = &ws->prims[run->combo];
    int n = emit(ws, &ws->light[run->combo], run, S);
    for (int level = 1; level <= P->max_level && n > 0 && !out->failed;
         level++)
        n = bounce(ws, P, S, n, level, out);
}

AI void fresnel_body(const float *cos_i, const float *eta, float *f,
                     float *cos_t, int n)
{
    for (int i = 0; i < n; i += WF_W) {
        float a[WF_W] = { 0 }, b[WF_W] = { 0 };
        int k = n - i < WF_W ? n - i : WF_W;
        memcpy(a, cos_i + i, (size_t)k * sizeof *a);
        memcpy(b, eta + i, (size_t)k * sizeof *b);
        vf ct;
        vf r = fresnel_lanes(ld(a), ld(b), &ct);
        for (int l = 0; l < k; l++) {
            f[i + l] = r[l];
            cos_t[i + l] = ct[l];
        }
    }
}

#undef bits
#undef bounce
#undef emit
#undef fresnel_body
#undef fresnel_lanes
#undef hash
#undef tab_lookup
#undef lane_keys
#undef ld
#undef ldi
#undef ldu
#undef pack
#undef packi
#undef permute
#undef pick
#undef picki
#undef rnd
#undef sel
#undef seli
#undef smoothstep01
#undef splat
#undef splati
#undef st
#undef sti
#undef trace_body
#undef vmax
#undef vmin
#undef vsincos
#undef vsqrt
#undef vf
#undef vi
#undef vu
#undef WF_IOTA
#undef WF_PERM
