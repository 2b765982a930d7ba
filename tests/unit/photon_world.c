/* SPDX-License-Identifier: MIT */
/*
** photon_world.c: the analytic test double of photon_world.h.
*/
#include "config.h"

#include "photon_world.h"

#include <math.h>
#include <string.h>

void tw_init(struct tw_scene *t, double spacing, int gather_max)
{
    memset(t, 0, sizeof *t);
    iris_scene *s = &t->scene;
    s->objects = t->objs;
    s->lights = t->lights;
    s->version = 3.7;
    s->settings.max_trace_level = 5;
    s->settings.adc_bailout = 1.0 / 255.0;
    iris_photon_settings *p = &s->settings.photons;
    p->enabled = true;
    p->spacing = spacing;
    p->gather_min = 20;
    p->gather_max = gather_max;
    p->radius = -1;
    p->radius_mul = 1;
    p->jitter = 0.4;
    p->max_trace_level = -1;
    p->adc_bailout = -1;
    p->autostop = 0.5;
    p->expand_tol = 0.2;
    p->expand_min = 35;
}

/* Material slot k: POV-Ray's finish defaults with 'diffuse', solid colour
** 'col', an interior when ior > 0. */
static iris_object *new_object(struct tw_scene *t, enum iris_object_kind kind,
                               iris_colour col, double diffuse, double ior)
{
    int k = t->scene.n_objects++;
    iris_object *o = &t->obj_store[k];
    t->objs[k] = o;
    o->kind = kind;
    o->photon_collect = true;
    o->photon_density = 1;
    o->split_union = true;
    iris_finish *f = &t->fin[k];
    iris_finish_defaults(f);
    f->ambient = (iris_colour){0, 0, 0, 0, 0};
    f->diffuse = diffuse;
    t->pig[k].colour = col;
    t->tex[k].pigment = &t->pig[k];
    t->tex[k].finish = f;
    o->texture = &t->tex[k];
    if (ior > 0) {
        iris_interior *in = &t->inter[k];
        in->ior = ior;
        in->dispersion = 1;
        in->dispersion_samples = 7;
        o->interior = in;
    }
    return o;
}

iris_object *tw_sphere(struct tw_scene *t, vec3 c, double r, iris_colour col,
                       double diffuse, double ior)
{
    iris_object *o = new_object(t, IRIS_OBJ_SPHERE, col, diffuse, ior);
    o->u.sphere.centre = c;
    o->u.sphere.radius = r;
    return o;
}

iris_object *tw_plane(struct tw_scene *t, vec3 n, double d, iris_colour col,
                      double diffuse)
{
    iris_object *o = new_object(t, IRIS_OBJ_PLANE, col, diffuse, 0);
    o->u.plane.normal = n;
    o->u.plane.distance = d;
    return o;
}

iris_object *tw_box(struct tw_scene *t, vec3 lo, vec3 hi, iris_colour col,
                    double diffuse, double ior)
{
    iris_object *o = new_object(t, IRIS_OBJ_BOX, col, diffuse, ior);
    o->u.box.lo = lo;
    o->u.box.hi = hi;
    return o;
}

iris_object *tw_convex(struct tw_scene *t, int n, const vec3 *normals,
                       const double *d, iris_colour col, double ior)
{
    int k = t->scene.n_objects;
    iris_object *o = new_object(t, IRIS_OBJ_INTERSECTION, col, 0, ior);
    o->u.csg.n_children = n;
    o->u.csg.children = t->children[k];
    for (int i = 0; i < n && i < 8; i++) {
        iris_object *c = &t->child_store[k][i];
        c->kind = IRIS_OBJ_PLANE;
        c->u.plane.normal = v3_norm(normals[i]);
        c->u.plane.distance = d[i];
        t->children[k][i] = c;
    }
    return o;
}

iris_light *tw_light(struct tw_scene *t, vec3 location, vec3 point_at,
                     bool parallel)
{
    int k = t->scene.n_lights++;
    iris_light *l = &t->light_store[k];
    t->lights[k] = l;
    l->kind = IRIS_LIGHT_POINT;
    l->location = location;
    l->point_at = point_at;
    l->parallel = parallel;
    l->colour.r = l->colour.g = l->colour.b = 1;
    l->radius = 30;
    l->falloff = 45;
    l->photon_refraction = IRIS_ON;
    l->spectrum = IRIS_SPEC_D65;
    return l;
}

