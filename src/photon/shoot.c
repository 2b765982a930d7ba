/* SPDX-License-Identifier: MIT */
/*
** shoot.c: emitting photons as POV-Ray 3.7 does, and building the map.
**
** DESIGN. Every light x target pair that the shooting rule allows (a
** "combo"; the targets found as POV-Ray finds them, also inside CSG:
** targets.c) aims at the target's bounding sphere (centre of the world
** bounding box, radius half its diagonal) in rings of constant polar angle
** theta about the light->centre axis, dtheta = atan(spacing·density/dist)
** apart, each ring holding n_phi = round(2·pi·sin(theta)/dtheta) photons
** (parallel lights: rings of radius theta in the plane normal to the
** light, dtheta = spacing·density). Each photon is jittered inside its
** cell by POV-Ray's 'jitter' (default 0.4).
**
** Power. Each photon carries the light's power through its cell: the
** exact solid angle of the cell (parallel lights: its area), times the
** emission at its wavelength relative to D65 (spec_emitter_eval) times the
** spot attenuation; at deposit it is multiplied by D^2 (D = path length
** from the light; not for parallel lights) and the light fade, which is
** POV-Ray's "flux through the target per area = light colour" (§2.5:
** Phi = P·spread^2·D^2, with the cell's true size for spread^2).
**
** Wavelengths. Each photon carries one wavelength, lambda = 380 +
** 400·frac(u0 + a1·ring + a2·k_phi + a3·k_area), where (ring, k_phi) is
** its direction cell, k_area its area-light cell and u0 a random offset
** per (seed, pass): a rank-1 lattice over the cells with Roberts' R2 steps
** a1, a2 (the 2-D Kronecker lattice of lowest known discrepancy). Cells
** that are neighbours on the target are neighbours in (ring, k_phi), so
** any patch of cells - what one k-nearest gather sees - covers the
** spectrum evenly: the rms colour error (b/g) of an estimate of 100
** photons drops from 0.4-0.6 (independent draws; the per-photon RGB weight
** has a standard deviation of 2-3) to 0.05-0.18 (more near the rings'
** centre, where cells are irregular). With the random offset each photon's lambda
** is uniform on [380, 780] (pdf 1/400 per nm), as
** spec_lambda_rgb_weight() assumes. (Tried and rejected: a Kronecker
** sequence over the photon index, which forms colour moire over whole
** regions on the ring layout; random permutations in blocks or tiles,
** which gather windows cut through; a random offset per ring; the R2
** lattice over Cartesian cells of the target plane: all noisier.)
**
** Sibling wavelengths (trace.h): the photon (in media too, pmedia.c)
** also carries u + 1/3 and u + 2/3 (mod 1), a third of the power each,
** along one path (shoot_one), until a dispersive interior keeps u alone.
**
** Threads. The rings of all combos are laid end to end and numbered
** photon by photon; batches of PHOTON_BATCH consecutive photon indices
** are the work items of par_for(). A photon's random stream is keyed by
** (seed, pass, photon index), each batch fills its own buffer, and the
** buffers are concatenated in batch order, so the map does not depend on
** the thread count. POV-Ray's autostop (which needs rings in sequence) is
** not used: all rings up to theta_max are shot.
**
** Progressive passes (opts->pass > 0). Pass 0 keeps POV-Ray's jitter, so a
** single render matches POV-Ray's photon layout. POV-Ray's jitter (a
** fraction of the cell, uniform in theta and phi) leaves every pass on
** nearly the same ring lattice, and averaging passes would then keep the
** lattice's pattern. Later passes instead place each photon uniformly
** by area (solid angle for point lights) inside its whole cell: each pass
** is an unbiased stratified sample of the light's flux, independent of the
** other passes, which is what averaging passes needs (progressive.c).
*/
#include "config.h"

#include "photon/pmap.h"

#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <time.h>
#include <unistd.h>

#include "photon/membudget.h"
#include "photon/povbox.h"
#include "photon/trace.h"
#include "photon/wavefront.h"
#include "spectrum/ior.h"
#include "spectrum/spectrum.h"
#include "util/mem.h"
#include "util/thread.h"

#define PHOTON_BATCH 4096
_Static_assert(PHOTON_BATCH <= WF_MAX, "a batch is one wavefront run");

/* Roberts' R2 steps 1/phi2, 1/phi2^2 (phi2 = 1.3247..., the real root of
** x^3 = x + 1), and a third irrational step for area-light cells. */
static const double LATTICE[3] = { 0.7548776662466927, 0.5698402909980532,
                                   0.5497004779019703 };

/* One light x target pair. */
struct combo {
    struct ptrace_combo tc;
    struct spec_emitter em;
    double flat_emission;      /* !tc.chromatic: the emission at every
                                  lambda (to 1e-12), taken once */
    int n_sibs;                /* sibling wavelengths a photon carries
                                  (trace.h): PTRACE_SIBS (media too), 1
                                  with no_siblings (make_rings) */
    vec3 ctr, axis, a, b;      /* centre; unit axis light->centre or the
                                  light direction; a, b complete a basis */
    vec3 origin;               /* the light's location */
    double rad, dist;
    double est_rad;            /* the target sphere's radius, for count */
    double dtheta, theta_max;
    int n1, n2;                /* area-light photon grid (1x1 if none) */
    vec3 axis1, axis2;
    vec3 beam;                 /* unit light->point_at, for the spot and
                                  cylinder attenuation (once, not per
                                  photon) */
    double spot_cr, spot_cf;   /* spot: cos of radius and falloff */
};

/* One ring of photons. */
struct ring {
    int combo;
    double theta;
    int n_phi;
    double dphi;               /* 2·pi/n_phi, once per ring (a division
                                  per photon otherwise) */
    double cell;               /* solid angle (area) of one direction cell */
    int64_t first;             /* first photon index */
    int64_t count;             /* n_phi · n1 · n2 */
};

struct shoot {
    const iris_scene *scene;
    const struct pmap_world *w;
    const struct photon_options *opts;
    struct combo *combos;
    int n_combos;
    struct ptargets targets;   /* the objects shot at (targets.c) */
    struct ptargets *leaves;   /* leaves[i]: targets.o[i]'s, for
                                  ptrace_in_target() */
    struct ring *rings;
    int64_t n_rings, n_photons;
    double jitter;
    double u0;                 /* random offset of the wavelength lattice */
    struct ptrace_out *outs;   /* one per batch */
    int64_t slab_per;          /* slab slots per photon (sibling_records) */
    struct pstore_raw *slab;   /* PHOTON_BATCH slots per batch, batch b's
                                  from b·PHOTON_BATCH (NULL: each batch
                                  grows its own buffer) */
    /* The memory budget (membudget.h) for the photons STORED: a photon
    ** can deposit many times (a diffuse mirror between two plates), which
    ** the count checked before shooting does not know. Batches add what
    ** they stored; once past 'store_cap' the rest are skipped and the
    ** build fails with a located error instead of running out. */
    double store_cap;
    struct membudget budget;
    _Atomic int64_t n_stored;
    atomic_bool over_budget;
    _Atomic int64_t tex_cached; /* photon_stats.tex_cached */
    /* The wavefront tracer (wavefront.h) when it takes the scene, with
    ** each thread's lanes and run; NULL: trace.c for every photon */
    struct wf_scene *wf;
    struct wf_state **wf_st;
    struct wf_run **wf_run;
    int wf_threads;
};

