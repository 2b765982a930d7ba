/* SPDX-License-Identifier: MIT */
/*
** dump.c: iris_scene_dump(), a stable, readable text form of a scene for
** the parse tests. Numbers are printed with 6 significant digits and -0
** as 0, so the output does not depend on rounding noise. Only values that
** differ from the defaults are printed for finishes and flags.
*/
#include "config.h"

#include <math.h>
#include <string.h>

#include "iris/fn.h"
#include "iris/parse.h"

static double z0(double v)
{
    if (fabs(v) < 5e-13)
        return 0;
    return v;
}

static void vec(FILE *o, iris_vec3 v)
{
    fprintf(o, "<%.6g, %.6g, %.6g>", z0(v.x), z0(v.y), z0(v.z));
}

static void col(FILE *o, iris_colour c)
{
    fprintf(o, "rgbft <%.6g, %.6g, %.6g, %.6g, %.6g>", z0(c.r), z0(c.g),
            z0(c.b), z0(c.f), z0(c.t));
}

static void ind(FILE *o, int d)
{
    for (int i = 0; i < d; i++)
        fputs("  ", o);
}

static bool is_identity(const iris_transform *t)
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++)
            if (fabs(t->m[i][j] - (i == j ? 1 : 0)) > 1e-12)
                return false;
    return true;
}

/* File names without their directory: the dump must not depend on where
** the include files are installed. */
static const char *base(const char *p)
{
    const char *s = p ? strrchr(p, '/') : NULL;
    return s ? s + 1 : p ? p : "";
}

static void xform(FILE *o, int d, const char *name, const iris_transform *t)
{
    if (is_identity(t))
        return;
    ind(o, d);
    fprintf(o, "%s [", name);
    for (int i = 0; i < 3; i++)
        fprintf(o, "%s%.6g %.6g %.6g %.6g", i ? "; " : "", z0(t->m[i][0]),
                z0(t->m[i][1]), z0(t->m[i][2]), z0(t->m[i][3]));
    fputs("]\n", o);
}

static const char *pattern_name(int k)
{
    static const char *const n[IRIS_PAT_COUNT] = {
        "solid", "agate", "average", "boxed", "bozo", "brick", "bumps",
        "cells", "checker", "crackle", "cylindrical", "dents", "function",
        "gradient", "granite", "hexagon", "image_map", "image_pattern",
        "julia", "leopard", "mandel", "marble", "onion", "planar", "quilted",
        "radial", "ripples", "slope", "spherical", "spiral1", "spiral2",
        "spotted", "waves", "wood", "wrinkles", "object", "tiling",
        "pavement", "square", "triangular", "facets", "density_file",
        "face_blend", "cubic",
    };
    return k >= 0 && k < IRIS_PAT_COUNT ? n[k] : "?";
}

static void pattern(FILE *o, int d, const iris_pattern *p)
{
    if (p->kind == IRIS_PAT_GRADIENT || p->kind == IRIS_PAT_SLOPE) {
        ind(o, d);
        fputs("vector ", o);
        vec(o, p->vector);
        fputc('\n', o);
    }
    if (p->wave != IRIS_WAVE_RAMP || p->frequency != 1 || p->phase != 0) {
        ind(o, d);
        fprintf(o, "wave %d frequency %.6g phase %.6g\n", (int)p->wave,
                p->frequency, p->phase);
    }
    for (int i = 0; i < p->n_warps; i++) {
        const iris_warp *w = &p->warps[i];
        ind(o, d);
        fprintf(o, "warp %d turbulence ", (int)w->kind);
        vec(o, w->turbulence);
        fprintf(o, " octaves %d omega %.6g lambda %.6g\n", w->octaves,
                w->omega, w->lambda);
    }
    if (p->image) {
        ind(o, d);
        fprintf(o, "image \"%s\" map_type %d interpolate %d%s\n",
                base(p->image->path), p->image->map_type, p->image->interpolate,
                p->image->once ? " once" : "");
    }
    if (p->fn) {
        ind(o, d);
        fprintf(o, "function (%d insns)\n", p->fn->n_code);
    }
    xform(o, d, "transform", &p->transform);
}

static void pigment(FILE *o, int d, const iris_pigment *p);