/* ---- intersection ---- */

/* Entry and exit of the ray in the convex set of half-spaces; normals
** of the entry and exit planes. false when the ray misses it. */
static bool convex_span(const iris_object *const *planes, int n, const ray *r,
                        double *t0, double *t1, vec3 *n0, vec3 *n1)
{
    *t0 = -INFINITY;
    *t1 = INFINITY;
    for (int i = 0; i < n; i++) {
        vec3 nn = planes[i]->u.plane.normal;
        double dn = v3_dot(nn, r->d);
        double s = planes[i]->u.plane.distance - v3_dot(nn, r->o);
        if (fabs(dn) < 1e-15) {
            if (s < 0)
                return false;
            continue;
        }
        double t = s / dn;
        if (dn < 0) {
            if (t > *t0) {
                *t0 = t;
                *n0 = nn;
            }
        } else if (t < *t1) {
            *t1 = t;
            *n1 = nn;
        }
    }
    return *t0 <= *t1;
}

static bool hit_object(const iris_object *o, const ray *r, double tmin,
                       double *t, vec3 *n)
{
    switch (o->kind) {
    case IRIS_OBJ_SPHERE: {
        vec3 oc = v3_sub(r->o, o->u.sphere.centre);
        double b = v3_dot(oc, r->d);
        double c = v3_dot(oc, oc) - o->u.sphere.radius * o->u.sphere.radius;
        double disc = b * b - c;
        if (disc < 0)
            return false;
        double sq = sqrt(disc);
        double tt = -b - sq;
        if (tt <= tmin)
            tt = -b + sq;
        if (tt <= tmin)
            return false;
        *t = tt;
        *n = v3_norm(v3_sub(v3_madd(r->o, r->d, tt), o->u.sphere.centre));
        return true;
    }
    case IRIS_OBJ_PLANE: {
        double dn = v3_dot(o->u.plane.normal, r->d);
        if (fabs(dn) < 1e-15)
            return false;
        double tt = (o->u.plane.distance - v3_dot(o->u.plane.normal, r->o)) /
                    dn;
        if (tt <= tmin)
            return false;
        *t = tt;
        *n = o->u.plane.normal;
        return true;
    }
    case IRIS_OBJ_BOX: {
        double t0 = -INFINITY, t1 = INFINITY;
        int a0 = 0, a1 = 0;
        double s0 = 1, s1 = 1;
        for (int a = 0; a < 3; a++) {
            double oa = v3_comp(r->o, a), da = v3_comp(r->d, a);
            double lo = v3_comp(o->u.box.lo, a), hi = v3_comp(o->u.box.hi, a);
            if (fabs(da) < 1e-15) {
                if (oa < lo || oa > hi)
                    return false;
                continue;
            }
            double ta = (lo - oa) / da, tb = (hi - oa) / da;
            double sa = -1, sb = 1;
            if (ta > tb) {
                double x = ta;
                ta = tb;
                tb = x;
                sa = 1;
                sb = -1;
            }
            if (ta > t0) {
                t0 = ta;
                a0 = a;
                s0 = sa;
            }
            if (tb < t1) {
                t1 = tb;
                a1 = a;
                s1 = sb;
            }
        }
        if (t0 > t1)
            return false;
        int axis;
        double sign;
        if (t0 > tmin) {
            *t = t0;
            axis = a0;
            sign = s0;
        } else if (t1 > tmin) {
            *t = t1;
            axis = a1;
            sign = s1;
        } else {
            return false;
        }
        *n = v3(axis == 0 ? sign : 0, axis == 1 ? sign : 0,
                axis == 2 ? sign : 0);
        return true;
    }
    case IRIS_OBJ_INTERSECTION: {
        double t0, t1;
        vec3 n0 = v3(0, 0, 0), n1 = v3(0, 0, 0);
        if (!convex_span((const iris_object *const *)o->u.csg.children,
                         o->u.csg.n_children, r, &t0, &t1, &n0, &n1))
            return false;
        if (t0 > tmin) {
            *t = t0;
            *n = n0;
        } else if (t1 > tmin) {
            *t = t1;
            *n = n1;
        } else {
            return false;
        }
        return true;
    }
    default:
        return false;
    }
}