bool pmap_shoots(const iris_light *l, const iris_object *t)
{
    if (l->shadowless || !t->photon_target || !(t->photon_density > 0.0))
        return false;
    enum iris_tristate rf[2] = { l->photon_refraction, t->photon_refraction };
    enum iris_tristate rl[2] = { l->photon_reflection, t->photon_reflection };
    bool rfr_on = rf[0] == IRIS_ON || rf[1] == IRIS_ON;
    bool rfr_off = rf[0] == IRIS_OFF || rf[1] == IRIS_OFF;
    bool rfl_on = rl[0] == IRIS_ON || rl[1] == IRIS_ON;
    bool rfl_off = rl[0] == IRIS_OFF || rl[1] == IRIS_OFF;
    return (rfr_on && !rfr_off) || (rfl_on && !rfl_off);
}

static bool light_parallel(const iris_light *l)
{
    return l->parallel || l->kind == IRIS_LIGHT_CYLINDER;
}

/* Spot and cylinder attenuation (semantics §3.5, without fade). */
static double smooth(double t)
{
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    return t * t * (3.0 - 2.0 * t);
}

/* A spot light's attenuation along 'dir', given the cosines of its radius
** 'cr' and falloff 'cf' (shoot_one takes them once per combo, not per
** photon). */
static double spot_atten(const iris_light *l, vec3 axis, vec3 dir, double cr,
                         double cf)
{
    double k = v3_dot(axis, dir);
    if (k <= 0.0)
        return 0.0;
    double a = l->tightness > 0.0 ? pow(k, l->tightness) : 1.0;
    if (k < cr)
        a *= k <= cf || cr <= cf ? 0.0 : smooth((k - cf) / (cr - cf));
    return a;
}

double pmap_light_atten(const iris_light *l, vec3 axis, vec3 origin, vec3 dir)
{
    if (l->kind == IRIS_LIGHT_SPOT && !l->parallel)
        return spot_atten(l, axis, dir, cos(l->radius * M_PI / 180.0),
                          cos(l->falloff * M_PI / 180.0));
    if (l->kind == IRIS_LIGHT_CYLINDER) {
        vec3 rel = v3_sub(origin, l->location);
        vec3 perp = v3_madd(rel, axis, -v3_dot(rel, axis));
        double d2 = v3_len2(perp);
        /* Well inside the full-power core (and tightness 0) the answer
        ** is exactly 1 below: no square root and division per photon.
        ** The margin keeps rounding of d2 against the limits away. */
        double core = l->radius > 0.0 && l->radius < l->falloff
                          ? l->radius : l->falloff;
        if (l->falloff > 0.0 && !(l->tightness > 0.0) &&
            d2 < 0.999 * core * core)
            return 1.0;
        double dist = sqrt(d2);
        if (!(l->falloff > 0.0) || dist >= l->falloff)
            return 0.0;
        double x = 1.0 - dist / l->falloff;
        double a = l->tightness > 0.0 ? pow(x, l->tightness) : 1.0;
        if (l->radius > 0.0 && dist > l->radius)
            a *= smooth(x / (1.0 - l->radius / l->falloff));
        return a;
    }
    return 1.0;
}

/*
** Whether no interior in object 'o' (CSG children and clipped_by
** included) is dispersive. A tree deeper than 64 levels answers false:
** trace.c then tests at every refraction, as without this.
*/
static bool object_none_dispersive(const iris_object *o, int depth)
{
    if (!o)
        return true;
    if (depth > 64 || ior_is_dispersive(o->interior))
        return false;
    if (o->kind >= IRIS_OBJ_UNION && o->kind < IRIS_OBJ_KIND_COUNT &&
        o->u.csg.children)
        for (int i = 0; i < o->u.csg.n_children; i++)
            if (!object_none_dispersive(o->u.csg.children[i], depth + 1))
                return false;
    if (o->clipped_by)
        for (int i = 0; i < o->n_clipped_by; i++)
            if (!object_none_dispersive(o->clipped_by[i], depth + 1))
                return false;
    return true;
}

/* Whether no interior of the scene, objects or lights' looks_like, is
** dispersive (ptrace_combo.no_dispersion). */
static bool scene_none_dispersive(const iris_scene *sc)
{
    for (int i = 0; i < sc->n_objects; i++)
        if (!object_none_dispersive(sc->objects[i], 0))
            return false;
    for (int i = 0; i < sc->n_lights; i++)
        if (!object_none_dispersive(sc->lights[i]->looks_like, 0) ||
            !object_none_dispersive(sc->lights[i]->projected_through, 0))
            return false;
    return true;
}

/* The targets of the scene (POV-Ray's, targets.c) and the leaves of
** those inside a CSG. */
static enum iris_status find_targets(struct shoot *s)
{
    enum iris_status rc = ptargets_find(s->scene, &s->targets);
    if (rc != IRIS_OK || s->targets.n == 0)
        return rc;
    s->leaves = iris_calloc((size_t)s->targets.n, sizeof *s->leaves);
    if (!s->leaves)
        return IRIS_ENOMEM;
    /* a first hit on a top-level target is known by its top-level
    ** object (ptrace_in_target): no leaves needed */
    for (int i = 0; i < s->targets.n && rc == IRIS_OK; i++)
        if (!s->targets.top[i])
            rc = ptargets_leaves(s->targets.o[i], &s->leaves[i]);
    return rc;
}