/*
** Pigments and textures a dump still shows. Objects share declared map
** trees, each up to IRIS_MAX_MAP_TREE pigments, and the dump writes a
** tree out for each: past this many the rest are elided, so that a dump
** (the fuzz targets write one for every input) stays short.
*/
#define DUMP_MAX_NODES 100000
static _Thread_local unsigned long nodes_left;

/* false (and a line saying so) once the dump has shown its share */
static bool node_shown(FILE *o, int d, const char *what)
{
    if (nodes_left == 0) {
        ind(o, d);
        fprintf(o, "%s (not shown: past %d in this dump)\n", what,
                DUMP_MAX_NODES);
        return false;
    }
    nodes_left--;
    return true;
}

static void entries(FILE *o, int d, const iris_map_entry *e, int n, int what)
{
    for (int i = 0; i < n; i++) {
        ind(o, d);
        fprintf(o, "[%.6g] ", z0(e[i].value));
        if (what == 0) {
            col(o, e[i].colour);
            fputc('\n', o);
        } else if (what == 1) {
            fputs("pigment\n", o);
            if (e[i].pigment)
                pigment(o, d + 1, e[i].pigment);
        } else if (what == 2) {
            fprintf(o, "normal\n");
        } else if (what == 3) {
            fprintf(o, "texture\n");
        } else {
            fprintf(o, "slope %.6g height %.6g\n", e[i].slope, e[i].height);
        }
    }
}

static void pigment(FILE *o, int d, const iris_pigment *p)
{
    if (!node_shown(o, d, "pigment"))
        return;
    ind(o, d);
    fprintf(o, "pigment %s", pattern_name(p->pattern.kind));
    if (p->pattern.kind == IRIS_PAT_NONE) {
        fputc(' ', o);
        col(o, p->colour);
    }
    fputc('\n', o);
    if (p->pattern.kind != IRIS_PAT_NONE)
        pattern(o, d + 1, &p->pattern);
    if (p->entry_xf)
        xform(o, d + 1, "entry transform", p->entry_xf);
    entries(o, d + 1, p->entries, p->n_entries, p->is_pigment_map ? 1 : 0);
}

static void finish(FILE *o, int d, const iris_finish *f)
{
    iris_finish def;
    iris_finish_defaults(&def);
    ind(o, d);
    fputs("finish", o);
#define F(field, name) \
    if (f->field != def.field) fprintf(o, " " name " %.6g", f->field)
    if (memcmp(&f->ambient, &def.ambient, sizeof def.ambient)) {
        fputs(" ambient ", o);
        col(o, f->ambient);
    }
    if (memcmp(&f->emission, &def.emission, sizeof def.emission)) {
        fputs(" emission ", o);
        col(o, f->emission);
    }
    F(diffuse, "diffuse");
    F(diffuse_back, "diffuse_back");
    F(brilliance, "brilliance");
    F(phong, "phong");
    F(phong_size, "phong_size");
    F(specular, "specular");
    F(roughness, "roughness");
    F(metallic, "metallic");
    F(reflection_falloff, "reflection_falloff");
    F(reflection_exponent, "reflection_exponent");
    F(reflection_metallic, "reflection_metallic");
    F(crand, "crand");
    F(irid, "irid");
    F(legacy_ior, "ior");
#undef F
    if (memcmp(&f->reflection_max, &def.reflection_max, sizeof def.reflection_max) ||
        memcmp(&f->reflection_min, &def.reflection_min, sizeof def.reflection_min)) {
        fputs(" reflection ", o);
        col(o, f->reflection_min);
        fputs(" .. ", o);
        col(o, f->reflection_max);
    }
    if (f->reflection_fresnel)
        fputs(" fresnel", o);
    if (f->conserve_energy)
        fputs(" conserve_energy", o);
    fputc('\n', o);
}