static bool tw_intersect(const void *ctx, const ray *r, double tmin,
                         double tmax, unsigned skip, struct hit *h)
{
    const iris_scene *s = ctx;
    bool found = false;
    for (int i = 0; i < s->n_objects; i++) {
        const iris_object *o = s->objects[i];
        if ((skip & ACCEL_SKIP_NO_SHADOW) && o->no_shadow)
            continue;
        if ((skip & ACCEL_SKIP_NO_IMAGE) && o->no_image)
            continue;
        double t;
        vec3 n;
        if (hit_object(o, r, tmin, &t, &n) && t < tmax) {
            tmax = t;
            found = true;
            h->t = t;
            h->p = v3_madd(r->o, r->d, t);
            h->n = n;
            h->shading_n = n;
            h->obj = o;
            h->top = o;
            h->texture = o->texture;
            h->interior = o->interior;
        }
    }
    return found;
}

static bool tw_bounds(const void *ctx, const iris_object *o, vec3 *lo,
                      vec3 *hi)
{
    (void)ctx;
    switch (o->kind) {
    case IRIS_OBJ_SPHERE: {
        double r = o->u.sphere.radius;
        *lo = v3_sub(o->u.sphere.centre, v3(r, r, r));
        *hi = v3_add(o->u.sphere.centre, v3(r, r, r));
        return true;
    }
    case IRIS_OBJ_BOX:
        *lo = o->u.box.lo;
        *hi = o->u.box.hi;
        return true;
    case IRIS_OBJ_INTERSECTION:
        /* the tests give convex solids inside |x|,|y|,|z| <= 1.5 of 0 */
        *lo = v3(-1.5, -1.5, -1.5);
        *hi = v3(1.5, 1.5, 1.5);
        return true;
    default:
        return false;
    }
}

static bool tw_inside(const void *ctx, const iris_object *o, vec3 p)
{
    (void)ctx;
    switch (o->kind) {
    case IRIS_OBJ_SPHERE:
        return v3_len(v3_sub(p, o->u.sphere.centre)) < o->u.sphere.radius;
    case IRIS_OBJ_BOX:
        return p.x > o->u.box.lo.x && p.x < o->u.box.hi.x &&
               p.y > o->u.box.lo.y && p.y < o->u.box.hi.y &&
               p.z > o->u.box.lo.z && p.z < o->u.box.hi.z;
    case IRIS_OBJ_PLANE:
        return v3_dot(o->u.plane.normal, p) < o->u.plane.distance;
    default:
        return false;
    }
}

struct pmap_world tw_world(struct tw_scene *t)
{
    struct pmap_world w = { &t->scene, tw_intersect, tw_bounds, tw_inside,
                            1e-9 };
    return w;
}

void tw_floor_mean(const struct photon_map *m, double out[3])
{
    static iris_finish fin;
    fin.diffuse = 1;
    fin.brilliance = 1;
    const int n = 24;
    out[0] = out[1] = out[2] = 0;
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) {
            vec3 p = v3(-0.8 + 1.6 * (i + 0.5) / n, 0,
                        -0.8 + 1.6 * (j + 0.5) / n);
            struct photon_shade_input in = { p, v3(0, 1, 0), v3(0, 1, 0),
                                             v3(0, -1, 0), { 1, 1, 1 }, 1.0,
                                             &fin, NULL };
            double rgb[3];
            photon_map_shade(m, &in, rgb);
            for (int c = 0; c < 3; c++)
                out[c] += rgb[c] / (n * n);
        }
}

void tw_chroma_stats(const double (*pt)[3], int n, double mean[3],
                     double *chroma_rms)
{
    double cr = 0, cb = 0;
    mean[0] = mean[1] = mean[2] = 0;
    for (int i = 0; i < n; i++) {
        double s = pt[i][0] + pt[i][1] + pt[i][2];
        cr += pt[i][0] / s / n;
        cb += pt[i][2] / s / n;
        for (int c = 0; c < 3; c++)
            mean[c] += pt[i][c] / n;
    }
    double v = 0;
    for (int i = 0; i < n; i++) {
        double s = pt[i][0] + pt[i][1] + pt[i][2];
        double dr = pt[i][0] / s - cr, db = pt[i][2] / s - cb;
        v += (dr * dr + db * db) / n;
    }
    *chroma_rms = sqrt(v);
}