/* Collects the combos and their bounding spheres: every light x target
** pair in POV-Ray's order (lights, then targets, targets.c). */
static enum iris_status find_combos(struct shoot *s)
{
    const iris_scene *sc = s->scene;
    enum iris_status rc = find_targets(s);
    if (rc != IRIS_OK)
        return rc;
    int cap = sc->n_lights * s->targets.n;
    if (cap <= 0)
        return IRIS_OK;
    s->combos = iris_calloc((size_t)cap, sizeof *s->combos);
    if (!s->combos)
        return IRIS_ENOMEM;
    int max_level = sc->settings.photons.max_trace_level;
    if (max_level < 0)
        max_level = sc->settings.max_trace_level;
    /* Whether any interior disperses, once instead of at every refraction
    ** of every photon (trace.c) */
    bool none_dispersive = scene_none_dispersive(sc);
    for (int li = 0; li < sc->n_lights; li++) {
        const iris_light *l = sc->lights[li];
        for (int ti = 0; ti < s->targets.n; ti++) {
            const iris_object *t = s->targets.o[ti];
            vec3 lo, hi;
            if (!pmap_shoots(l, t) ||
                !s->w->object_bounds(s->w->ctx, t, &lo, &hi))
                continue;
            struct combo *c = &s->combos[s->n_combos++];
            c->tc.light = l;
            c->tc.target = t;
            c->tc.target_leaves = s->leaves[ti].o;
            c->tc.n_target_leaves = s->leaves[ti].n;
            c->tc.parallel = light_parallel(l);
            c->tc.fade_distance = l->fade_distance;
            c->tc.fade_power = l->fade_power;
            c->tc.max_level = max_level;
            c->tc.mat = s->opts->mat;
            spec_emitter_init(&c->em, l);
            /* a flat emission (white or grey D65-shaped light) leaves the
            ** photon's power independent of its wavelength */
            double e0 = spec_emitter_eval(&c->em, SPEC_LAMBDA_MIN);
            for (int k = 1; k <= 80 && !c->tc.chromatic; k++)
                if (fabs(spec_emitter_eval(&c->em, SPEC_LAMBDA_MIN +
                                                       5.0 * k) - e0) >
                    1e-12 * fabs(e0))
                    c->tc.chromatic = true;
            c->flat_emission = e0;
            c->tc.no_dispersion = none_dispersive;
            c->beam = v3_norm(v3_sub(l->point_at, l->location));
            c->spot_cr = cos(l->radius * M_PI / 180.0);
            c->spot_cf = cos(l->falloff * M_PI / 180.0);
            c->ctr = v3_scale(v3_add(lo, hi), 0.5);
            c->rad = 0.5 * v3_len(v3_sub(hi, lo));
            c->est_rad = c->rad;
            /* the count estimate takes POV-Ray's wider box of a target
            ** holding a blob (povbox.c); the rings keep iris's */
            vec3 plo, phi;
            if (povbox_target(t, s->w->object_bounds, s->w->ctx, &plo, &phi))
                c->est_rad = 0.5 * v3_len(v3_sub(phi, plo));
            c->origin = l->location;
            if (c->tc.parallel) {
                c->axis = v3_norm(v3_sub(l->point_at, l->location));
                c->dist = v3_dot(v3_sub(c->ctr, l->location), c->axis);
                if (l->kind == IRIS_LIGHT_CYLINDER && l->falloff > 0.0) {
                    /* Only the beam carries light: centre the rings on
                    ** its axis and stop at its falloff radius (fewer
                    ** wasted photons, same power per area) */
                    vec3 on_axis = v3_madd(l->location, c->axis, c->dist);
                    double off = v3_len(v3_sub(on_axis, c->ctr));
                    if (off > c->rad + l->falloff) {
                        s->n_combos--; /* the beam misses the target */
                        continue;
                    }
                    c->ctr = on_axis;
                    c->rad = fmin(c->rad + off, l->falloff);
                }
            } else {
                c->dist = v3_len(v3_sub(c->ctr, l->location));
                c->axis = c->dist > 0 ? v3_scale(v3_sub(c->ctr, l->location),
                                                 1.0 / c->dist)
                                      : v3(0, 0, 1);
            }
            v3_basis(c->axis, &c->a, &c->b);
            c->n1 = c->n2 = 1;
            if (l->area && l->photon_area_light && l->size1 > 1 &&
                l->size2 > 1) {
                c->n1 = l->size1;
                c->n2 = l->size2;
                c->axis1 = l->axis1;
                c->axis2 = l->axis2;
            }
            /* Interiors that contain the light */
            if (s->w->inside && !c->tc.parallel)
                for (int k = 0; k < sc->n_objects; k++) {
                    const iris_object *o = sc->objects[k];
                    if (o->interior && c->tc.n_stack < PTRACE_MAX_STACK &&
                        s->w->inside(s->w->ctx, o, l->location))
                        c->tc.stack[c->tc.n_stack++] = o;
                }
        }
    }
    return IRIS_OK;
}

/* POV-Ray's 'count' -> spacing (semantics §2.4). */
static double spacing_for(const struct shoot *s)
{
    const iris_photon_settings *ps = &s->scene->settings.photons;
    double sp = ps->spacing > 0.0 ? ps->spacing : 1.0;
    if (ps->count <= 0)
        return sp;
    double e = 0.0;
    for (int i = 0; i < s->n_combos; i++) {
        const struct combo *c = &s->combos[i];
        const iris_object *t = c->tc.target;
        /* the whole target sphere, as POV-Ray, also for cylinder beams
        ** (whose rings stop at the beam: find_combos) */
        double x = M_PI * pow(c->est_rad / (t->photon_density * sp), 2.0);
        bool rfr = t->photon_refraction == IRIS_ON ||
                   c->tc.light->photon_refraction == IRIS_ON;
        bool rfl = t->photon_reflection == IRIS_ON ||
                   c->tc.light->photon_reflection == IRIS_ON;
        if (rfr && rfl)
            x *= t->photon_collect ? 1.5 * 3.0 : 1.5;
        else if (rfr && t->photon_collect)
            x *= 2.0;
        e += 0.5 * x;
    }
    return e > 0.0 ? sp * sqrt(e / ps->count) : sp;
}

/*
** The photon cap. A spacing of 1e-9 (or count 1e12) asks for ~1e19
** photons; shooting them would run out of memory or time with no hint
** why. The cap is what the memory this process may still allocate
** (membudget.h: MemAvailable, ulimit -v/-d, the cgroup's memory.max,
** whichever is least) holds at MEMBUDGET_PHOTON_BYTES a record, after
** the global map's share, and at sibling_records() records an emitted
** photon: about 3.8e8 photons on an idle 24 GB machine, 1.27e8 under a
** coloured light (three records a photon), so a pass of 1e8 photons runs
** (issue 8). Past it the build fails with a
** located error before anything is allocated ("a clear error before a
** run would exceed the memory available"), rather than being killed or
** silently shooting fewer photons than the scene asks for. A caller that
** sets max_photons chooses clamping instead: the spacing is raised to
** fit, with a warning.
*/
#define PMAP_MAX_PHOTONS 1e12 /* no cap but memory's */

/* The records an emitted photon stores: PTRACE_SIBS when some combo
** shoots sibling wavelengths (trace.h) from a light of chromatic emission,
** whose every path is chromatic and stores one record per sibling (fewer
** where a dispersive interior keeps one); else 1. A white
** light's photons turn chromatic only at coloured surfaces, unknown here:
** if they then store more records than the budget holds, shoot_batch()'s
** store cap stops the pass with a located error, as for photons that
** deposit more than once. Media photons (several a photon, one per
** sibling on a chromatic path) are caught by that cap too. */
static double sibling_records(const struct shoot *s)
{
    if (s->opts->no_siblings)
        return 1.0;
    for (int ci = 0; ci < s->n_combos; ci++)
        if (s->combos[ci].tc.chromatic)
            return PTRACE_SIBS;
    return 1.0;
}

/* The photons a pass may emit; '*records' gets the records it may
** store (the store's cap while shooting, shoot_batch()). */
static double photon_cap(const struct shoot *s, struct membudget *b,
                         double *global, double *records)
{
    const struct photon_options *o = s->opts;
    membudget_available(b);
    *global = 0.0;
    *records = INFINITY; /* clamping bounds what is shot, not stored */
    if (o->max_photons > 0)
        return (double)o->max_photons;
    *global = !pmap_wants_global(s->scene) ? 0.0
              : o->global_photons > 0      ? (double)o->global_photons
                                           : PMAP_GLOBAL_PHOTONS;
    double room = b->bytes - membudget_photon_peak(0.0, *global);
    double cap = fmin(PMAP_MAX_PHOTONS, room / MEMBUDGET_PHOTON_BYTES);
    /* pstore_knn's indices are uint32_t: a 512 GB machine is the first
    ** that could store more photons */
    cap = fmax(fmin(cap, 4.0e9), 1000.0);
    *records = cap;
    return fmax(cap / sibling_records(s), 1000.0);
}

/* The ring step and extent of combo 'c' at 'spacing' (as make_rings). */
static void combo_grid(struct combo *c, double spacing)
{
    double spread = c->tc.target->photon_density * spacing;
    if (c->n1 > 1)
        spread *= sqrt((double)c->n1 * c->n2);
    if (c->tc.parallel) {
        c->dtheta = spread;
        c->theta_max = c->rad;
    } else {
        spread /= c->dist > 0 ? c->dist : 1.0;
        c->dtheta = atan(spread);
        c->theta_max = c->dist >= c->rad ? asin(c->rad / c->dist) : M_PI;
    }
}