static void texture(FILE *o, int d, const iris_texture *t)
{
    int layer = 0;
    for (; t; t = t->next, layer++) {
        if (!node_shown(o, d, "texture"))
            return;
        ind(o, d);
        fprintf(o, "texture layer %d", layer);
        if (t->n_entries)
            fprintf(o, " map %s (%d entries)", pattern_name(t->map_pattern.kind),
                    t->n_entries);
        fputc('\n', o);
        if (t->n_entries) {
            pattern(o, d + 1, &t->map_pattern);
            for (int i = 0; i < t->n_entries; i++) {
                ind(o, d + 1);
                fprintf(o, "[%.6g]\n", z0(t->entries[i].value));
                if (t->entries[i].texture)
                    texture(o, d + 2, t->entries[i].texture);
            }
            continue;
        }
        if (t->pigment)
            pigment(o, d + 1, t->pigment);
        if (t->normal) {
            ind(o, d + 1);
            fprintf(o, "normal %s amount %.6g\n",
                    t->normal->bump_map ? "bump_map"
                                        : pattern_name(t->normal->pattern.kind),
                    t->normal->amount);
            pattern(o, d + 2, &t->normal->pattern);
            if (t->normal->entry_xf)
                xform(o, d + 2, "entry transform", t->normal->entry_xf);
            entries(o, d + 2, t->normal->entries, t->normal->n_entries,
                    t->normal->is_slope_map ? 4 : 2);
        }
        if (t->finish)
            finish(o, d + 1, t->finish);
    }
}

static const char *object_name(int k)
{
    static const char *const n[IRIS_OBJ_KIND_COUNT] = {
        "sphere", "box", "plane", "cylinder", "cone", "torus", "disc",
        "triangle", "mesh", "polygon", "prism", "lathe", "sor",
        "superellipsoid", "blob", "height_field", "text", "isosurface",
        "quadric", "poly", "julia_fractal", "bicubic_patch", "parametric",
        "sphere_sweep", "ovus", "lemon", "union", "merge", "intersection",
        "difference", "light_group",
    };
    return k >= 0 && k < IRIS_OBJ_KIND_COUNT ? n[k] : "?";
}