/*
** The photons make_rings() lays out at 'spacing', in closed form: rings
** of constant theta dtheta apart with 2·pi·sin(theta)/dtheta photons each
** integrate to 2·pi·(1 - cos theta_max)/dtheta^2 (parallel lights:
** pi·theta_max^2/dtheta^2), plus at most one photon per ring from the
** rounding up; times the area-light grid. Overflows to +inf, not UB.
*/
static double combo_photons(struct combo *c, double spacing)
{
    combo_grid(c, spacing);
    double d = c->dtheta;
    if (!(d > 0.0) || !isfinite(d))
        return 0.0;
    double area = c->tc.parallel ? M_PI * c->theta_max * c->theta_max
                                 : 2.0 * M_PI * (1.0 - cos(c->theta_max));
    return (area / (d * d) + c->theta_max / d + 1.0) * (double)c->n1 *
           (double)c->n2;
}

static double estimate_photons(struct shoot *s, double spacing)
{
    double total = 0.0;
    for (int ci = 0; ci < s->n_combos; ci++)
        total += combo_photons(&s->combos[ci], spacing);
    return total;
}

/*
** The file:line:col to blame for the photons 'spacing' asks for: the
** 'target S' of the object that asks for the most, when S is not 1 (an
** object's 'target 1e-7' under a sane global spacing is what a user must
** change), else the photon settings (or the first target). '*density'
** gets that S (1 for the settings).
*/
static void photon_loc(struct shoot *s, double spacing, const char **file,
                       iris_loc *loc, double *density)
{
    const iris_scene *sc = s->scene;
    *loc = sc->settings.photons.loc;
    if (loc->line == 0)
        *loc = s->combos[0].tc.target->loc;
    *density = 1.0;
    int worst = 0;
    double most = -1.0;
    for (int ci = 0; ci < s->n_combos; ci++) {
        double n = combo_photons(&s->combos[ci], spacing);
        if (!(n <= most)) { /* an infinite count counts too */
            most = n;
            worst = ci;
        }
    }
    const iris_object *t = s->combos[worst].tc.target;
    if (t->photon_density != 1.0 && t->photon_target_loc.line > 0) {
        *loc = t->photon_target_loc;
        *density = t->photon_density;
    }
    *file = "<unknown>";
    if (loc->file > 0 && (int)loc->file < sc->n_files && sc->files &&
        sc->files[loc->file])
        *file = sc->files[loc->file];
}

/*
** Checks the photons 'spacing' asks for against the cap (see above).
** Returns the spacing to use, or -1 after a located error when the
** memory cap is exceeded and the caller did not ask for clamping. With
** max_photons set, raises the spacing until the photons fit and warns
** once (pass 0). The count falls as 1/spacing^2 but not exactly (the
** ring rounding, atan), hence the few iterations.
*/
static double cap_spacing(struct shoot *s, double spacing)
{
    struct membudget b;
    double global;
    double cap = photon_cap(s, &b, &global, &s->store_cap);
    s->budget = b;
    double est = estimate_photons(s, spacing);
    if (!(est > cap) || s->n_combos == 0)
        return spacing;
    FILE *log = s->opts->log ? s->opts->log : stderr;
    const char *file;
    iris_loc loc;
    double density;
    photon_loc(s, spacing, &file, &loc, &density);
    if (s->opts->max_photons <= 0) {
        char need[32], have[32], what[96];
        if (density != 1.0)
            snprintf(what, sizeof what, "this object's 'target %g' (spacing "
                     "%g x %g)", density, spacing, density);
        else
            snprintf(what, sizeof what, "spacing %g", spacing);
        /* every pass: a failure stops the run, and an MPI rank > 0
        ** never builds pass 0 (progressive.c sends its message on) */
        fprintf(log, "%s:%u:%u: error: photons: %s would shoot "
                    "%.3g photons, about %s at the photon pass's peak, more "
                    "than the %s %s leaves (%.3g photons); raise %s\n", file,
                    (unsigned)loc.line, (unsigned)loc.col, what, est,
                    membudget_format(membudget_photon_peak(
                                         est * sibling_records(s), global),
                                     need, sizeof need),
                    membudget_format(b.bytes, have, sizeof have), b.what,
                    cap, density != 1.0 ? "the target"
                                        : "'spacing' or lower 'count'");
        return -1.0;
    }
    double sp = spacing;
    for (int it = 0; it < 60 && !(estimate_photons(s, sp) <= cap); it++) {
        double e = estimate_photons(s, sp);
        double f = isfinite(e) ? sqrt(e / cap) * 1.0001 : 1e3;
        sp *= f > 1.0001 ? f : 1.0001;
    }
    if (s->opts->pass == 0)
        fprintf(log, "%s:%u:%u: warning: photons: spacing %g would shoot %.3g "
                "photons; capped at %.3g photons (spacing %g)\n", file,
                (unsigned)loc.line, (unsigned)loc.col, spacing, est, cap, sp);
    return sp;
}

/* Lays out the rings of every combo. */
static enum iris_status make_rings(struct shoot *s, double spacing)
{
    int64_t cap = 0;
    for (int pass = 0; pass < 2; pass++) {
        int64_t nr = 0, np = 0;
        for (int ci = 0; ci < s->n_combos; ci++) {
            struct combo *c = &s->combos[ci];
            combo_grid(c, spacing);
            pmedia_setup(&c->tc.media, s->scene, c->dtheta);
            c->n_sibs = !s->opts->no_siblings ? PTRACE_SIBS : 1;
            if (!(c->dtheta > 0.0) || !isfinite(c->dtheta))
                continue;
            /* Guard against absurd photon counts (about 1e9 rings). */
            if (c->theta_max / c->dtheta > 1e7)
                c->dtheta = c->theta_max / 1e7;
            int64_t per = (int64_t)c->n1 * c->n2;
            for (double th = 0.0; th < c->theta_max; th += c->dtheta) {
                double lo = fmax(0.0, th - 0.5 * c->dtheta);
                double hi = th + 0.5 * c->dtheta;
                int n_phi;
                double cell;
                if (c->tc.parallel) {
                    n_phi = th > 0 ? (int)fmax(1.0, lround(2 * M_PI * th /
                                                          c->dtheta))
                                   : 1;
                    cell = M_PI * (hi * hi - lo * lo) / n_phi;
                } else {
                    hi = fmin(hi, M_PI);
                    n_phi = th > 0 ? (int)fmax(1.0, lround(2 * M_PI * sin(th) /
                                                          c->dtheta))
                                   : 1;
                    cell = 2 * M_PI * (cos(lo) - cos(hi)) / n_phi;
                }
                if (pass == 1) {
                    struct ring *r = &s->rings[nr];
                    r->combo = ci;
                    r->theta = th;
                    r->n_phi = n_phi;
                    r->dphi = 2.0 * M_PI / n_phi;
                    r->cell = cell / per;
                    r->first = np;
                    r->count = (int64_t)n_phi * per;
                }
                nr++;
                np += (int64_t)n_phi * per;
            }
        }
        if (pass == 0) {
            cap = nr;
            if (cap == 0)
                return IRIS_OK;
            s->rings = iris_calloc((size_t)cap, sizeof *s->rings);
            if (!s->rings)
                return IRIS_ENOMEM;
        } else {
            s->n_rings = nr;
            s->n_photons = np;
        }
    }
    return IRIS_OK;
}

/* The ring holding photon index 'j' (binary search). */
static const struct ring *ring_of(const struct shoot *s, int64_t j)
{
    int64_t lo = 0, hi = s->n_rings - 1;
    while (lo < hi) {
        int64_t mid = (lo + hi + 1) / 2;
        if (s->rings[mid].first <= j)
            lo = mid;
        else
            hi = mid - 1;
    }
    return &s->rings[lo];
}

/*
** The wavelength of the photon at direction cell ('ring', 'k_phi') and
** area-light cell 'k_area', before the random offset (DESIGN note above):
** a rank-1 lattice over the cell indices.
*/
static double lambda_lattice(int64_t ring, int64_t k_phi, int64_t k_area)
{
    double x = LATTICE[0] * (double)ring + LATTICE[1] * (double)k_phi +
               LATTICE[2] * (double)k_area;
    /* x >= 0 (the indices are), below 2^63: truncation is floor(), the
    ** same number without the libm call */
    return x - (double)(int64_t)x;
}

/*
** A direction uniform by area (parallel lights) or solid angle inside the
** whole cell (ring 'rg', column 'k_phi'): theta from the inverse of the
** cell's cumulative measure, phi uniform over the column.
*/
static void cell_uniform(const struct combo *c, const struct ring *rg,
                         int64_t k_phi, rng *r, double *th, double *ph)
{
    double lo = fmax(0.0, rg->theta - 0.5 * c->dtheta);
    double hi = rg->theta + 0.5 * c->dtheta;
    double u = rng_uniform(r), v = rng_uniform(r);
    if (c->tc.parallel) {
        *th = sqrt(lo * lo + u * (hi * hi - lo * lo));
    } else {
        hi = fmin(hi, M_PI);
        double z = cos(lo) + u * (cos(hi) - cos(lo));
        *th = acos(z < -1.0 ? -1.0 : z > 1.0 ? 1.0 : z);
    }
    *ph = -M_PI + rg->dphi * ((double)k_phi + v);
}

/* The siblings' offsets j/S on the lattice value (k/3 as the division
** gives it; one sibling reads the first only). */
static const double SIB_OFFSET[PTRACE_SIBS] = { 0.0, 1.0 / 3.0, 2.0 / 3.0 };
_Static_assert(PTRACE_SIBS == 3, "SIB_OFFSET lists PTRACE_SIBS offsets");

/* Emits and traces photon 'j' of ring 'rg'. */
static void shoot_one(const struct shoot *s, const struct ring *rg, int64_t j,
                      struct ptrace_out *out)
{
    const struct combo *c = &s->combos[rg->combo];
    int64_t local = j - rg->first;
    int64_t per = (int64_t)c->n1 * c->n2;
    /* (no 64-bit division for the usual single light cell) */
    int64_t k_phi = per == 1 ? local : local / per;
    int64_t k_area = per == 1 ? 0 : local % per;
    rng r;
    rng_seed(&r, s->opts->seed, (uint64_t)s->opts->pass, (uint64_t)j);
    double dphi = rg->dphi;
    double th = rg->theta + c->dtheta * (rng_uniform(&r) - 0.5) * s->jitter;
    double ph = -M_PI + dphi * (k_phi + 0.5) +
                dphi * (rng_uniform(&r) - 0.5) * s->jitter;
    if (rg->theta == 0.0)
        ph = 2.0 * M_PI * rng_uniform(&r); /* the central cell: any phi */
    th = fabs(th);
    if (s->opts->pass > 0)
        cell_uniform(c, rg, k_phi, &r, &th, &ph);
    vec3 radial = v3_add(v3_scale(c->a, cos(ph)), v3_scale(c->b, sin(ph)));
    vec3 o, d;
    if (c->tc.parallel) {
        d = c->axis;
        /* start on the light's plane, opposite the target's centre */
        vec3 base = v3_madd(c->ctr, c->axis, -c->dist);
        o = v3_madd(base, radial, th);
    } else {
        d = v3_norm(v3_add(v3_scale(c->axis, cos(th)),
                           v3_scale(radial, sin(th))));
        o = c->origin;
    }
    if (per > 1) {
        int u = (int)(k_area % c->n1), v = (int)(k_area / c->n1);
        o = v3_madd(o, c->axis1, (double)u / (c->n1 - 1) - 0.5);
        o = v3_madd(o, c->axis2, (double)v / (c->n2 - 1) - 0.5);
    }
    const iris_light *l = c->tc.light;
    double a = l->kind == IRIS_LIGHT_SPOT && !l->parallel
                   ? spot_atten(l, c->beam, d, c->spot_cr, c->spot_cf)
                   : pmap_light_atten(l, c->beam, o, d);
    if (a < 1e-5)
        return;
    double u = s->u0 + lambda_lattice(rg - s->rings, k_phi, k_area);
    if (u >= 1.0) /* u in [0, 2): u - floor(u), exact (Sterbenz) */
        u -= 1.0;
    /* Sibling wavelengths u + j/S (trace.h; global photons are
    ** global.c's). A light of flat emission gives them one
    ** power, taken once (the siblings' 'equal' set). */
    struct ptrace_sibs sb;
    sb.n = c->n_sibs;
    for (int k = 0; k < sb.n; k++) {
        double uj = u + SIB_OFFSET[k];
        sb.lambda[k] = spec_sample_uniform(uj < 1.0 ? uj : uj - 1.0);
    }
    sb.equal = !c->tc.chromatic;
    if (sb.equal) {
        sb.power[0] = rg->cell * a / sb.n * c->flat_emission;
        if (!(sb.power[0] > 0.0))
            return;
    } else {
        bool any = false;
        for (int k = 0; k < sb.n; k++) {
            sb.power[k] = rg->cell * a / sb.n *
                          spec_emitter_eval(&c->em, sb.lambda[k]);
            any = any || sb.power[k] > 0.0;
        }
        if (!any)
            return;
    }
    ptrace_photon_sibs(s->w, &c->tc, o, d, &sb, &r, out);
}