static void object(FILE *o, int d, const iris_object *ob,
                   const iris_texture *parent_tex)
{
    ind(o, d);
    fprintf(o, "%s @%u:%u", object_name(ob->kind), ob->loc.line, ob->loc.col);
    const struct { bool v; const char *n; } flags[] = {
        { ob->inverse, "inverse" }, { ob->hollow, "hollow" },
        { ob->no_shadow, "no_shadow" }, { ob->no_image, "no_image" },
        { ob->no_reflection, "no_reflection" },
        { ob->double_illuminate, "double_illuminate" },
        { ob->sturm, "sturm" }, { ob->open, "open" },
        { ob->photon_target, "photon_target" },
        { !ob->photon_collect, "photon_collect_off" },
        { ob->photon_pass_through, "photon_pass_through" },
        { ob->photon_refraction == IRIS_ON, "photon_refraction_on" },
        { ob->photon_refraction == IRIS_OFF, "photon_refraction_off" },
        { ob->photon_reflection == IRIS_ON, "photon_reflection_on" },
        { ob->photon_reflection == IRIS_OFF, "photon_reflection_off" },
        { ob->no_global_lights, "no_global_lights" },
    };
    for (size_t i = 0; i < sizeof flags / sizeof flags[0]; i++)
        if (flags[i].v)
            fprintf(o, " %s", flags[i].n);
    if (ob->light_group_count > 0)
        fprintf(o, " group_lights %d+%d", ob->light_group_first,
                ob->light_group_count);
    fputc('\n', o);
    ind(o, d + 1);
    switch (ob->kind) {
    case IRIS_OBJ_SPHERE:
        fputs("centre ", o); vec(o, ob->u.sphere.centre);
        fprintf(o, " radius %.6g\n", ob->u.sphere.radius);
        break;
    case IRIS_OBJ_BOX:
        fputs("corners ", o); vec(o, ob->u.box.lo); fputc(' ', o);
        vec(o, ob->u.box.hi); fputc('\n', o);
        break;
    case IRIS_OBJ_PLANE:
        fputs("normal ", o); vec(o, ob->u.plane.normal);
        fprintf(o, " distance %.6g\n", ob->u.plane.distance);
        break;
    case IRIS_OBJ_CYLINDER:
        fputs("base ", o); vec(o, ob->u.cylinder.base);
        fputs(" cap ", o); vec(o, ob->u.cylinder.cap);
        fprintf(o, " radius %.6g\n", ob->u.cylinder.radius);
        break;
    case IRIS_OBJ_CONE:
        fputs("base ", o); vec(o, ob->u.cone.base);
        fprintf(o, " %.6g cap ", ob->u.cone.base_radius);
        vec(o, ob->u.cone.cap);
        fprintf(o, " %.6g\n", ob->u.cone.cap_radius);
        break;
    case IRIS_OBJ_TORUS:
        fprintf(o, "major %.6g minor %.6g\n", ob->u.torus.major,
                ob->u.torus.minor);
        break;
    case IRIS_OBJ_DISC:
        fputs("centre ", o); vec(o, ob->u.disc.centre);
        fputs(" normal ", o); vec(o, ob->u.disc.normal);
        fprintf(o, " radius %.6g hole %.6g\n", ob->u.disc.radius,
                ob->u.disc.hole_radius);
        break;
    case IRIS_OBJ_TRIANGLE:
        fprintf(o, "%s", ob->u.triangle.smooth ? "smooth " : "");
        for (int i = 0; i < 3; i++) {
            vec(o, ob->u.triangle.p[i]);
            fputc(' ', o);
        }
        fputc('\n', o);
        break;
    case IRIS_OBJ_MESH:
        fprintf(o, "vertices %d normals %d uvs %d triangles %d textures %d\n",
                ob->u.mesh.n_vertices, ob->u.mesh.n_normals, ob->u.mesh.n_uvs,
                ob->u.mesh.n_triangles, ob->u.mesh.n_textures);
        if (ob->u.mesh.tri_texture && ob->u.mesh.n_triangles > 0) {
            /* each face's texture_list index (the first 16) */
            fprintf(o, "  face textures");
            for (int i = 0; i < ob->u.mesh.n_triangles && i < 16; i++)
                fprintf(o, " %d", (int)ob->u.mesh.tri_texture[i]);
            fputc('\n', o);
        }
        break;
    case IRIS_OBJ_POLYGON:
        fprintf(o, "points %d\n", ob->u.polygon.n_points);
        break;
    case IRIS_OBJ_PRISM:
        fprintf(o, "spline %d sweep %d heights %.6g %.6g points %d\n",
                (int)ob->u.prism.spline, ob->u.prism.sweep,
                ob->u.prism.height1, ob->u.prism.height2,
                ob->u.prism.n_points);
        break;
    case IRIS_OBJ_LATHE: case IRIS_OBJ_SOR:
        fprintf(o, "spline %d points %d\n", (int)ob->u.lathe.spline,
                ob->u.lathe.n_points);
        break;
    case IRIS_OBJ_SUPERELLIPSOID:
        fprintf(o, "e %.6g n %.6g\n", ob->u.superellipsoid.e,
                ob->u.superellipsoid.n);
        break;
    case IRIS_OBJ_BLOB:
        fprintf(o, "threshold %.6g components %d\n", ob->u.blob.threshold,
                ob->u.blob.n_components);
        break;
    case IRIS_OBJ_HEIGHT_FIELD:
        fprintf(o, "%s%s water_level %.6g\n",
                ob->u.height_field.fn ? "function" : "image",
                ob->u.height_field.smooth ? " smooth" : "",
                ob->u.height_field.water_level);
        break;
    case IRIS_OBJ_TEXT:
        fprintf(o, "font \"%s\" string \"%s\" thickness %.6g offset ",
                base(ob->u.text.font), ob->u.text.string,
                ob->u.text.thickness);
        vec(o, ob->u.text.offset);
        fputc('\n', o);
        break;
    case IRIS_OBJ_ISOSURFACE:
        fprintf(o, "function (%d insns) threshold %.6g max_gradient %.6g "
                "contained_by %s\n",
                ob->u.isosurface.fn ? ob->u.isosurface.fn->n_code : 0,
                ob->u.isosurface.threshold, ob->u.isosurface.max_gradient,
                ob->u.isosurface.contained_kind ? "sphere" : "box");
        break;
    case IRIS_OBJ_QUADRIC: case IRIS_OBJ_POLY:
        fprintf(o, "order %d coefficients %d\n", ob->u.poly.order,
                ob->u.poly.n_coeffs);
        break;
    case IRIS_OBJ_UNION: case IRIS_OBJ_MERGE: case IRIS_OBJ_INTERSECTION:
    case IRIS_OBJ_DIFFERENCE: case IRIS_OBJ_LIGHT_GROUP:
        fprintf(o, "children %d\n", ob->u.csg.n_children);
        break;
    case IRIS_OBJ_JULIA_FRACTAL:
        fprintf(o, "c <%.6g, %.6g, %.6g, %.6g> type %d fn %d iterations %d "
                "precision %.6g slice <%.6g, %.6g, %.6g, %.6g> %.6g",
                ob->u.julia.data[0], ob->u.julia.data[1],
                ob->u.julia.data[2], ob->u.julia.data[3], ob->u.julia.type,
                ob->u.julia.fn, ob->u.julia.iterations,
                ob->u.julia.precision, ob->u.julia.slice.x,
                ob->u.julia.slice.y, ob->u.julia.slice.z,
                ob->u.julia.data[5], ob->u.julia.distance);
        if (ob->u.julia.fn == IRIS_JULIA_PWR)
            fprintf(o, " pwr <%.6g, %.6g>", ob->u.julia.data[6],
                    ob->u.julia.data[7]);
        fputc('\n', o);
        break;
    case IRIS_OBJ_BICUBIC_PATCH:
        fprintf(o, "type %d flatness %.6g steps %d %d last ",
                ob->u.bicubic.type, ob->u.bicubic.flatness,
                ob->u.bicubic.u_steps, ob->u.bicubic.v_steps);
        vec(o, ob->u.bicubic.points[15]);
        fputc('\n', o);
        break;
    case IRIS_OBJ_SPHERE_SWEEP:
        fprintf(o, "spline %d spheres %d\n", ob->u.sphere_sweep.spline,
                ob->u.sphere_sweep.n_spheres);
        break;
    case IRIS_OBJ_OVUS:
        fprintf(o, "r1 %.6g r2 %.6g\n", ob->u.ovus.r1, ob->u.ovus.r2);
        break;
    default:
        fputs("(parameters not shown)\n", o);
        break;
    }
    if (ob->has_transform)
        xform(o, d + 1, "transform", &ob->transform);
    if (ob->texture && ob->texture != parent_tex)
        texture(o, d + 1, ob->texture);
    if (ob->interior) {
        const iris_interior *in = ob->interior;
        ind(o, d + 1);
        fprintf(o, "interior ior %.6g dispersion %.6g samples %d caustics "
                "%.6g fade %.6g %.6g%s", in->ior, in->dispersion,
                in->dispersion_samples, in->caustics, in->fade_distance,
                in->fade_power, in->has_media ? " media" : "");
        if (in->spectral_ior) {
            const iris_ior_spec *s = in->spectral_ior;
            fprintf(o, " spectral model %d", (int)s->model);
            if (s->glass_name)
                fprintf(o, " glass \"%s\"", s->glass_name);
            if (s->model == IRIS_IOR_SELLMEIER && !s->glass_name)
                fprintf(o, " B %.6g %.6g %.6g C %.6g %.6g %.6g", s->b[0],
                        s->b[1], s->b[2], s->c[0], s->c[1], s->c[2]);
            if (s->model == IRIS_IOR_CAUCHY)
                fprintf(o, " A %.6g B %.6g", s->cauchy_a, s->cauchy_b);
            if (s->model == IRIS_IOR_ABBE)
                fprintf(o, " nd %.6g Vd %.6g", s->abbe_nd, s->abbe_vd);
            if (s->model == IRIS_IOR_DECAY)
                fprintf(o, " n1 %.6g n2 %.6g spread %.6g", s->decay_n1,
                        s->decay_n2, s->decay_spread);
        }
        fputc('\n', o);
    }
    for (int i = 0; i < ob->n_clipped_by; i++) {
        ind(o, d + 1);
        fputs("clipped_by\n", o);
        object(o, d + 2, ob->clipped_by[i], ob->texture);
    }
    if (ob->kind >= IRIS_OBJ_UNION)
        for (int i = 0; i < ob->u.csg.n_children; i++)
            object(o, d + 1, ob->u.csg.children[i], NULL);
}