/*
** Photons lo..hi-1 through the wavefront tracer: each run of one combo
** laid out in the thread's lanes (the cell, column and lattice wavelength
** of shoot_one(); the random draws and the rest are wavefront.c's).
*/
static void wf_batch(struct shoot *s, int64_t lo, int64_t hi, int thread,
                     struct ptrace_out *out)
{
    struct wf_run *run = s->wf_run[thread];
    const struct ring *rg = ring_of(s, lo);
    const struct ring *last = s->rings + s->n_rings - 1;
    run->n = 0;
    run->combo = rg->combo;
    /* the combo's lanes a photon, its flat power share (per combo) */
    int lanes_of = -1, n_lanes = 1;
    float flat = 0.0f;
    for (int64_t j = lo; j < hi && !out->failed; j++) {
        while (rg < last && j >= rg[1].first)
            rg++;
        if (run->n > 0 && rg->combo != run->combo) {
            wf_trace(s->wf, s->wf_st[thread], run, out);
            run->n = 0;
        }
        run->combo = rg->combo;
        const struct combo *c = &s->combos[rg->combo];
        if (lanes_of != rg->combo) {
            /* a flat emission: one lane at the lattice wavelength with
            ** the whole power (its siblings' white record, or sibling 0
            ** with theirs past dispersion); a chromatic one, or a flat
            ** one that a coloured filter may make chromatic: a lane per
            ** sibling (wavefront.c), each with its share of
            ** shoot_one()'s power */
            lanes_of = rg->combo;
            n_lanes = c->tc.chromatic || wf_sibling_lanes(s->wf, rg->combo)
                          ? c->n_sibs
                          : 1;
            flat = (float)(c->flat_emission / n_lanes);
        }
        int64_t k_phi = j - rg->first; /* one light cell (wf_setup) */
        double u = s->u0 + lambda_lattice(rg - s->rings, k_phi, 0);
        if (u >= 1.0)
            u -= 1.0;
        for (int sib = 0; sib < n_lanes; sib++) {
            int k = run->n++;
            double uj = u + SIB_OFFSET[sib];
            double lam = spec_sample_uniform(uj < 1.0 ? uj : uj - 1.0);
            run->theta[k] = (float)rg->theta;
            run->dphi[k] = (float)rg->dphi;
            run->kphi[k] = (float)k_phi;
            run->cell[k] = (float)rg->cell;
            run->lambda[k] = (float)lam;
            run->emission[k] =
                c->tc.chromatic
                    ? (float)(spec_emitter_eval(&c->em, lam) / n_lanes)
                    : flat;
            run->white[k] = n_lanes == 1 ? 1.0f
                            : sib == 0   ? (float)n_lanes
                                         : 0.0f;
            run->idx_lo[k] = (uint32_t)j;
            run->idx_hi[k] = (uint32_t)((uint64_t)j >> 32);
        }
    }
    if (run->n > 0 && !out->failed)
        wf_trace(s->wf, s->wf_st[thread], run, out);
}

static void shoot_batch(void *ctx, int64_t item, int thread)
{
    struct shoot *s = ctx;
    int64_t lo = item * PHOTON_BATCH;
    int64_t hi = lo + PHOTON_BATCH < s->n_photons ? lo + PHOTON_BATCH
                                                  : s->n_photons;
    if (atomic_load(&s->over_budget) ||
        (s->opts->interrupt && *s->opts->interrupt))
        return;
    /* The batch's output record is written at every photon stored (its
    ** count); it lives on this thread's stack meanwhile. In s->outs the
    ** records of neighbouring batches (40 bytes each) share cache lines,
    ** and two threads on neighbouring batches, the usual case, moved the
    ** line between the cores at every store (false sharing). */
    struct ptrace_out out = s->outs[item];
    if (s->wf) {
        wf_batch(s, lo, hi, thread, &out);
        s->outs[item] = out;
        int64_t n = atomic_fetch_add(&s->n_stored, (int64_t)out.n) +
                    (int64_t)out.n;
        if ((double)n > s->store_cap)
            atomic_store(&s->over_budget, true);
        return;
    }
    /* one search per batch, then the rings in order */
    const struct ring *rg = ring_of(s, lo);
    const struct ring *last = s->rings + s->n_rings - 1;
    /* textures of one colour everywhere, evaluated once a batch */
    struct ptrace_tex_cache tex;
    memset(&tex, 0, sizeof tex);
    out.tex = s->opts->no_tex_cache ? NULL : &tex;
    for (int64_t j = lo; j < hi && !out.failed; j++) {
        while (rg < last && j >= rg[1].first)
            rg++;
        shoot_one(s, rg, j, &out);
    }
    out.tex = NULL;
    s->outs[item] = out;
    atomic_fetch_add(&s->tex_cached, tex.hits);
    int64_t n = atomic_fetch_add(&s->n_stored, (int64_t)out.n) +
                (int64_t)out.n;
    if ((double)n > s->store_cap)
        atomic_store(&s->over_budget, true);
}

/*
** A thread's lanes (its wf_state and wf_run, about 1 MB together) kept
** between passes: a progressive render shoots a map every pass, and fresh
** lanes each time cost some 290 page faults a pass at 2 threads (the
** kernel hands out new zero pages on their first touch; bench/scaling.sh
** at 8 passes: 7,700 -> 5,100 in all), kernel time that made 2 threads
** use more CPU than 1 (issue 8). A stack
** of up to WF_KEEP spare pairs, taken by wf_setup and given back by
** wf_teardown; a shoot running alongside another takes fresh ones when
** the stack is empty. Nothing in the lanes outlives a run: wf_trace
** writes every lane it reads (emit() lays out each run; lanes past a
** run's end are masked off), so reused lanes give the same map.
*/
#define WF_KEEP 16
static pthread_mutex_t wf_keep_mu = PTHREAD_MUTEX_INITIALIZER;
static struct wf_state *wf_keep_st[WF_KEEP];
static struct wf_run *wf_keep_run[WF_KEEP];
static int wf_n_keep;

/* Kept lanes into '*st' and '*run', else new ones (NULL on no memory). */
static void wf_lanes_take(struct wf_state **st, struct wf_run **run)
{
    *st = NULL;
    *run = NULL;
    pthread_mutex_lock(&wf_keep_mu);
    if (wf_n_keep > 0) {
        wf_n_keep--;
        *st = wf_keep_st[wf_n_keep];
        *run = wf_keep_run[wf_n_keep];
    }
    pthread_mutex_unlock(&wf_keep_mu);
    if (!*st) {
        *st = wf_state_new();
        *run = iris_malloc(sizeof **run);
    }
}

/* Lanes back to the stack, or freed when it is full or one is missing. */
static void wf_lanes_give(struct wf_state *st, struct wf_run *run)
{
    bool kept = false;
    if (st && run) {
        pthread_mutex_lock(&wf_keep_mu);
        if (wf_n_keep < WF_KEEP) {
            wf_keep_st[wf_n_keep] = st;
            wf_keep_run[wf_n_keep] = run;
            wf_n_keep++;
            kept = true;
        }
        pthread_mutex_unlock(&wf_keep_mu);
    }
    if (!kept) {
        wf_state_free(st);
        iris_free(run);
    }
}

/* Frees the wavefront tracer; the lanes back to the stack (none: nothing). */
static void wf_teardown(struct shoot *s)
{
    for (int t = 0; t < s->wf_threads; t++)
        wf_lanes_give(s->wf_st ? s->wf_st[t] : NULL,
                      s->wf_run ? s->wf_run[t] : NULL);
    iris_free(s->wf_st);
    iris_free(s->wf_run);
    wf_destroy(s->wf);
    s->wf = NULL;
    s->wf_st = NULL;
    s->wf_run = NULL;
    s->wf_threads = 0;
}

/*
** The wavefront tracer for this pass, when it takes every combo and is
** not turned off (photon_options.no_wavefront, IRIS_NO_WAVEFRONT): s->wf
** and each thread's lanes, or s->wf NULL (trace.c shoots).
*/
static void wf_setup(struct shoot *s)
{
    const char *env = getenv("IRIS_NO_WAVEFRONT");
    if (s->opts->no_wavefront || (env && *env && strcmp(env, "0") != 0) ||
        s->n_combos <= 0)
        return;
    struct wf_light *L = iris_calloc((size_t)s->n_combos, sizeof *L);
    const struct ptrace_combo **tc =
        iris_calloc((size_t)s->n_combos, sizeof *tc);
    bool ok = L && tc;
    for (int i = 0; ok && i < s->n_combos; i++) {
        const struct combo *c = &s->combos[i];
        const iris_light *l = c->tc.light;
        ok = c->n1 * c->n2 == 1; /* no area-light grid */
        tc[i] = &c->tc;
        L[i] = (struct wf_light){
            .parallel = c->tc.parallel,
            .origin = c->origin,
            .axis = c->axis,
            .a = c->a,
            .b = c->b,
            .base = v3_madd(c->ctr, c->axis, -c->dist),
            .dtheta = c->dtheta,
            .jitter = s->jitter,
            .pass = s->opts->pass,
            .seed = s->opts->seed,
            .chromatic = c->tc.chromatic,
            .atten = l->kind == IRIS_LIGHT_SPOT && !l->parallel
                         ? WF_ATTEN_SPOT
                     : l->kind == IRIS_LIGHT_CYLINDER ? WF_ATTEN_CYLINDER
                                                      : WF_ATTEN_ONE,
            .beam = c->beam,
            .location = l->location,
            .spot_cr = c->spot_cr,
            .spot_cf = c->spot_cf,
            .radius = l->radius,
            .falloff = l->falloff,
        };
    }
    if (ok)
        s->wf = wf_build(s->scene, s->w, tc, L, s->n_combos, NULL);
    iris_free(L);
    iris_free(tc);
    if (!s->wf)
        return;
    int nt = s->opts->threads > 1 ? s->opts->threads : 1;
    s->wf_threads = nt;
    s->wf_st = iris_calloc((size_t)nt, sizeof *s->wf_st);
    s->wf_run = iris_calloc((size_t)nt, sizeof *s->wf_run);
    ok = s->wf_st && s->wf_run;
    for (int t = 0; ok && t < nt; t++) {
        wf_lanes_take(&s->wf_st[t], &s->wf_run[t]);
        ok = s->wf_st[t] && s->wf_run[t];
    }
    if (!ok) { /* no memory for the lanes: the scalar tracer */
        wf_teardown(s);
    }
}

static void shoot_fini(struct shoot *s, int64_t n_batches)
{
    wf_teardown(s);
    if (s->outs)
        for (int64_t b = 0; b < n_batches; b++)
            if (!s->outs[b].borrowed)
                iris_free(s->outs[b].ph);
    iris_free(s->slab);
    iris_free(s->outs);
    iris_free(s->rings);
    iris_free(s->combos);
    for (int i = 0; s->leaves && i < s->targets.n; i++)
        iris_free(s->leaves[i].o);
    iris_free(s->leaves);
    iris_free(s->targets.o);
    iris_free(s->targets.top);
}

enum iris_status pmap_concat(struct ptrace_out *outs, int64_t n,
                             struct pstore_raw **all, size_t *total)
{
    enum iris_status rc = IRIS_OK;
    size_t sum = 0;
    for (int64_t b = 0; b < n; b++) {
        if (outs[b].failed)
            rc = IRIS_ENOMEM;
        sum += outs[b].n;
    }
    struct pstore_raw *a = NULL;
    if (rc == IRIS_OK && sum > 0) {
        a = iris_malloc(sum * sizeof *a);
        if (!a)
            rc = IRIS_ENOMEM;
    }
    size_t at = 0;
    for (int64_t b = 0; b < n; b++) {
        if (a && outs[b].n)
            memcpy(a + at, outs[b].ph, outs[b].n * sizeof *a);
        at += outs[b].n;
        if (!outs[b].borrowed)
            iris_free(outs[b].ph);
        outs[b].ph = NULL;
        outs[b].borrowed = false;
    }
    *all = a;
    *total = rc == IRIS_OK ? sum : 0;
    return rc;
}

/*
** Gives the whole pages inside [from, to) back to the system, where the
** system allows it (Linux's madvise): the slab between the photons moved
** down so far and the next batch's slice holds nothing any more. Without
** it the moves would keep the pages of the slots that stored nothing
** (photons that missed) and the peak would count the photons shot, not
** those stored. Reading a released page would give zeros: nothing reads
** there before writing.
*/
static void release_pages(void *from, void *to)
{
#ifdef MADV_DONTNEED
    long pg = sysconf(_SC_PAGESIZE);
    if (pg <= 0)
        return;
    uintptr_t lo = ((uintptr_t)from + (uintptr_t)pg - 1) / (uintptr_t)pg *
                   (uintptr_t)pg;
    uintptr_t hi = (uintptr_t)to / (uintptr_t)pg * (uintptr_t)pg;
    if (hi > lo)
        (void)madvise((void *)lo, hi - lo, MADV_DONTNEED);
#else
    (void)from;
    (void)to;
#endif
}

/*
** The batches' photons in order in one array. When every batch still
** writes into its own slice of the slab (none stored more photons than
** it shot), the slices are moved down over the slab itself and the slab
** is shrunk to them: no second array, and no copy into fresh pages (that
** copy and its page faults were about 5% of the shooting, perf).
** Otherwise pmap_concat() copies them into a new array. The slab is
** consumed either way.
*/
static enum iris_status concat_batches(struct shoot *s, int64_t n_batches,
                                       struct pstore_raw **all,
                                       size_t *total)
{
    bool in_place = s->slab != NULL;
    for (int64_t b = 0; b < n_batches && in_place; b++)
        in_place = s->outs[b].borrowed && !s->outs[b].failed;
    if (!in_place) {
        enum iris_status rc = pmap_concat(s->outs, n_batches, all, total);
        iris_free(s->slab);
        s->slab = NULL;
        return rc;
    }
    size_t at = 0;
    for (int64_t b = 0; b < n_batches; b++) {
        struct ptrace_out *o = &s->outs[b];
        /* at <= b·PHOTON_BATCH·slab_per, the slice's start: a move down */
        if (o->n > 0 && o->ph != s->slab + at)
            memmove(s->slab + at, o->ph, o->n * sizeof *o->ph);
        at += o->n;
        o->ph = NULL;
        o->n = 0;
        o->borrowed = false;
        /* the next slice */
        int64_t next = (b + 1) * PHOTON_BATCH * s->slab_per;
        int64_t end = s->n_photons * s->slab_per;
        release_pages(s->slab + at, s->slab + (next < end ? next : end));
    }
    *all = NULL;
    *total = at;
    if (at == 0) {
        iris_free(s->slab);
    } else {
        /* shrinking: glibc returns a large block's tail without copying */
        struct pstore_raw *a = iris_realloc(s->slab, at * sizeof *a);
        *all = a ? a : s->slab;
    }
    s->slab = NULL;
    return IRIS_OK;
}

/* CPU seconds of the whole process (all threads), for the stats. */
static double cpu_now(void)
{
#ifdef CLOCK_PROCESS_CPUTIME_ID
    struct timespec ts;
    if (clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts) == 0)
        return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
#endif
    return 0.0;
}