static void light(FILE *o, const iris_light *l)
{
    static const char *const kinds[] = { "point", "spotlight", "cylinder" };
    fprintf(o, "light %s @%u:%u at ", kinds[l->kind], l->loc.line, l->loc.col);
    vec(o, l->location);
    fputc(' ', o);
    col(o, l->colour);
    fputc('\n', o);
    if (l->kind != IRIS_LIGHT_POINT || l->parallel) {
        fputs("  point_at ", o);
        vec(o, l->point_at);
        fprintf(o, " radius %.6g falloff %.6g tightness %.6g%s\n", l->radius,
                l->falloff, l->tightness, l->parallel ? " parallel" : "");
    }
    if (l->area) {
        fputs("  area_light ", o);
        vec(o, l->axis1);
        fputc(' ', o);
        vec(o, l->axis2);
        fprintf(o, " %d %d adaptive %d%s%s%s\n", l->size1, l->size2,
                l->adaptive, l->jitter ? " jitter" : "",
                l->circular ? " circular" : "", l->orient ? " orient" : "");
    }
    if (l->shadowless || l->fade_power > 0 || l->spectrum != IRIS_SPEC_D65 ||
        l->looks_like || l->photon_refraction || l->photon_reflection)
        fprintf(o, "  %s%sfade %.6g %.6g spectrum %d %.6g photons %d %d%s\n",
                l->shadowless ? "shadowless " : "",
                l->looks_like ? "looks_like " : "", l->fade_distance,
                l->fade_power, (int)l->spectrum, l->blackbody_kelvin,
                (int)l->photon_refraction, (int)l->photon_reflection,
                l->photon_area_light ? " area" : "");
}