/* The caustic map (see the DESIGN note at the top). */
static enum iris_status build_caustic(const iris_scene *scene,
                                      const struct pmap_world *w,
                                      const struct photon_options *opts,
                                      struct photon_map **out,
                                      struct photon_stats *stats)
{
    struct photon_stats st;
    memset(&st, 0, sizeof st);
    *out = NULL;
    const iris_photon_settings *ps = &scene->settings.photons;
    if (!ps->enabled || ps->gather_max <= 0) {
        if (stats)
            *stats = st;
        return IRIS_OK;
    }
    double t0 = par_now(), c0 = cpu_now();
    struct shoot s;
    memset(&s, 0, sizeof s);
    atomic_init(&s.n_stored, 0);
    atomic_init(&s.over_budget, false);
    atomic_init(&s.tex_cached, 0);
    s.store_cap = INFINITY;
    s.scene = scene;
    s.w = w;
    s.opts = opts;
    s.jitter = ps->jitter >= 0.0 ? ps->jitter : 0.4;
    rng r0;
    rng_seed(&r0, opts->seed, (uint64_t)opts->pass, UINT64_MAX);
    s.u0 = rng_uniform(&r0);
    enum iris_status rc = find_combos(&s);
    st.spacing = rc == IRIS_OK ? cap_spacing(&s, spacing_for(&s)) : 0.0;
    if (rc == IRIS_OK && st.spacing < 0.0)
        rc = IRIS_EINVAL; /* more photons than memory holds: reported */
    if (rc == IRIS_OK)
        rc = make_rings(&s, st.spacing);
    int64_t n_batches = (s.n_photons + PHOTON_BATCH - 1) / PHOTON_BATCH;
    if (rc == IRIS_OK && s.n_photons == 0) {
        shoot_fini(&s, 0);
        if (stats)
            *stats = st;
        return IRIS_OK; /* nothing to shoot: no map */
    }
    if (rc == IRIS_OK) {
        s.outs = iris_calloc((size_t)n_batches, sizeof *s.outs);
        if (!s.outs)
            rc = IRIS_ENOMEM;
    }
    if (rc == IRIS_OK) {
        /* One slot per photon shot, batch b's from b·PHOTON_BATCH: a
        ** caustic photon is stored at most once or twice, mostly once, so
        ** the batches write where the map will be (concat_batches). Its
        ** pages are touched only where written. Without it (too large)
        ** each batch grows its own buffer. */
        /* Under a coloured light with sibling wavelengths, one slot per
        ** sibling (sibling_records()): each path stores that many. */
        s.slab_per = (int64_t)sibling_records(&s);
        s.slab = iris_malloc((size_t)(s.n_photons * s.slab_per) *
                             sizeof *s.slab);
        for (int64_t b = 0; s.slab && b < n_batches; b++) {
            int64_t lo = b * PHOTON_BATCH;
            s.outs[b].ph = s.slab + lo * s.slab_per;
            s.outs[b].cap = (size_t)((s.n_photons - lo < PHOTON_BATCH
                                          ? s.n_photons - lo
                                          : PHOTON_BATCH) *
                                     s.slab_per);
            s.outs[b].borrowed = true;
        }
    }
    if (rc == IRIS_OK)
        wf_setup(&s);
    st.wavefront = s.wf ? s.n_photons : 0;
    if (rc == IRIS_OK)
        par_for(opts->threads, n_batches, shoot_batch, &s);
    if (rc == IRIS_OK && opts->interrupt && *opts->interrupt)
        rc = IRIS_EINTR; /* batches were skipped: no map */
    if (rc == IRIS_OK && atomic_load(&s.over_budget)) {
        const char *file;
        iris_loc loc;
        double density;
        photon_loc(&s, st.spacing, &file, &loc, &density);
        char have[32];
        fprintf(opts->log ? opts->log : stderr,
                "%s:%u:%u: error: photons: %.3g photons would store more "
                "than %.3g (they deposit more than once each), what the %s "
                "%s leaves holds; shooting stopped; raise 'spacing' or "
                "lower 'count'\n",
                file, (unsigned)loc.line, (unsigned)loc.col,
                (double)s.n_photons, s.store_cap,
                membudget_format(s.budget.bytes, have, sizeof have),
                s.budget.what);
        rc = IRIS_EINVAL; /* reported */
    }

    /* Concatenate the batches in order */
    size_t total = 0;
    struct pstore_raw *all = NULL;
    if (rc == IRIS_OK)
        rc = concat_batches(&s, n_batches, &all, &total);
    st.shot = s.n_photons;
    st.n_combos = s.n_combos;
    st.tex_cached = atomic_load(&s.tex_cached);
    shoot_fini(&s, n_batches);
    double t1 = par_now(), c1 = cpu_now();

    struct photon_map *m = NULL;
    if (rc == IRIS_OK)
        rc = pmap_from_raw(scene, all, total, opts->threads, &m);
    else
        iris_free(all);
    if (rc != IRIS_OK)
        return rc;
    pmap_caustic_setup(m, ps, opts);
    st.stored = (int64_t)m->store.n;
    st.bytes = (int64_t)pstore_bytes(&m->store);
    st.gather_radius = m->radius;
    st.seconds_shoot = t1 - t0;
    st.seconds_build = par_now() - t1;
    st.cpu_shoot = c1 - c0;
    st.cpu_build = cpu_now() - c1;
    if (stats)
        *stats = st;
    *out = m;
    return IRIS_OK;
}

void pmap_caustic_setup(struct photon_map *m, const iris_photon_settings *ps,
                        const struct photon_options *opts)
{
    m->gather_min = ps->gather_min > 0 ? ps->gather_min : 0;
    m->gather_max = ps->gather_max > PSTORE_MAX_K ? PSTORE_MAX_K
                                                  : ps->gather_max;
    m->expand_tol = ps->expand_tol;
    m->expand_min = ps->expand_min;
    m->cone_k = 1.0;
    pmap_white_matrix(m->white);
    double rmul = ps->radius_mul > 0.0 ? ps->radius_mul : 1.0;
    m->radius = ps->radius > 0.0
                    ? ps->radius
                    : pmap_auto_radius_mt(&m->store, m->gather_max,
                                          opts->threads);
    m->radius *= rmul;
    /* The progressive schedule shrinks the estimate radius, not the
    ** search radius (estimate.c) */
    m->estimate_scale = opts->radius_scale > 0.0 ? opts->radius_scale : 1.0;
}

/*
** The caustic map and, with radiosity{}, the global map (global.c), which
** hangs off the caustic one (an empty caustic map when the scene has no
** photons{} block).
*/
enum iris_status pmap_from_raw(const iris_scene *scene,
                               struct pstore_raw *all, size_t n, int threads,
                               struct photon_map **out)
{
    struct photon_map *m = iris_calloc(1, sizeof *m);
    enum iris_status rc = m ? IRIS_OK : IRIS_ENOMEM;
    if (rc == IRIS_OK) /* media photons to a map of their own */
        rc = pmedia_take(scene, all, &n, threads, &m->media);
    if (rc == IRIS_OK)
        rc = pstore_build_in_place(&m->store, all, n, threads);
    else
        iris_free(all);
    if (rc != IRIS_OK) {
        photon_map_destroy(m);
        return rc;
    }
    m->scene = scene;
    *out = m;
    return IRIS_OK;
}

enum iris_status pmap_build(const iris_scene *scene, const struct pmap_world *w,
                            const struct photon_options *opts,
                            struct photon_map **out,
                            struct photon_stats *stats)
{
    struct photon_stats st;
    memset(&st, 0, sizeof st);
    struct photon_map *m = NULL, *g = NULL;
    enum iris_status rc = build_caustic(scene, w, opts, &m, &st);
    if (rc == IRIS_OK)
        rc = pmap_build_global(scene, w, opts, &g, &st);
    if (rc == IRIS_OK && g && !m) {
        m = iris_calloc(1, sizeof *m);
        if (!m)
            rc = IRIS_ENOMEM;
        else
            m->scene = scene;
    }
    if (rc != IRIS_OK) {
        photon_map_destroy(g);
        photon_map_destroy(m);
        *out = NULL;
        return rc;
    }
    if (m)
        m->global = g;
    if (stats)
        *stats = st;
    *out = m;
    return IRIS_OK;
}