void iris_scene_dump(const iris_scene *s, FILE *o)
{
    static const char *const cams[] = { "perspective", "orthographic",
        "fisheye", "panoramic", "ultra_wide_angle", "omnimax", "cylinder",
        "spherical", "mesh_camera" };
    nodes_left = DUMP_MAX_NODES;
    fprintf(o, "version %.6g\n", s->version);
    const iris_camera *c = &s->camera;
    fprintf(o, "camera %s%s\n", cams[c->kind], s->has_camera ? "" : " (default)");
    fputs("  location ", o); vec(o, c->location); fputc('\n', o);
    fputs("  direction ", o); vec(o, c->direction); fputc('\n', o);
    fputs("  right ", o); vec(o, c->right); fputc('\n', o);
    fputs("  up ", o); vec(o, c->up); fputc('\n', o);
    if (c->angle > 0)
        fprintf(o, "  angle %.6g\n", c->angle);
    if (c->v_angle > 0)
        fprintf(o, "  vertical angle %.6g\n", c->v_angle);
    if (c->aperture > 0)
        fprintf(o, "  aperture %.6g blur_samples %d\n", c->aperture,
                c->blur_samples);
    const iris_global_settings *g = &s->settings;
    fprintf(o, "settings assumed_gamma %.6g max_trace_level %d adc_bailout "
            "%.6g ambient_light ", g->assumed_gamma, g->max_trace_level,
            g->adc_bailout);
    col(o, g->ambient_light);
    fprintf(o, "%s\n", g->radiosity ? " radiosity" : "");
    if (g->photons.enabled)
        fprintf(o, "photons spacing %.6g count %d gather %d %d radius %.6g "
                "jitter %.6g autostop %.6g expand %.6g %d\n",
                g->photons.spacing, g->photons.count, g->photons.gather_min,
                g->photons.gather_max, g->photons.radius, g->photons.jitter,
                g->photons.autostop, g->photons.expand_tol,
                g->photons.expand_min);
    if (s->has_background) {
        fputs("background ", o);
        col(o, s->background);
        fputc('\n', o);
    }
    if (s->sky_sphere) {
        fprintf(o, "sky_sphere pigments %d emission %.6g\n",
                s->sky_sphere->n_pigments, s->sky_sphere->emission);
        for (int i = 0; i < s->sky_sphere->n_pigments; i++)
            pigment(o, 1, s->sky_sphere->pigments[i]);
    }
    for (int i = 0; i < s->n_fogs; i++) {
        fprintf(o, "fog type %d distance %.6g ", (int)s->fogs[i]->kind,
                s->fogs[i]->distance);
        col(o, s->fogs[i]->colour);
        fputc('\n', o);
    }
    for (int i = 0; i < s->n_lights; i++)
        light(o, s->lights[i]);
    for (int i = 0; i < s->n_group_lights; i++) {
        fprintf(o, "group %d ", i);
        light(o, s->group_lights[i]);
    }
    for (int i = 0; i < s->n_objects; i++)
        object(o, 0, s->objects[i], NULL);
}
