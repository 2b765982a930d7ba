/* SPDX-License-Identifier: MIT */
/*
** obj.c: objects, CSG, object modifiers and light sources.
**
** Transforms are applied eagerly, as POV-Ray applies them: a transform on
** an object composes into its own transform, into its texture (so a
** texture given before the transform moves with the object, one given
** after does not) and, for CSG, into every child. object { ID ... } works
** on a deep copy, so declared objects are never changed. Inheritance of
** textures and interiors from CSG parents to children is resolved when a
** top-level object is finished (pp_finalize_object), as POV-Ray's
** Post_Process does.
*/
#include "config.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "math/vec3.h"
#include "pp.h"

static iris_object *obj_new(pp_state *ps, int kind, const pp_token *at)
{
    pp_obj *po = pp_alloc(ps, sizeof *po);
    iris_object *o = &po->o;
    o->kind = kind;
    o->loc = pp_loc(ps, at);
    xf_identity(&o->transform);
    o->photon_density = 1;
    o->photon_collect = true;
    o->split_union = true;
    return o;
}

static bool is_csg(const iris_object *o)
{
    return o->kind == IRIS_OBJ_UNION || o->kind == IRIS_OBJ_MERGE ||
           o->kind == IRIS_OBJ_INTERSECTION ||
           o->kind == IRIS_OBJ_DIFFERENCE || o->kind == IRIS_OBJ_LIGHT_GROUP;
}

static iris_light *light_copy(pp_state *ps, const iris_light *l)
{
    iris_light *n = pp_alloc(ps, sizeof *n);
    *n = *l;
    if (l->looks_like)
        n->looks_like = pp_object_copy(ps, l->looks_like);
    if (l->projected_through)
        n->projected_through = pp_object_copy(ps, l->projected_through);
    return n;
}

iris_object *pp_object_copy(pp_state *ps, const iris_object *o)
{
    const pp_obj *src = (const pp_obj *)o;
    pp_obj *po = pp_alloc(ps, sizeof *po);
    *po = *src;
    iris_object *n = &po->o;
    /* A CSG's children stay shared until something changes them
    ** (own_children): a union redeclared from itself, '#declare A =
    ** union { object { A } ... }' 1365 times (GonzalMZ's arosFractal),
    ** then costs a node per step, not a copy of the whole tree (quadratic:
    ** over 1 GB; POV-Ray, which frees the old value, needs 22 MB). */
    if (is_csg(o) && o->u.csg.n_children)
        po->shared_children = true;
    if (o->n_clipped_by) {
        n->clipped_by = pp_alloc(ps, (size_t)o->n_clipped_by *
                                         sizeof *n->clipped_by);
        for (int i = 0; i < o->n_clipped_by; i++)
            n->clipped_by[i] = pp_object_copy(ps, o->clipped_by[i]);
    }
    if (o->bounded_by)
        n->bounded_by = pp_object_copy(ps, o->bounded_by);
    pp_light_node **tail = &po->lights;
    for (const pp_light_node *l = src->lights; l; l = l->next) {
        pp_light_node *ln = pp_alloc(ps, sizeof *ln);
        ln->light = light_copy(ps, l->light);
        *tail = ln;
        tail = &ln->next;
    }
    *tail = NULL;
    return n;
}

/* Gives CSG 'o' its own copies of its children if they are still those
** of the object it was copied from, before they are changed. */
static void own_children(pp_state *ps, iris_object *o)
{
    pp_obj *po = (pp_obj *)o;
    if (!po->shared_children)
        return;
    po->shared_children = false;
    int n = o->u.csg.n_children;
    iris_object **ch = pp_alloc(ps, (size_t)n * sizeof *ch);
    for (int i = 0; i < n; i++)
        ch[i] = pp_object_copy(ps, o->u.csg.children[i]);
    o->u.csg.children = ch;
}

void pp_light_transform(iris_light *l, const iris_transform *xf)
{
    l->location = xf_point(xf, l->location);
    l->point_at = xf_point(xf, l->point_at);
    l->axis1 = xf_dir(xf, l->axis1);
    l->axis2 = xf_dir(xf, l->axis2);
}

/*
** POV-Ray's Box::Scale and Box::Translate move a box's corners while it
** has no transform yet (no rotate, matrix or transform{} so far),
** ordering them per axis, instead of starting a transform. The box looks
** the same, but a negative scale then does not mirror the box's own
** space, which its uv mapping reads (Box::UVCoord): every face keeps its
** place in the unfolded cube. 'xf' is one scale or translate. Returns
** false when it cannot be folded so (the caller composes it).
*/
static bool box_fold(iris_object *o, const iris_transform *xf)
{
    if (o->kind != IRIS_OBJ_BOX || o->has_transform)
        return false;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            if (i != j && xf->m[i][j] != 0.0)
                return false;
    vec3 a = xf_point(xf, o->u.box.lo), b = xf_point(xf, o->u.box.hi);
    o->u.box.lo = v3_min(a, b);
    o->u.box.hi = v3_max(a, b);
    return true;
}

/* Applies 'xf' to 'o', its texture, its children and its lights. 'fold':
** 'xf' is a scale or translate, which a box may take into its corners. */
static void transform_rec(pp_state *ps, iris_object *o,
                          const iris_transform *xf, bool textures, bool fold)
{
    if (!(fold && box_fold(o, xf))) {
        xf_compose(&o->transform, &o->transform, xf);
        o->has_transform = true;
    }
    pp_obj *po = (pp_obj *)o;
    if (po->has_box) { /* POV-Ray's Recompute_BBox */
        vec3 a = po->box_lo, b = po->box_hi;
        po->box_lo = v3(1e30, 1e30, 1e30);
        po->box_hi = v3(-1e30, -1e30, -1e30);
        for (int i = 0; i < 8; i++) {
            vec3 p = xf_point(xf, v3(i & 1 ? b.x : a.x, i & 2 ? b.y : a.y,
                                     i & 4 ? b.z : a.z));
            po->box_lo = v3_min(po->box_lo, p);
            po->box_hi = v3_max(po->box_hi, p);
        }
    }
    if (o->interior && o->interior->n_media > 0)
        o->interior = pp_interior_transform(ps, o->interior, xf);
    if (textures) {
        if (o->texture)
            o->texture = pp_tex_transform(ps, o->texture, xf);
        if (o->interior_texture)
            o->interior_texture = pp_tex_transform(ps, o->interior_texture, xf);
    }
    if (is_csg(o)) {
        own_children(ps, o);
        for (int i = 0; i < o->u.csg.n_children; i++)
            transform_rec(ps, o->u.csg.children[i], xf, textures, fold);
    }
    for (int i = 0; i < o->n_clipped_by; i++)
        transform_rec(ps, o->clipped_by[i], xf, textures, fold);
    if (o->bounded_by)
        transform_rec(ps, o->bounded_by, xf, textures, fold);
    if (o->kind == IRIS_OBJ_BLOB)
        for (int i = 0; i < o->u.blob.n_components; i++)
            if (o->u.blob.components[i].texture)
                o->u.blob.components[i].texture = pp_tex_transform(
                    ps, o->u.blob.components[i].texture, xf);
    /* a mesh's own textures (texture_list, triangle textures) move with
    ** it, as POV-Ray's Mesh::Transform does; a new array, because copies
    ** of a declared mesh share the old one */
    if (textures && o->kind == IRIS_OBJ_MESH && o->u.mesh.n_textures > 0) {
        iris_mesh_data *m = &o->u.mesh;
        iris_texture **t = pp_alloc(ps, (size_t)m->n_textures * sizeof *t);
        for (int i = 0; i < m->n_textures; i++)
            t[i] = pp_tex_transform(ps, m->textures[i], xf);
        m->textures = t;
    }
    for (pp_light_node *l = ((pp_obj *)o)->lights; l; l = l->next) {
        pp_light_transform(l->light, xf);
        if (l->light->looks_like)
            transform_rec(ps, l->light->looks_like, xf, textures, fold);
        if (l->light->projected_through)
            transform_rec(ps, l->light->projected_through, xf, textures,
                          fold);
    }
}

void pp_object_transform(pp_state *ps, iris_object *o, const iris_transform *xf)
{
    transform_rec(ps, o, xf, true, false);
}

/* Adds 'c' to CSG node 'o'. */
static void csg_add(pp_state *ps, iris_object *o, iris_object *c, int *cap)
{
    if (o->u.csg.n_children == *cap) {
        int nc = *cap ? *cap * 2 : 4;
        iris_object **ch = pp_alloc(ps, (size_t)nc * sizeof *ch);
        if (o->u.csg.n_children)
            memcpy(ch, o->u.csg.children,
                   (size_t)o->u.csg.n_children * sizeof *ch);
        o->u.csg.children = ch;
        *cap = nc;
    }
    o->u.csg.children[o->u.csg.n_children++] = c;
}

static void add_light_to(pp_state *ps, iris_object *o, iris_light *l)
{
    pp_light_node *n = pp_alloc(ps, sizeof *n);
    n->light = l;
    pp_obj *po = (pp_obj *)o;
    n->next = po->lights;
    po->lights = n;
}

/* POV-Ray's CheckPassThru: target, pass_through and refraction (not off)
** cannot all hold; the flag set last decides which one is turned off
** ('which' is the keyword just parsed: pass_through turns refraction
** off; refraction on turns pass_through off; target turns off
** pass_through when refraction is explicitly on, else refraction). */
static void check_pass_through(pp_state *ps, const pp_token *at,
                               iris_object *o, int which)
{
    if (!o->photon_pass_through || !o->photon_target ||
        o->photon_refraction == IRIS_OFF)
        return;
    bool off_pass = which == T_REFRACTION ||
                    (which == T_TARGET && o->photon_refraction == IRIS_ON);
    if (off_pass) {
        pp_warning(ps, at, "cannot use pass_through with refraction and "
                   "target: turning off pass_through");
        o->photon_pass_through = false;
    } else {
        pp_warning(ps, at, "cannot use pass_through with refraction and "
                   "target: turning off refraction");
        o->photon_refraction = IRIS_OFF;
    }
}

/* photons { target [f] refraction b reflection b collect b pass_through } */
static void object_photons(pp_state *ps, iris_object *o)
{
    pp_expect(ps, T_LBRACE, "'{'");
    for (;;) {
        pp_next(ps);
        pp_token at = ps->tok;
        switch (at.kind) {
        case T_RBRACE: return;
        case T_TARGET: {
            o->photon_target = true;
            double d = 1;
            pp_next(ps);
            pp_unget(ps);
            if (pp_starts_expr(ps))
                d = pp_float(ps);
            o->photon_density = d;
            o->photon_target_loc = pp_loc(ps, &at);
            if (d <= 0)
                o->photon_target = false;
            check_pass_through(ps, &at, o, T_TARGET);
            break;
        }
        case T_REFRACTION:
            o->photon_refraction = pp_bool_opt(ps) ? IRIS_ON : IRIS_OFF;
            check_pass_through(ps, &at, o, T_REFRACTION);
            break;
        case T_REFLECTION:
            o->photon_reflection = pp_bool_opt(ps) ? IRIS_ON : IRIS_OFF;
            break;
        case T_COLLECT: o->photon_collect = pp_bool_opt(ps); break;
        case T_PASS_THROUGH:
            o->photon_pass_through = pp_bool_opt(ps);
            check_pass_through(ps, &at, o, T_PASS_THROUGH);
            break;
        default: {
            pp_unexpected(ps, &at, "photons");
        }
        }
    }
}

/*
** clip_bound: clipped_by '{' ( object { object } { TRANSFORM } | bounded_by ) '}'
**             bounded_by '{' ( object { object } { TRANSFORM } | clipped_by ) '}'
** Transforms after the objects move all of them, as POV-Ray's
** Parse_Bound_Clip does: clipped_by { Box scale 2 }.
*/
static void clip_bound(pp_state *ps, iris_object *o, bool clip)
{
    pp_expect(ps, T_LBRACE, "'{'");
    iris_object *list[64];
    int n = 0;
    for (;;) {
        pp_next(ps);
        pp_token at = ps->tok;
        if (at.kind == T_RBRACE)
            break;
        iris_transform x;
        if (n > 0 && pp_transform_item(ps, &x)) {
            for (int i = 0; i < n; i++)
                pp_object_transform(ps, list[i], &x);
            continue;
        }
        if (clip && at.kind == T_BOUNDED_BY) {
            if (o->bounded_by && n < 64)
                list[n++] = pp_object_copy(ps, o->bounded_by);
            continue;
        }
        if (!clip && at.kind == T_CLIPPED_BY) {
            if (o->n_clipped_by)
                o->bounded_by = pp_object_copy(ps, o->clipped_by[0]);
            continue;
        }
        pp_unget(ps);
        iris_object *c = pp_object(ps);
        if (!c) {
            char buf[80];
            pp_error(ps, &at, "expected an object in %s, found %s",
                     clip ? "clipped_by" : "bounded_by",
                     pp_tok_name(ps, &at, buf, sizeof buf));
        }
        if (n >= 64)
            pp_error(ps, &at, "too many objects in %s",
                     clip ? "clipped_by" : "bounded_by");
        list[n++] = c;
    }
    if (clip) {
        iris_object **cl = pp_alloc(ps, (size_t)(o->n_clipped_by + n) *
                                            sizeof *cl);
        if (o->n_clipped_by)
            memcpy(cl, o->clipped_by, (size_t)o->n_clipped_by * sizeof *cl);
        memcpy(cl + o->n_clipped_by, list, (size_t)n * sizeof *cl);
        o->clipped_by = cl;
        o->n_clipped_by += n;
    } else if (n > 0) {
        o->bounded_by = list[0];
    }
}

/* Sets the top texture layer's pigment/normal/finish on 'o'. */
static iris_texture *own_top_texture(pp_state *ps, iris_object *o,
                                     const pp_token *at)
{
    iris_texture *t = pp_alloc(ps, sizeof *t);
    if (o->texture) {
        *t = *o->texture;
    } else {
        iris_texture *d = pp_texture_new(ps, at);
        *t = *d;
    }
    o->texture = t;
    return t;
}

/*
** radiosity_block: '{' [importance F] '}'
** After 'radiosity' (an object modifier, or in #default). POV-Ray 3.7
** refuses F outside (0, 1]. Returns F, or 0 when not given.
*/
double pp_radiosity_block(pp_state *ps)
{
    pp_expect(ps, T_LBRACE, "'{'");
    double imp = 0.0;
    for (;;) {
        pp_next(ps);
        pp_token at = ps->tok;
        if (at.kind == T_RBRACE)
            return imp;
        if (at.kind != T_IMPORTANCE) {
            pp_unexpected(ps, &at, "radiosity");
            return imp;
        }
        imp = pp_float(ps);
        if (!(imp > 0.0 && imp <= 1.0)) {
            pp_error(ps, &at, "radiosity importance must be greater than 0 "
                     "and at most 1");
            imp = 1.0;
        }
        if (imp < 1.0)
            ps->scene->settings.rad_importance_used = true;
    }
}

/* One object modifier; false when the current token is none. */
static bool object_mod_item(pp_state *ps, iris_object *o)
{
    pp_token at = ps->tok;
    switch (at.kind) {
    case T_TEXTURE: {
        iris_texture *t = pp_texture(ps);
        /* layers: the new texture goes on top of the old ones */
        if (o->texture) {
            iris_texture *top = t;
            iris_texture *copy = pp_alloc(ps, sizeof *copy);
            *copy = *top;
            iris_texture *last = copy;
            while (last->next) {
                iris_texture *nx = pp_alloc(ps, sizeof *nx);
                *nx = *last->next;
                last->next = nx;
                last = nx;
            }
            last->next = o->texture;
            t = copy;
        }
        o->texture = t;
        return true;
    }
    case T_PIGMENT: {
        iris_texture *t = own_top_texture(ps, o, &at);
        t->pigment = pp_pigment(ps, t->pigment);
        return true;
    }
    case T_NORMAL: {
        iris_texture *t = own_top_texture(ps, o, &at);
        t->normal = pp_normal(ps, t->normal);
        return true;
    }
    case T_FINISH: {
        iris_texture *t = own_top_texture(ps, o, &at);
        t->finish = pp_finish(ps, t->finish);
        return true;
    }
    case T_INTERIOR:
        o->interior = pp_interior(ps, o->interior);
        return true;
    case T_INTERIOR_TEXTURE:
        o->interior_texture = pp_texture(ps);
        return true;
    case T_MATERIAL: {
        pp_material *m = pp_material_block(ps);
        if (m->tex)
            o->texture = m->tex;
        if (m->interior_tex)
            o->interior_texture = m->interior_tex;
        if (m->inter)
            o->interior = m->inter;
        return true;
    }
    case T_INVERSE: o->inverse = !o->inverse; return true;
    case T_HOLLOW: o->hollow = pp_bool_opt(ps); return true;
    case T_NO_SHADOW: o->no_shadow = true; return true;
    case T_NO_IMAGE: o->no_image = pp_bool_opt(ps); return true;
    case T_NO_REFLECTION: o->no_reflection = pp_bool_opt(ps); return true;
    case T_NO_RADIOSITY: o->no_radiosity = true; return true;
    case T_DOUBLE_ILLUMINATE: o->double_illuminate = pp_bool_opt(ps); return true;
    case T_STURM: o->sturm = pp_bool_opt(ps); return true;
    case T_SPLIT_UNION: o->split_union = pp_bool_opt(ps); return true;
    case T_CLIPPED_BY: clip_bound(ps, o, true); return true;
    case T_BOUNDED_BY: clip_bound(ps, o, false); return true;
    case T_PHOTONS: object_photons(ps, o); return true;
    case T_UV_MAPPING: {
        ((pp_obj *)o)->uv_mapping = true;
        /* a mesh's own textures (texture_list, triangle textures) too */
        iris_mesh_data *m = o->kind == IRIS_OBJ_MESH ? &o->u.mesh : NULL;
        if (m && m->n_textures > 0 && m->textures) {
            iris_texture **nt = pp_alloc(ps, (size_t)m->n_textures *
                                                 sizeof *nt);
            for (int i = 0; i < m->n_textures; i++)
                nt[i] = pp_tex_uv_mapped(ps, m->textures[i]);
            m->textures = nt;
        }
        return true;
    }
    case T_CUTAWAY_TEXTURES: ((pp_obj *)o)->cutaway = true; return true;
    case T_RADIOSITY: {
        double imp = pp_radiosity_block(ps);
        if (imp > 0.0)
            o->radiosity_importance = imp;
        return true;
    }
    case T_NO_BUMP_SCALE: pp_bool_opt(ps); return true;
    default: {
        iris_transform x;
        int kind = ps->tok.kind;
        bool fold = kind == T_SCALE || kind == T_TRANSLATE;
        if (pp_transform_item(ps, &x)) {
            if (o->kind == IRIS_OBJ_SPHERE &&
                (kind == T_MATRIX || kind == T_TRANSFORM ||
                 (kind == T_SCALE && (x.m[0][0] != x.m[1][1] ||
                                      x.m[0][0] != x.m[2][2]))))
                ((pp_obj *)o)->sphere_trans = true;
            transform_rec(ps, o, &x, true, fold);
            return true;
        }
        return false;
    }
    }
}

/* After an object's uv_mapping, every texture it is given is evaluated at
** the surface's <u, v, 0>, and the object's later transforms leave it
** (POV-Ray's UV_FLAG: trace.cpp takes the uv point for the whole texture;
** Transform_Textures is skipped). Marked as each texture arrives, before
** any transform that follows it. */
static void uv_mark(pp_state *ps, iris_object *o)
{
    if (!((pp_obj *)o)->uv_mapping)
        return;
    o->texture = pp_tex_uv_mapped(ps, o->texture);
    o->interior_texture = pp_tex_uv_mapped(ps, o->interior_texture);
}

/* Object modifiers; false when the current token is none. */
static bool object_mod(pp_state *ps, iris_object *o)
{
    int k = ps->tok.kind;
    bool r = object_mod_item(ps, o);
    if (r && (k == T_TEXTURE || k == T_PIGMENT || k == T_NORMAL ||
              k == T_MATERIAL || k == T_INTERIOR_TEXTURE))
        uv_mark(ps, o);
    return r;
}

/* Reads modifiers up to the closing '}' of the object opened at 'open'. */
static void object_mods(pp_state *ps, iris_object *o, const pp_token *open,
                        const char *what)
{
    for (;;) {
        pp_next(ps);
        if (ps->tok.kind == T_RBRACE)
            return;
        if (object_mod(ps, o))
            continue;
        char buf[80];
        if (ps->tok.kind == T_EOF)
            pp_error(ps, open, "%s without its closing '}'", what);
        if (ps->tok.kind == T_IDENT)
            pp_unexpected(ps, &ps->tok, what);
        pp_error(ps, &ps->tok, "unexpected %s in %s (opened at line %u)",
                 pp_tok_name(ps, &ps->tok, buf, sizeof buf), what,
                 pp_loc(ps, open).line);
    }
}

/* POV-Ray's Parse_Comma: the comma is optional. */
static void comma(pp_state *ps) { pp_accept(ps, T_COMMA); }

/* contained_by_rest: '{' ( box '{' vector [','] vector '}'
**                         | sphere '{' vector [','] float '}' ) '}'
** (isosurface and parametric; *kind 0 box lo..hi, 1 sphere) */
static void contained_by(pp_state *ps, int *kind, iris_vec3 *lo,
                         iris_vec3 *hi, iris_vec3 *centre, double *radius)
{
    pp_expect(ps, T_LBRACE, "'{'");
    pp_next(ps);
    if (ps->tok.kind == T_BOX) {
        pp_expect(ps, T_LBRACE, "'{'");
        *kind = 0;
        *lo = pp_vector(ps); comma(ps);
        *hi = pp_vector(ps);
    } else if (ps->tok.kind == T_SPHERE) {
        pp_expect(ps, T_LBRACE, "'{'");
        *kind = 1;
        *centre = pp_vector(ps); comma(ps);
        *radius = pp_float(ps);
    } else {
        pp_error(ps, &ps->tok, "contained_by takes a box or a sphere");
    }
    pp_expect(ps, T_RBRACE, "'}'");
    pp_expect(ps, T_RBRACE, "'}'");
}

/* An index read as a float: out-of-range values become -1 (rejected by
** the callers' range checks) instead of undefined conversions. */
static int32_t index_of(double v)
{
    return v >= 0 && v < 2147483647.0 ? (int32_t)v : -1;
}

/* ---- the light source ------------------------------------------- */

static bool ident_is(pp_state *ps, const pp_token *t, const char *word)
{
    size_t n = strlen(word);
    return t->kind == T_IDENT && t->len == n &&
           memcmp(pp_tok_text(ps, t), word, n) == 0;
}

/* light_source { <location>, colour modifiers... } */
iris_light *pp_light(pp_state *ps)
{
    pp_token open = ps->tok;
    pp_expect(ps, T_LBRACE, "'{' after light_source");
    iris_light *l = pp_alloc(ps, sizeof *l);
    pp_next(ps);
    if (ps->tok.kind == T_IDENT && ps->tok.val.kind == V_LIGHT) {
        *l = *light_copy(ps, ps->tok.val.u.light);
    } else {
        pp_unget(ps);
        iris_light_defaults(l);
        l->location = pp_vector(ps);
        pp_accept(ps, T_COMMA);
        l->colour = pp_colour(ps);
    }
    l->loc = pp_loc(ps, &open);
    bool radius_set = false, falloff_set = false;
    for (;;) {
        pp_next(ps);
        pp_token at = ps->tok;
        switch (at.kind) {
        case T_RBRACE:
            if (l->kind == IRIS_LIGHT_CYLINDER) {
                if (!radius_set) l->radius = 0.75;
                if (!falloff_set) l->falloff = 1;
            }
            return l;
        case T_SPOTLIGHT:
            l->kind = IRIS_LIGHT_SPOT;
            if (!radius_set) l->radius = 30;
            if (!falloff_set) l->falloff = 45;
            break;
        case T_CYLINDER: l->kind = IRIS_LIGHT_CYLINDER; l->parallel = true; break;
        case T_PARALLEL: l->parallel = true; break;
        case T_POINT_AT: l->point_at = pp_vector(ps); break;
        case T_RADIUS: l->radius = pp_float(ps); radius_set = true; break;
        case T_FALLOFF: l->falloff = pp_float(ps); falloff_set = true; break;
        case T_TIGHTNESS: l->tightness = pp_float(ps); break;
        case T_AREA_LIGHT:
            l->area = true;
            l->axis1 = pp_vector(ps); comma(ps);
            l->axis2 = pp_vector(ps); comma(ps);
            pp_next(ps);
            pp_token sizes = ps->tok;
            pp_unget(ps);
            l->size1 = pp_int(ps); comma(ps);
            l->size2 = pp_int(ps);
            if (l->size1 < 1 || l->size2 < 1)
                pp_error(ps, &at, "area_light sizes must be >= 1");
            else if ((double)l->size1 * l->size2 > IRIS_AREA_LIGHT_MAX_GRID)
                pp_warning(ps, &sizes, "area_light %d x %d: more than %d "
                           "sub-lights; rendered as a point light at its "
                           "centre (hard shadows)", l->size1, l->size2,
                           IRIS_AREA_LIGHT_MAX_GRID);
            break;
        case T_ADAPTIVE: l->adaptive = pp_int(ps); break;
        case T_JITTER: l->jitter = pp_bool_opt(ps); break;
        case T_CIRCULAR: l->circular = pp_bool_opt(ps); break;
        case T_ORIENT: l->orient = pp_bool_opt(ps); break;
        case T_AREA_ILLUMINATION: l->area_illumination = pp_bool_opt(ps); break;
        case T_SHADOWLESS: l->shadowless = true; break;
        case T_FADE_DISTANCE: l->fade_distance = pp_float(ps); break;
        case T_FADE_POWER: l->fade_power = pp_float(ps); break;
        case T_MEDIA_INTERACTION: l->media_interaction = pp_bool_opt(ps); break;
        case T_MEDIA_ATTENUATION: l->media_attenuation = pp_bool_opt(ps); break;
        case T_LOOKS_LIKE: case T_PROJECTED_THROUGH: {
            pp_expect(ps, T_LBRACE, "'{'");
            pp_next(ps);
            iris_object *o;
            if (ps->tok.kind == T_IDENT && ps->tok.val.kind == V_OBJECT) {
                o = pp_object_copy(ps, ps->tok.val.u.obj);
            } else {
                pp_unget(ps);
                o = pp_object(ps);
                if (!o)
                    pp_error(ps, &ps->tok, "expected an object");
            }
            pp_expect(ps, T_RBRACE, "'}'");
            if (at.kind == T_LOOKS_LIKE) {
                /* POV-Ray moves the object to the light and removes its
                ** shadow */
                iris_transform tr;
                xf_translate(&tr, l->location);
                pp_object_transform(ps, o, &tr);
                o->no_shadow = true;
                l->looks_like = o;
            } else {
                l->projected_through = o;
            }
            break;
        }
        case T_PHOTONS:
            pp_expect(ps, T_LBRACE, "'{'");
            for (;;) {
                pp_next(ps);
                if (ps->tok.kind == T_RBRACE)
                    break;
                if (ps->tok.kind == T_REFRACTION)
                    l->photon_refraction = pp_bool_opt(ps) ? IRIS_ON : IRIS_OFF;
                else if (ps->tok.kind == T_REFLECTION)
                    l->photon_reflection = pp_bool_opt(ps) ? IRIS_ON : IRIS_OFF;
                else if (ps->tok.kind == T_AREA_LIGHT)
                    l->photon_area_light = pp_bool_opt(ps);
                else
                    pp_error(ps, &ps->tok, "expected refraction, reflection "
                             "or area_light in the light's photons block");
            }
            break;
        case T_IDENT:
            if (ident_is(ps, &at, "spectrum")) {
                const char *s = pp_string(ps);
                if (strcmp(s, "D65") == 0) {
                    l->spectrum = IRIS_SPEC_D65;
                } else if (strcmp(s, "A") == 0) {
                    l->spectrum = IRIS_SPEC_A;
                } else if (s[0] == 'F' && s[1] >= '1' && s[1] <= '9' &&
                           atoi(s + 1) >= 1 && atoi(s + 1) <= 12 &&
                           strlen(s) <= 3) {
                    l->spectrum = IRIS_SPEC_F1 + atoi(s + 1) - 1;
                } else {
                    pp_error(ps, &at, "unknown spectrum \"%s\" (D65, A, F1 "
                             "to F12)", s);
                }
                break;
            }
            if (ident_is(ps, &at, "blackbody")) {
                double k = pp_float(ps);
                if (!(k > 0) || k > 1e6)
                    pp_error(ps, &at, "blackbody temperature must be in "
                             "(0, 1e6] kelvin");
                l->spectrum = IRIS_SPEC_BLACKBODY;
                l->blackbody_kelvin = k;
                break;
            }
            goto bad;
        case T_COLOR: case T_RGB: case T_RGBF: case T_RGBT: case T_RGBFT:
        case T_SRGB:
            pp_unget(ps);
            l->colour = pp_colour(ps);
            break;
        default: {
            iris_transform x;
            if (pp_transform_item(ps, &x)) {
                pp_light_transform(l, &x);
                if (l->looks_like)
                    pp_object_transform(ps, l->looks_like, &x);
                if (l->projected_through)
                    pp_object_transform(ps, l->projected_through, &x);
                break;
            }
        }
        bad: {
            pp_unexpected(ps, &at, "light_source");
        }
        }
    }
}

/* ---- shapes ------------------------------------------------------ */

static iris_vec3 *vec_list(pp_state *ps, int n)
{
    iris_vec3 *v = pp_alloc(ps, (size_t)n * sizeof *v);
    for (int i = 0; i < n; i++) {
        if (i)
            pp_accept(ps, T_COMMA);
        v[i] = pp_vector(ps);
    }
    return v;
}

static int count(pp_state *ps, int max, const char *what)
{
    pp_token at;
    pp_next(ps);
    at = ps->tok;
    pp_unget(ps);
    double n = pp_float(ps);
    if (!(n >= 0) || n > max)
        pp_error(ps, &at, "%s count %g out of range [0, %d]", what, n, max);
    return (int)n;
}

#define MAX_ITEMS (1 << 24)

/* True when the next tokens are a float expression, not the '<' or vector
** identifier of the next face, nor the '}' or a directive that ends the
** list: POV-Ray's test for a texture index after a face. */
static bool next_is_float(pp_state *ps)
{
    if (pp_next_is_directive(ps))
        return false;
    pp_next(ps);
    bool f = pp_starts_expr(ps);
    switch (ps->tok.kind) {
    case T_LT: case T_STRING:
    case T_X: case T_Y: case T_Z: case T_T: case T_U: case T_V:
    case T_VNORMALIZE: case T_VCROSS: case T_VROTATE: case T_VAXIS_ROTATE:
    case T_VTURBULENCE: case T_MIN_EXTENT: case T_MAX_EXTENT: case T_TRACE:
        f = false;
        break;
    case T_IDENT: {
        const pp_value *v = &ps->tok.val;
        if (v->kind == V_ARRAY && v->u.arr->n > 0)
            v = &v->u.arr->items[0]; /* its elements' kind */
        f = v->kind == V_FLOAT;
        break;
    }
    default:
        break;
    }
    pp_unget(ps);
    return f;
}

/* The texture maps a mesh2's faces with three different texture indices
** get, numbered after the texture_list (face_blends_add appends them). */
struct face_blends {
    iris_texture **t;
    int n, cap;
};

/*
** A face with three textures: POV-Ray shades all three and mixes them by
** the point's place on the face (Mesh::Determine_Textures), which the
** renderer does for a FACE_BLEND map of the three (mat_face_weights).
** The corners 'v', in the mesh's space as the map's pattern (a transform
** of the mesh moves both), are rounded to float as POV-Ray stores mesh
** vertices.
*/
static iris_texture *face_blend_texture(pp_state *ps, const pp_token *at,
                                        const vec3 v[3],
                                        iris_texture *const tex[3])
{
    iris_texture *t = pp_texture_new(ps, at);
    iris_pattern *pat = &t->map_pattern;
    pat->kind = IRIS_PAT_FACE_BLEND;
    vec3 c[3];
    for (int k = 0; k < 3; k++)
        c[k] = v3((float)v[k].x, (float)v[k].y, (float)v[k].z);
    pat->vector = c[0];
    pat->params[0] = c[1].x; pat->params[1] = c[1].y; pat->params[2] = c[1].z;
    pat->params[3] = c[2].x; pat->params[4] = c[2].y; pat->params[5] = c[2].z;
    t->n_entries = 3;
    t->entries = pp_alloc(ps, 3 * sizeof *t->entries);
    memset(t->entries, 0, 3 * sizeof *t->entries);
    for (int k = 0; k < 3; k++) {
        t->entries[k].value = 1.0;
        t->entries[k].texture = tex[k];
    }
    pp_tex_map_tree(ps, t, at);
    return t;
}

/* A mesh2 face's FACE_BLEND map of texture_list entries 'tk', kept in
** 'b'; returns the texture index it will have. */
static int32_t face_blend(pp_state *ps, const pp_token *at,
                          const iris_mesh_data *m, int face,
                          const int32_t tk[3], struct face_blends *b)
{
    vec3 v[3];
    iris_texture *tex[3];
    for (int k = 0; k < 3; k++) {
        v[k] = m->vertices[m->tri_vertices[3 * face + k]];
        tex[k] = m->textures[tk[k]];
    }
    iris_texture *t = face_blend_texture(ps, at, v, tex);
    if (b->n == b->cap) {
        int nc = b->cap ? 2 * b->cap : 16;
        iris_texture **nt = pp_alloc(ps, (size_t)nc * sizeof *nt);
        if (b->n)
            memcpy(nt, b->t, (size_t)b->n * sizeof *nt);
        b->t = nt;
        b->cap = nc;
    }
    b->t[b->n++] = t;
    return (int32_t)(m->n_textures + b->n - 1);
}

/* Appends the face maps to the mesh's textures. */
static void face_blends_add(pp_state *ps, iris_mesh_data *m,
                            const struct face_blends *b)
{
    if (b->n == 0)
        return;
    iris_texture **nt = pp_alloc(ps, (size_t)(m->n_textures + b->n) *
                                         sizeof *nt);
    memcpy(nt, m->textures, (size_t)m->n_textures * sizeof *nt);
    memcpy(nt + m->n_textures, b->t, (size_t)b->n * sizeof *nt);
    m->textures = nt;
    m->n_textures += b->n;
}

/* mesh2 { vertex_vectors{} normal_vectors{} uv_vectors{} texture_list{}
**         face_indices{} normal_indices{} uv_indices{} ... } */
static void mesh2(pp_state *ps, iris_object *o)
{
    iris_mesh_data *m = &o->u.mesh;
    for (;;) {
        pp_next(ps);
        pp_token at = ps->tok;
        switch (at.kind) {
        case T_VERTEX_VECTORS: case T_NORMAL_VECTORS: {
            pp_expect(ps, T_LBRACE, "'{'");
            int n = count(ps, MAX_ITEMS, "vector");
            pp_accept(ps, T_COMMA);
            iris_vec3 *v = vec_list(ps, n);
            pp_accept(ps, T_COMMA);
            pp_expect(ps, T_RBRACE, "'}' (more vectors than the count?)");
            if (at.kind == T_VERTEX_VECTORS) {
                m->n_vertices = n;
                m->vertices = v;
            } else {
                m->n_normals = n;
                m->normals = v;
            }
            break;
        }
        case T_UV_VECTORS: {
            pp_expect(ps, T_LBRACE, "'{'");
            int n = count(ps, MAX_ITEMS, "uv vector");
            m->uvs = pp_alloc(ps, (size_t)n * sizeof *m->uvs);
            for (int i = 0; i < n; i++) {
                pp_accept(ps, T_COMMA);
                m->uvs[i] = pp_vector2(ps);
            }
            m->n_uvs = n;
            pp_accept(ps, T_COMMA);
            pp_expect(ps, T_RBRACE, "'}'");
            break;
        }
        case T_TEXTURE_LIST: {
            pp_expect(ps, T_LBRACE, "'{'");
            int n = count(ps, 1 << 20, "texture");
            m->textures = pp_alloc(ps, (size_t)(n ? n : 1) * sizeof *m->textures);
            for (int i = 0; i < n; i++) {
                pp_accept(ps, T_COMMA);
                pp_expect(ps, T_TEXTURE, "texture");
                m->textures[i] = pp_texture(ps);
            }
            m->n_textures = n;
            pp_accept(ps, T_COMMA);
            pp_expect(ps, T_RBRACE, "'}'");
            break;
        }
        case T_FACE_INDICES: {
            struct face_blends blends = { NULL, 0, 0 };
            pp_expect(ps, T_LBRACE, "'{'");
            int n = count(ps, MAX_ITEMS, "face");
            m->n_triangles = n;
            m->tri_vertices = pp_alloc(ps, (size_t)n * 3 * sizeof(int32_t));
            if (m->n_textures)
                m->tri_texture = pp_alloc(ps, (size_t)n * sizeof(int32_t));
            for (int i = 0; i < n; i++) {
                pp_accept(ps, T_COMMA);
                pp_token vt = ps->tok;
                iris_vec3 f = pp_vector(ps);
                int32_t a = index_of(f.x), b = index_of(f.y), c = index_of(f.z);
                if (a < 0 || b < 0 || c < 0 || a >= m->n_vertices ||
                    b >= m->n_vertices || c >= m->n_vertices)
                    pp_error(ps, &vt, "face index out of range [0, %d]",
                             m->n_vertices - 1);
                m->tri_vertices[3 * i] = a;
                m->tri_vertices[3 * i + 1] = b;
                m->tri_vertices[3 * i + 2] = c;
                if (m->tri_texture) /* none: the object's texture */
                    m->tri_texture[i] = -1;
                /* optional texture indices: one or three, each any
                ** float expression (mod(I+J, 2)); three different ones
                ** blend across the face (face_blend) */
                int32_t tk[3] = { -1, -1, -1 };
                for (int k = 0; k < 3; k++) {
                    pp_accept(ps, T_COMMA);
                    if (!next_is_float(ps))
                        break;
                    pp_next(ps);
                    pp_token tt = ps->tok;
                    pp_unget(ps);
                    double tf = pp_float(ps);
                    if (!(tf >= 0) || tf >= m->n_textures)
                        pp_error(ps, &tt, "texture index %g out of range "
                                 "[0, %d]", tf, m->n_textures - 1);
                    tk[k] = (int32_t)tf;
                    if (k == 0 && m->tri_texture)
                        m->tri_texture[i] = (int32_t)tf;
                }
                if (m->tri_texture && tk[2] >= 0 &&
                    (tk[1] != tk[0] || tk[2] != tk[0]))
                    m->tri_texture[i] = face_blend(ps, &vt, m, i, tk,
                                                   &blends);
            }
            pp_accept(ps, T_COMMA);
            pp_expect(ps, T_RBRACE, "'}' (more faces than the count?)");
            face_blends_add(ps, m, &blends);
            break;
        }
        case T_NORMAL_INDICES: case T_UV_INDICES: {
            pp_expect(ps, T_LBRACE, "'{'");
            int n = count(ps, MAX_ITEMS, "index");
            int32_t *idx = pp_alloc(ps, (size_t)(n ? n : 1) * 3 * sizeof *idx);
            int lim = at.kind == T_NORMAL_INDICES ? m->n_normals : m->n_uvs;
            for (int i = 0; i < n; i++) {
                pp_accept(ps, T_COMMA);
                pp_token vt = ps->tok;
                iris_vec3 f = pp_vector(ps);
                idx[3 * i] = index_of(f.x);
                idx[3 * i + 1] = index_of(f.y);
                idx[3 * i + 2] = index_of(f.z);
                for (int k = 0; k < 3; k++)
                    if (idx[3 * i + k] < 0 || idx[3 * i + k] >= lim)
                        pp_error(ps, &vt, "index out of range [0, %d]",
                                 lim - 1);
            }
            pp_accept(ps, T_COMMA);
            pp_expect(ps, T_RBRACE, "'}'");
            if (at.kind == T_NORMAL_INDICES)
                m->tri_normals = idx;
            else
                m->tri_uvs = idx;
            break;
        }
        case T_INSIDE_VECTOR:
            m->inside_vector = pp_vector(ps);
            break;
        default:
            pp_unget(ps);
            if (m->normals && !m->tri_normals &&
                m->n_normals == m->n_vertices)
                m->tri_normals = m->tri_vertices;
            if (m->uvs && !m->tri_uvs && m->n_uvs == m->n_vertices)
                m->tri_uvs = m->tri_vertices;
            return;
        }
    }
}

/* texture_list { TEXTURE_ID, TEXTURE_ID, TEXTURE_ID } in a mesh{}
** triangle with corners 'p': the three blended across it (face_blend).
** The current token is texture_list. */
static iris_texture *mesh1_texture_list(pp_state *ps, const vec3 p[3])
{
    pp_token at = ps->tok;
    pp_expect(ps, T_LBRACE, "'{'");
    iris_texture *tex[3];
    for (int k = 0; k < 3; k++) {
        if (k)
            pp_accept(ps, T_COMMA);
        pp_next(ps);
        if (ps->tok.kind != T_IDENT || ps->tok.val.kind != V_TEXTURE)
            pp_error(ps, &ps->tok, "expected a declared texture (a mesh "
                     "triangle's texture_list names three)");
        tex[k] = ps->tok.val.u.tex;
    }
    pp_accept(ps, T_COMMA);
    pp_expect(ps, T_RBRACE, "'}' after three textures");
    return face_blend_texture(ps, &at, p, tex);
}

/* mesh { triangle{} smooth_triangle{} ... [inside_vector v] } */
static void mesh1(pp_state *ps, iris_object *o)
{
    iris_mesh_data *m = &o->u.mesh;
    int cap = 0;
    int tcap = 0;
    for (;;) {
        pp_next(ps);
        pp_token at = ps->tok;
        bool smooth = at.kind == T_SMOOTH_TRIANGLE;
        if (at.kind == T_INSIDE_VECTOR) {
            m->inside_vector = pp_vector(ps);
            continue;
        }
        if (at.kind != T_TRIANGLE && !smooth) {
            pp_unget(ps);
            return;
        }
        pp_expect(ps, T_LBRACE, "'{'");
        iris_vec3 p[3], n[3];
        for (int i = 0; i < 3; i++) {
            if (i)
                pp_accept(ps, T_COMMA);
            p[i] = pp_vector(ps);
            if (smooth) {
                pp_accept(ps, T_COMMA);
                n[i] = pp_vector(ps);
            }
        }
        if (m->n_triangles >= MAX_ITEMS)
            pp_error(ps, &at, "mesh with too many triangles");
        if (m->n_triangles == cap) {
            int nc = cap ? cap * 2 : 64;
            iris_vec3 *nv = pp_alloc(ps, (size_t)nc * 3 * sizeof *nv);
            iris_vec3 *nn = pp_alloc(ps, (size_t)nc * 3 * sizeof *nn);
            int32_t *ti = pp_alloc(ps, (size_t)nc * sizeof *ti);
            iris_vec2 *nu = pp_alloc(ps, (size_t)nc * 3 * sizeof *nu);
            if (cap) {
                memcpy(nv, m->vertices, (size_t)cap * 3 * sizeof *nv);
                memcpy(nn, m->normals, (size_t)cap * 3 * sizeof *nn);
                memcpy(ti, m->tri_texture, (size_t)cap * sizeof *ti);
                memcpy(nu, m->uvs, (size_t)cap * 3 * sizeof *nu);
            }
            m->vertices = nv;
            m->normals = nn;
            m->tri_texture = ti;
            m->uvs = nu;
            cap = nc;
        }
        int t = m->n_triangles++;
        for (int i = 0; i < 3; i++) {
            m->vertices[3 * t + i] = p[i];
            m->normals[3 * t + i] = smooth ? n[i] : v3(0, 0, 0);
            m->uvs[3 * t + i] = (iris_vec2){ 0, 0 }; /* POV-Ray's default */
        }
        m->tri_texture[t] = -1;
        for (;;) {
            pp_next(ps);
            if (ps->tok.kind == T_RBRACE)
                break;
            if (ps->tok.kind == T_TEXTURE ||
                ps->tok.kind == T_TEXTURE_LIST) {
                iris_texture *tx = ps->tok.kind == T_TEXTURE
                                       ? pp_texture(ps)
                                       : mesh1_texture_list(ps, p);
                if (m->n_textures == tcap) {
                    int nc = tcap ? tcap * 2 : 8;
                    iris_texture **nt = pp_alloc(ps, (size_t)nc * sizeof *nt);
                    if (tcap)
                        memcpy(nt, m->textures, (size_t)tcap * sizeof *nt);
                    m->textures = nt;
                    tcap = nc;
                }
                m->tri_texture[t] = m->n_textures;
                m->textures[m->n_textures++] = tx;
            } else if (ps->tok.kind == T_UV_VECTORS) {
                /* kept (mesh1_finish): uv_mapping and the mesh camera's
                ** distribution 3 read them; n_uvs marks "some given" */
                for (int i = 0; i < 3; i++) {
                    if (i)
                        pp_accept(ps, T_COMMA);
                    m->uvs[3 * t + i] = pp_vector2(ps);
                }
                m->n_uvs = 1;
            } else {
                pp_unexpected(ps, &ps->tok, "a mesh triangle");
            }
        }
    }
}

/* Finishes a mesh{}: vertices per triangle become indexed. */
static void mesh1_finish(pp_state *ps, iris_object *o)
{
    iris_mesh_data *m = &o->u.mesh;
    int n = m->n_triangles;
    m->n_vertices = 3 * n;
    m->tri_vertices = pp_alloc(ps, (size_t)(n ? n : 1) * 3 * sizeof(int32_t));
    bool any_smooth = false;
    for (int i = 0; i < 3 * n; i++) {
        m->tri_vertices[i] = i;
        if (v3_len2(m->normals[i]) > 0)
            any_smooth = true;
    }
    if (any_smooth) {
        m->n_normals = 3 * n;
        m->tri_normals = m->tri_vertices;
    } else {
        m->normals = NULL;
    }
    if (m->n_uvs > 0) {
        m->n_uvs = 3 * n;
        m->tri_uvs = m->tri_vertices;
    } else {
        m->uvs = NULL;
    }
    bool any_tex = false;
    for (int i = 0; i < n; i++)
        any_tex |= m->tri_texture[i] >= 0;
    if (!any_tex)
        m->tri_texture = NULL;
}

/* The list of 2-D points of prism/lathe/sor; 'n' points. */
static iris_vec2 *points2(pp_state *ps, int n)
{
    iris_vec2 *p = pp_alloc(ps, (size_t)(n ? n : 1) * sizeof *p);
    for (int i = 0; i < n; i++) {
        pp_accept(ps, T_COMMA);
        p[i] = pp_vector2(ps);
    }
    return p;
}

static int spline_kw(int k)
{
    switch (k) {
    case T_LINEAR_SPLINE: return IRIS_SPLINE_LINEAR;
    case T_QUADRATIC_SPLINE: return IRIS_SPLINE_QUADRATIC;
    case T_CUBIC_SPLINE: return IRIS_SPLINE_CUBIC;
    case T_BEZIER_SPLINE: return IRIS_SPLINE_BEZIER;
    default: return -1;
    }
}

/* Polynomial coefficients: '<' c0, c1, ... '>' of exactly 'n' terms. */
static double *coeffs(pp_state *ps, int n)
{
    double *c = pp_alloc(ps, (size_t)n * sizeof *c);
    pp_expect(ps, T_LT, "'<'");
    bool iv = ps->in_vector;
    ps->in_vector = true;
    for (int i = 0; i < n; i++) {
        if (i)
            comma(ps);
        c[i] = pp_float(ps);
    }
    ps->in_vector = iv;
    pp_expect(ps, T_GT, "'>' (wrong number of coefficients?)");
    return c;
}

/* blob { threshold t  sphere{c, r, [strength] s mods} cylinder{...}
**        component s, r, <c> ... } */
static void blob(pp_state *ps, iris_object *o)
{
    int cap = 0;
    o->u.blob.threshold = 1;
    for (;;) {
        pp_next(ps);
        pp_token at = ps->tok;
        if (at.kind == T_THRESHOLD) {
            o->u.blob.threshold = pp_float(ps);
            continue;
        }
        if (at.kind == T_HIERARCHY) {
            pp_bool_opt(ps);
            continue;
        }
        if (at.kind != T_SPHERE && at.kind != T_CYLINDER &&
            at.kind != T_COMPONENT) {
            pp_unget(ps);
            return;
        }
        if (o->u.blob.n_components == cap) {
            int nc = cap ? cap * 2 : 8;
            iris_blob_component *c = pp_alloc(ps, (size_t)nc * sizeof *c);
            if (cap)
                memcpy(c, o->u.blob.components, (size_t)cap * sizeof *c);
            o->u.blob.components = c;
            cap = nc;
        }
        iris_blob_component *c = &o->u.blob.components[o->u.blob.n_components++];
        memset(c, 0, sizeof *c);
        xf_identity(&c->transform);
        if (at.kind == T_COMPONENT) {
            c->strength = pp_float(ps); comma(ps);
            c->radius = pp_float(ps); comma(ps);
            c->a = pp_vector(ps);
            continue;
        }
        pp_expect(ps, T_LBRACE, "'{'");
        c->kind = at.kind == T_CYLINDER;
        c->a = pp_vector(ps); comma(ps);
        if (c->kind) {
            c->b = pp_vector(ps); comma(ps);
        }
        c->radius = pp_float(ps);
        pp_accept(ps, T_COMMA);
        pp_accept(ps, T_STRENGTH);
        c->strength = pp_float(ps);
        for (;;) {
            pp_next(ps);
            pp_token mt = ps->tok;
            if (mt.kind == T_RBRACE)
                break;
            iris_transform x;
            if (pp_transform_item(ps, &x)) {
                xf_compose(&c->transform, &c->transform, &x);
                c->has_transform = true;
                if (c->texture)
                    c->texture = pp_tex_transform(ps, c->texture, &x);
            } else if (mt.kind == T_TEXTURE) {
                c->texture = pp_texture(ps);
            } else if (mt.kind == T_PIGMENT) {
                if (!c->texture)
                    c->texture = pp_texture_new(ps, &mt);
                c->texture->pigment = pp_pigment(ps, c->texture->pigment);
            } else if (mt.kind == T_FINISH) {
                if (!c->texture)
                    c->texture = pp_texture_new(ps, &mt);
                c->texture->finish = pp_finish(ps, c->texture->finish);
            } else if (mt.kind == T_NORMAL) {
                if (!c->texture)
                    c->texture = pp_texture_new(ps, &mt);
                c->texture->normal = pp_normal(ps, c->texture->normal);
            } else {
                pp_unexpected(ps, &mt, "a blob component");
            }
        }
    }
}

/* isosurface { function{} [contained_by{}] [threshold] [accuracy]
**              [max_gradient] [evaluate] [max_trace] [all_intersections] } */
static void isosurface(pp_state *ps, iris_object *o)
{
    o->u.isosurface.threshold = 0;
    o->u.isosurface.accuracy = 0.001;
    o->u.isosurface.max_gradient = 1.1;
    o->u.isosurface.lo = v3(-1, -1, -1);
    o->u.isosurface.hi = v3(1, 1, 1);
    o->u.isosurface.max_trace = 1;
    for (;;) {
        pp_next(ps);
        pp_token at = ps->tok;
        switch (at.kind) {
        case T_FUNCTION: o->u.isosurface.fn = pp_function(ps); break;
        case T_CONTAINED_BY: {
            contained_by(ps, &o->u.isosurface.contained_kind,
                         &o->u.isosurface.lo, &o->u.isosurface.hi,
                         &o->u.isosurface.centre, &o->u.isosurface.radius);
            break;
        }
        case T_THRESHOLD: o->u.isosurface.threshold = pp_float(ps); break;
        case T_ACCURACY: o->u.isosurface.accuracy = pp_float(ps); break;
        case T_MAX_GRADIENT: o->u.isosurface.max_gradient = pp_float(ps); break;
        case T_EVALUATE:
            pp_float(ps); comma(ps); pp_float(ps); comma(ps); pp_float(ps);
            break;
        case T_MAX_TRACE: o->u.isosurface.max_trace = pp_int(ps); break;
        case T_ALL_INTERSECTIONS: o->u.isosurface.all_intersections = true; break;
        /* POV-Ray's isosurface reads 'open' among its own keywords, so
        ** that max_gradient and the others may still follow it */
        case T_OPEN: o->open = true; break;
        default:
            pp_unget(ps);
            if (!o->u.isosurface.fn)
                pp_error(ps, &at, "isosurface without a function");
            return;
        }
    }
}

/* The shape-specific part of an object, after its '{'. */
/* [ open ] right after the parameters of a cylinder, cone, prism or sor:
** POV-Ray's Parse_Cylinder, Parse_Cone, Parse_Prism and Parse_Sor read it
** there and nowhere else, and no other shape takes it ('sphere { 0, 1
** open }', 'object { C open }' are errors). The isosurface reads its own
** among its keywords. */
static void closed_or_open(pp_state *ps, iris_object *o)
{
    /* POV-Ray reads on with Get_Token, which runs directives first:
    ** 'cylinder { A, B, R #if (Hollow) open #end }' */
    if (pp_accept_in_list(ps, T_OPEN))
        o->open = true;
}

static void shape_body(pp_state *ps, iris_object *o, int kw, const pp_token *at)
{
    switch (kw) {
    case T_SPHERE:
        o->u.sphere.centre = pp_vector(ps); comma(ps);
        o->u.sphere.radius = pp_float(ps);
        break;
    case T_BOX:
        /* an infinite corner: POV-Ray's rays leave the box at
        ** BOUND_HUGE (box.cpp's tmax), iris's at POV_MAX_DISTANCE */
        o->u.box.lo = pp_vector_clamped(ps, POV_MAX_DISTANCE); comma(ps);
        o->u.box.hi = pp_vector_clamped(ps, POV_MAX_DISTANCE);
        break;
    case T_PLANE:
        o->u.plane.normal = pp_vector(ps); comma(ps);
        o->u.plane.distance = pp_float(ps);
        if (v3_len(o->u.plane.normal) == 0)
            pp_error(ps, at, "plane with a zero normal");
        break;
    case T_CYLINDER:
        o->u.cylinder.base = pp_vector(ps); comma(ps);
        o->u.cylinder.cap = pp_vector(ps); comma(ps);
        o->u.cylinder.radius = pp_float(ps);
        closed_or_open(ps, o);
        break;
    case T_CONE:
        o->u.cone.base = pp_vector(ps); comma(ps);
        o->u.cone.base_radius = pp_float(ps); comma(ps);
        o->u.cone.cap = pp_vector(ps); comma(ps);
        o->u.cone.cap_radius = pp_float(ps);
        closed_or_open(ps, o);
        break;
    case T_TORUS:
        o->u.torus.major = pp_float(ps); comma(ps);
        o->u.torus.minor = pp_float(ps);
        break;
    case T_DISC:
        o->u.disc.centre = pp_vector(ps); comma(ps);
        o->u.disc.normal = pp_vector(ps); comma(ps);
        o->u.disc.radius = pp_float(ps);
        /* POV-Ray: an optional comma, then a hole radius if a float
        ** follows ('disc { C N 1 0.5 }' has a hole too) */
        if (pp_accept(ps, T_COMMA) || next_is_float(ps))
            o->u.disc.hole_radius = pp_float(ps);
        break;
    case T_TRIANGLE: case T_SMOOTH_TRIANGLE: {
        bool smooth = kw == T_SMOOTH_TRIANGLE;
        o->u.triangle.smooth = smooth;
        for (int i = 0; i < 3; i++) {
            if (i)
                pp_accept(ps, T_COMMA);
            o->u.triangle.p[i] = pp_vector(ps);
            if (smooth) {
                pp_accept(ps, T_COMMA);
                o->u.triangle.n[i] = pp_vector(ps);
            }
        }
        break;
    }
    case T_MESH: mesh1(ps, o); mesh1_finish(ps, o); break;
    case T_MESH2: mesh2(ps, o); break;
    case T_POLYGON: {
        int n = count(ps, MAX_ITEMS, "polygon point");
        o->u.polygon.n_points = n;
        o->u.polygon.points = pp_alloc(ps, (size_t)(n ? n : 1) * sizeof(iris_vec3));
        for (int i = 0; i < n; i++) {
            pp_accept(ps, T_COMMA);
            o->u.polygon.points[i] = pp_vector(ps);
        }
        break;
    }
    case T_PRISM: {
        o->u.prism.spline = IRIS_SPLINE_LINEAR;
        for (;;) {
            pp_next(ps);
            int s = spline_kw(ps->tok.kind);
            if (s >= 0)
                o->u.prism.spline = s;
            else if (ps->tok.kind == T_LINEAR_SWEEP)
                o->u.prism.sweep = 0;
            else if (ps->tok.kind == T_CONIC_SWEEP)
                o->u.prism.sweep = 1;
            else
                break;
        }
        pp_unget(ps);
        o->u.prism.height1 = pp_float(ps); comma(ps);
        o->u.prism.height2 = pp_float(ps); comma(ps);
        int n = count(ps, MAX_ITEMS, "prism point");
        o->u.prism.n_points = n;
        o->u.prism.points = points2(ps, n);
        closed_or_open(ps, o);
        break;
    }
    case T_LATHE: case T_SOR: {
        o->u.lathe.spline = kw == T_SOR ? IRIS_SPLINE_CUBIC : IRIS_SPLINE_LINEAR;
        for (;;) {
            pp_next(ps);
            int s = spline_kw(ps->tok.kind);
            if (s < 0)
                break;
            o->u.lathe.spline = s;
        }
        pp_unget(ps);
        int n = count(ps, MAX_ITEMS, "point");
        o->u.lathe.n_points = n;
        o->u.lathe.points = points2(ps, n);
        if (kw == T_SOR)
            closed_or_open(ps, o);
        break;
    }
    case T_SUPERELLIPSOID: {
        iris_vec2 en = pp_vector2(ps);
        o->u.superellipsoid.e = en.u;
        o->u.superellipsoid.n = en.v;
        break;
    }
    case T_BLOB: blob(ps, o); break;
    case T_HEIGHT_FIELD: {
        pp_next(ps);
        if (ps->tok.kind == T_FUNCTION) {
            o->u.height_field.fn_res_x = pp_int(ps); comma(ps);
            o->u.height_field.fn_res_y = pp_int(ps);
            iris_fn *fn = pp_function(ps);
            /* POV-Ray stores a pigment function as a 16-bit colour image
            ** and takes its heights from Greyscale() (imageutil.cpp's
            ** image_height_at), not from the red component. */
            if (fn->n_results == 5 && fn->n_code == 1 && fn->code[0].pigment)
                fn->code[0].arg = 5;
            o->u.height_field.fn = fn;
        } else {
            pp_unget(ps);
            iris_image_ref *img = pp_alloc(ps, sizeof *img);
            pp_next(ps);
            if (ps->tok.kind == T_IDENT && ps->tok.val.kind == V_FUNCTION)
                pp_error(ps, &ps->tok, "height_field from a function "
                         "identifier: write function W, H { F(x,y,0) }");
            const char *const *exts = pp_image_exts(ps->tok.kind);
            if (ps->tok.kind < T_KW_FIRST)
                pp_unget(ps);
            pp_token st = ps->tok;
            pp_next(ps);
            st = ps->tok;
            pp_unget(ps);
            const char *name = pp_string(ps);
            img->path = pp_require_file(ps, &st, name, exts, "image file");
            o->u.height_field.image = img;
        }
        for (;;) {
            pp_next(ps);
            if (ps->tok.kind == T_SMOOTH)
                o->u.height_field.smooth = true;
            else if (ps->tok.kind == T_WATER_LEVEL)
                o->u.height_field.water_level = pp_float(ps);
            else if (ps->tok.kind == T_HIERARCHY || ps->tok.kind == T_GAMMA ||
                     ps->tok.kind == T_PREMULTIPLIED)
                pp_bool_opt(ps);
            else
                break;
        }
        pp_unget(ps);
        break;
    }
    case T_TEXT: {
        pp_next(ps);
        if (ps->tok.kind == T_INTERNAL) {
            /* POV-Ray's built-in fonts are copies of the four it ships
            ** (fileutil.cpp): 1 timrom, 2 cyrvetic, 3 crystal, any other
            ** number povlogo; iris reads the installed files */
            static const char *const internal[] = {
                "povlogo.ttf", "timrom.ttf", "cyrvetic.ttf", "crystal.ttf" };
            pp_next(ps);
            pp_token kt = ps->tok;
            pp_unget(ps);
            double k = pp_float(ps);
            int id = k >= 1 && k < 4 ? (int)k : 0;
            o->u.text.font = pp_find_file(ps, &kt, internal[id]);
        } else {
            if (ps->tok.kind != T_TTF)
                pp_unget(ps);
            pp_next(ps);
            pp_token ft = ps->tok;
            pp_unget(ps);
            const char *font = pp_string(ps);
            static const char *const ttf_ext[] = { ".ttf", ".TTF", NULL };
            o->u.text.font = pp_require_file(ps, &ft, font, ttf_ext,
                                             "font file");
        }
        pp_accept(ps, T_COMMA);
        {
            const char *str = pp_string(ps);
            o->u.text.string = pp_strdup(ps, str, strlen(str));
        }
        pp_accept(ps, T_COMMA);
        o->u.text.thickness = pp_float(ps);
        pp_accept(ps, T_COMMA);
        o->u.text.offset = pp_vector(ps);
        break;
    }
    case T_ISOSURFACE: isosurface(ps, o); break;
    case T_QUADRIC: {
        iris_vec3 a = pp_vector(ps); comma(ps);
        iris_vec3 b = pp_vector(ps); comma(ps);
        iris_vec3 c = pp_vector(ps); comma(ps);
        double j = pp_float(ps);
        double *k = pp_alloc(ps, 10 * sizeof *k);
        k[0] = a.x; k[1] = a.y; k[2] = a.z; k[3] = b.x; k[4] = b.y;
        k[5] = b.z; k[6] = c.x; k[7] = c.y; k[8] = c.z; k[9] = j;
        o->u.poly.order = 2;
        o->u.poly.n_coeffs = 10;
        o->u.poly.coeffs = k;
        break;
    }
    case T_POLY: case T_CUBIC: case T_QUARTIC: {
        int order = kw == T_CUBIC ? 3 : kw == T_QUARTIC ? 4 : 0;
        if (kw == T_POLY) {
            pp_token ot = ps->tok;
            order = pp_int(ps);
            if (order < 2 || order > 15)
                pp_error(ps, &ot, "poly order must be 2..15");
            comma(ps);
        }
        int n = (order + 1) * (order + 2) * (order + 3) / 6;
        o->u.poly.order = order;
        o->u.poly.n_coeffs = n;
        o->u.poly.coeffs = coeffs(ps, n);
        break;
    }
    case T_JULIA_FRACTAL: {
        double v[4];
        pp_vector4(ps, v);
        memcpy(o->u.julia.data, v, sizeof v);
        o->u.julia.iterations = 20;
        o->u.julia.precision = 20;
        o->u.julia.slice = v3(0, 0, 0);
        for (;;) {
            pp_next(ps);
            pp_token jt = ps->tok;
            switch (jt.kind) {
            case T_QUATERNION: o->u.julia.type = 0; continue;
            case T_HYPERCOMPLEX: o->u.julia.type = 1; continue;
            case T_SQR: o->u.julia.fn = IRIS_JULIA_SQR; continue;
            case T_CUBE: o->u.julia.fn = IRIS_JULIA_CUBE; continue;
            case T_EXP: o->u.julia.fn = IRIS_JULIA_EXP; continue;
            case T_RECIPROCAL: o->u.julia.fn = IRIS_JULIA_RECIPROCAL; continue;
            case T_SIN: o->u.julia.fn = IRIS_JULIA_SIN; continue;
            case T_ASIN: o->u.julia.fn = IRIS_JULIA_ASIN; continue;
            case T_SINH: o->u.julia.fn = IRIS_JULIA_SINH; continue;
            case T_ASINH: o->u.julia.fn = IRIS_JULIA_ASINH; continue;
            case T_COS: o->u.julia.fn = IRIS_JULIA_COS; continue;
            case T_ACOS: o->u.julia.fn = IRIS_JULIA_ACOS; continue;
            case T_COSH: o->u.julia.fn = IRIS_JULIA_COSH; continue;
            case T_ACOSH: o->u.julia.fn = IRIS_JULIA_ACOSH; continue;
            case T_TAN: o->u.julia.fn = IRIS_JULIA_TAN; continue;
            case T_ATAN: o->u.julia.fn = IRIS_JULIA_ATAN; continue;
            case T_TANH: o->u.julia.fn = IRIS_JULIA_TANH; continue;
            case T_ATANH: o->u.julia.fn = IRIS_JULIA_ATANH; continue;
            case T_LN: o->u.julia.fn = IRIS_JULIA_LN; continue;
            case T_PWR: {
                /* pwr(x, y): the exponent, kept in data[6..7] */
                o->u.julia.fn = IRIS_JULIA_PWR;
                pp_expect(ps, T_LPAREN, "'('");
                o->u.julia.data[6] = pp_float(ps);
                comma(ps);
                o->u.julia.data[7] = pp_float(ps);
                pp_expect(ps, T_RPAREN, "')'");
                continue;
            }
            case T_MAX_ITERATION: o->u.julia.iterations = pp_int(ps); continue;
            case T_PRECISION: o->u.julia.precision = pp_float(ps); continue;
            case T_SLICE: {
                double s[4];
                pp_vector4(ps, s);
                o->u.julia.slice = v3(s[0], s[1], s[2]);
                o->u.julia.data[5] = s[3];
                comma(ps);
                o->u.julia.distance = pp_float(ps);
                continue;
            }
            default:
                pp_unget(ps);
                break;
            }
            break;
        }
        break;
    }
    case T_BICUBIC_PATCH: {
        /* POV-Ray's default is 0 steps: one cell of two triangles
        ** unless u_steps/v_steps are given */
        o->u.bicubic.u_steps = o->u.bicubic.v_steps = 0;
        for (;;) {
            pp_next(ps);
            if (ps->tok.kind == T_TYPE)
                o->u.bicubic.type = pp_int(ps);
            else if (ps->tok.kind == T_FLATNESS)
                o->u.bicubic.flatness = pp_float(ps);
            else if (ps->tok.kind == T_U_STEPS)
                o->u.bicubic.u_steps = pp_int(ps);
            else if (ps->tok.kind == T_V_STEPS)
                o->u.bicubic.v_steps = pp_int(ps);
            else if (ps->tok.kind == T_ACCURACY)
                pp_float(ps);
            else if (ps->tok.kind == T_UV_VECTORS) {
                /* the texture uv of the four corners; only uv_mapping
                ** would use them, and iris keeps the patch's own uv */
                for (int k = 0; k < 4; k++) {
                    pp_accept(ps, T_COMMA);
                    pp_vector2(ps);
                }
            } else
                break;
        }
        pp_unget(ps);
        for (int i = 0; i < 16; i++) {
            pp_accept(ps, T_COMMA);
            o->u.bicubic.points[i] = pp_vector(ps);
        }
        break;
    }
    case T_PARAMETRIC: {
        pp_expect(ps, T_FUNCTION, "function");
        o->u.parametric.fx = pp_function(ps);
        pp_accept(ps, T_COMMA);
        pp_expect(ps, T_FUNCTION, "function");
        o->u.parametric.fy = pp_function(ps);
        pp_accept(ps, T_COMMA);
        pp_expect(ps, T_FUNCTION, "function");
        o->u.parametric.fz = pp_function(ps);
        o->u.parametric.uv_lo = pp_vector2(ps); comma(ps);
        o->u.parametric.uv_hi = pp_vector2(ps);
        for (;;) {
            pp_next(ps);
            if (ps->tok.kind == T_CONTAINED_BY) {
                /* POV-Ray's Parse_Parametric takes both forms */
                contained_by(ps, &o->u.parametric.contained_kind,
                             &o->u.parametric.lo, &o->u.parametric.hi,
                             &o->u.parametric.centre,
                             &o->u.parametric.radius);
            } else if (ps->tok.kind == T_MAX_GRADIENT) {
                o->u.parametric.max_gradient = pp_float(ps);
            } else if (ps->tok.kind == T_ACCURACY) {
                o->u.parametric.accuracy = pp_float(ps);
            } else if (ps->tok.kind == T_PRECOMPUTE) {
                /* precompute DEPTH [,] [x] [,] [y] [,] [z] (POV-Ray 3.7;
                ** a bracketed list is accepted too). The bounds POV-Ray
                ** precomputes are those of the finest level merged
                ** upwards, tighter than a coarse cell's own: they change
                ** the image (geometry/parametric.c). */
                pp_token pat = ps->tok;
                double depth = pp_float(ps);
                if (!(depth >= 1 && depth <= 20))
                    pp_error(ps, &pat, "precompute depth must be 1 to 20");
                o->u.parametric.precompute_depth = (int)depth;
                pp_accept(ps, T_COMMA);
                if (pp_accept(ps, T_LBRACKET)) {
                    while (!pp_accept(ps, T_RBRACKET))
                        pp_next(ps);
                } else {
                    for (int k = 0; k < 3; k++) {
                        pp_accept(ps, T_COMMA);
                        if (pp_accept(ps, T_X))
                            o->u.parametric.precompute_axes |= 1;
                        else if (pp_accept(ps, T_Y))
                            o->u.parametric.precompute_axes |= 2;
                        else if (pp_accept(ps, T_Z))
                            o->u.parametric.precompute_axes |= 4;
                        else
                            break;
                    }
                }
            } else {
                break;
            }
        }
        pp_unget(ps);
        break;
    }
    case T_SPHERE_SWEEP: {
        pp_next(ps);
        int sp = ps->tok.kind == T_LINEAR_SPLINE ? 0 :
                 ps->tok.kind == T_B_SPLINE ? 1 :
                 ps->tok.kind == T_CUBIC_SPLINE ? 2 : -1;
        if (sp < 0)
            pp_error(ps, &ps->tok, "expected linear_spline, b_spline or "
                     "cubic_spline");
        o->u.sphere_sweep.spline = sp;
        int n = count(ps, MAX_ITEMS, "sphere");
        o->u.sphere_sweep.n_spheres = n;
        o->u.sphere_sweep.centres = pp_alloc(ps, (size_t)(n ? n : 1) * sizeof(iris_vec3));
        o->u.sphere_sweep.radii = pp_alloc(ps, (size_t)(n ? n : 1) * sizeof(double));
        for (int i = 0; i < n; i++) {
            pp_accept(ps, T_COMMA);
            o->u.sphere_sweep.centres[i] = pp_vector(ps);
            pp_accept(ps, T_COMMA);
            o->u.sphere_sweep.radii[i] = pp_float(ps);
        }
        /* directives first, as POV-Ray reads on: '... #if (C) tolerance
        ** 0.01 #end' */
        if (pp_accept_in_list(ps, T_TOLERANCE))
            pp_float(ps);
        break;
    }
    case T_OVUS:
        o->u.ovus.r1 = pp_float(ps); comma(ps);
        o->u.ovus.r2 = pp_float(ps);
        break;
    default:
        break;
    }
}

static int shape_kind(int kw)
{
    switch (kw) {
    case T_SPHERE: return IRIS_OBJ_SPHERE;
    case T_BOX: return IRIS_OBJ_BOX;
    case T_PLANE: return IRIS_OBJ_PLANE;
    case T_CYLINDER: return IRIS_OBJ_CYLINDER;
    case T_CONE: return IRIS_OBJ_CONE;
    case T_TORUS: return IRIS_OBJ_TORUS;
    case T_DISC: return IRIS_OBJ_DISC;
    case T_TRIANGLE: case T_SMOOTH_TRIANGLE: return IRIS_OBJ_TRIANGLE;
    case T_MESH: case T_MESH2: return IRIS_OBJ_MESH;
    case T_POLYGON: return IRIS_OBJ_POLYGON;
    case T_PRISM: return IRIS_OBJ_PRISM;
    case T_LATHE: return IRIS_OBJ_LATHE;
    case T_SOR: return IRIS_OBJ_SOR;
    case T_SUPERELLIPSOID: return IRIS_OBJ_SUPERELLIPSOID;
    case T_BLOB: return IRIS_OBJ_BLOB;
    case T_HEIGHT_FIELD: return IRIS_OBJ_HEIGHT_FIELD;
    case T_TEXT: return IRIS_OBJ_TEXT;
    case T_ISOSURFACE: return IRIS_OBJ_ISOSURFACE;
    case T_QUADRIC: return IRIS_OBJ_QUADRIC;
    case T_POLY: case T_CUBIC: case T_QUARTIC: return IRIS_OBJ_POLY;
    case T_JULIA_FRACTAL: return IRIS_OBJ_JULIA_FRACTAL;
    case T_BICUBIC_PATCH: return IRIS_OBJ_BICUBIC_PATCH;
    case T_PARAMETRIC: return IRIS_OBJ_PARAMETRIC;
    case T_SPHERE_SWEEP: return IRIS_OBJ_SPHERE_SWEEP;
    case T_OVUS: return IRIS_OBJ_OVUS;
    case T_UNION: return IRIS_OBJ_UNION;
    case T_MERGE: return IRIS_OBJ_MERGE;
    case T_INTERSECTION: return IRIS_OBJ_INTERSECTION;
    case T_DIFFERENCE: return IRIS_OBJ_DIFFERENCE;
    case T_LIGHT_GROUP: return IRIS_OBJ_LIGHT_GROUP;
    default: return -1;
    }
}

bool pp_starts_object(pp_state *ps)
{
    pp_next(ps);
    int k = ps->tok.kind;
    pp_unget(ps);
    return shape_kind(k) >= 0 || k == T_OBJECT;
}

/* The CSG's own box once its children are read (pp_obj.has_box); left
** unset when a child is one the parser cannot bound. */
static void csg_box(iris_object *o)
{
    pp_obj *po = (pp_obj *)o;
    vec3 lo, hi;
    if (!po->has_box && o->kind != IRIS_OBJ_LIGHT_GROUP &&
        o->u.csg.n_children > 0 && pp_object_bounds(o, &lo, &hi)) {
        po->box_lo = lo;
        po->box_hi = hi;
        po->has_box = true;
    }
}

/* CSG body: objects and light sources, then modifiers. */
static void csg_body(pp_state *ps, iris_object *o, const pp_token *open)
{
    int cap = 0;
    for (;;) {
        pp_next(ps);
        pp_token at = ps->tok;
        if (at.kind == T_RBRACE)
            break;
        if (at.kind == T_LIGHT_SOURCE) {
            add_light_to(ps, o, pp_light(ps));
            continue;
        }
        if (at.kind == T_GLOBAL_LIGHTS && o->kind == IRIS_OBJ_LIGHT_GROUP) {
            ((pp_obj *)o)->global_lights = pp_bool_opt(ps);
            continue;
        }
        if (at.kind == T_IDENT && at.val.kind == V_LIGHT) {
            add_light_to(ps, o, light_copy(ps, at.val.u.light));
            continue;
        }
        if (shape_kind(at.kind) >= 0 || at.kind == T_OBJECT ||
            (at.kind == T_IDENT && at.val.kind == V_OBJECT)) {
            pp_unget(ps);
            iris_object *c = pp_object(ps);
            /* a light_source referenced by object{} comes back as NULL
            ** after being attached as a light */
            if (c)
                csg_add(ps, o, c, &cap);
            continue;
        }
        csg_box(o); /* before the first modifier, as POV-Ray */
        if (object_mod(ps, o))
            continue;
        char buf[80];
        if (at.kind == T_EOF)
            pp_error(ps, open, "CSG without its closing '}'");
        if (at.kind == T_IDENT)
            pp_unexpected(ps, &at, lex_keyword_name(open->kind));
        pp_error(ps, &at, "unexpected %s in CSG (opened at line %u)",
                 pp_tok_name(ps, &at, buf, sizeof buf), pp_loc(ps, open).line);
    }
    csg_box(o);
    if (o->kind == IRIS_OBJ_DIFFERENCE || o->kind == IRIS_OBJ_INTERSECTION) {
        if (o->u.csg.n_children < 1)
            pp_warning(ps, open, "CSG with no objects");
    }
}

/*
** object: OBJECT_IDENTIFIER | LIGHT_IDENTIFIER | 'object' '{' ... '}'
**       | SHAPE '{' ... '}' | CSG '{' ... '}'
** A bare identifier is a copy of the declared object without modifiers,
** as POV-Ray's Parse_Object (OBJECT_ID_TOKEN): 'Floor' alone in the scene,
** a CSG's children, clipped_by { Box }. A declared light_source is an
** object there too; it comes back wrapped in an empty union, as from
** object { Light }.
*/
iris_object *pp_object(pp_state *ps)
{
    pp_next(ps);
    pp_token at = ps->tok;
    int kw = at.kind;
    if (kw == T_IDENT && at.val.kind == V_OBJECT)
        return pp_object_copy(ps, at.val.u.obj);
    if (kw == T_IDENT && at.val.kind == V_LIGHT) {
        iris_object *o = obj_new(ps, IRIS_OBJ_UNION, &at);
        add_light_to(ps, o, light_copy(ps, at.val.u.light));
        return o;
    }
    if (kw == T_OBJECT) {
        pp_expect(ps, T_LBRACE, "'{' after object");
        pp_next(ps);
        pp_token id = ps->tok;
        iris_object *o = NULL;
        if (id.kind == T_IDENT && id.val.kind == V_OBJECT) {
            o = pp_object_copy(ps, id.val.u.obj);
        } else if (id.kind == T_IDENT && id.val.kind == V_LIGHT) {
            /* object { Light mods }: a light wrapped in an empty union */
            o = obj_new(ps, IRIS_OBJ_UNION, &at);
            add_light_to(ps, o, light_copy(ps, id.val.u.light));
        } else if (shape_kind(id.kind) >= 0 || id.kind == T_OBJECT) {
            pp_unget(ps);
            pp_enter(ps, &at);
            o = pp_object(ps);
            pp_leave(ps);
        } else if (id.kind == T_LIGHT_SOURCE) {
            o = obj_new(ps, IRIS_OBJ_UNION, &at);
            add_light_to(ps, o, pp_light(ps));
        } else {
            char buf[80];
            if (id.kind == T_IDENT && id.val.kind == V_NONE)
                pp_error(ps, &id, "undeclared identifier '%.*s'",
                         (int)id.len, pp_tok_text(ps, &id));
            pp_error(ps, &id, "expected an object identifier or an object "
                     "in object{}, found %s",
                     pp_tok_name(ps, &id, buf, sizeof buf));
        }
        object_mods(ps, o, &at, "object");
        return o;
    }
    int kind = shape_kind(kw);
    if (kind < 0) {
        pp_unget(ps);
        return NULL;
    }
    pp_token open = at;
    pp_expect(ps, T_LBRACE, "'{'");
    if (kind != IRIS_OBJ_LIGHT_GROUP) {
        /* SHAPE { OBJECT_ID mods }: a copy of the identifier, as POV-Ray's
        ** Parse_Object_Id (mesh { camera_mesh ... } in the mesh_camera
        ** demos). A CSG does the same (Parse_CSG): union { Id mods } is
        ** the copy itself, not a union around it. */
        pp_next(ps);
        pp_token id = ps->tok;
        if (id.kind == T_IDENT && id.val.kind == V_OBJECT) {
            iris_object *c = pp_object_copy(ps, id.val.u.obj);
            object_mods(ps, c, &at, lex_keyword_name(kw));
            return c;
        }
        pp_unget(ps);
    }
    iris_object *o = obj_new(ps, kind, &at);
    if (kind >= IRIS_OBJ_UNION) {
        if (kind == IRIS_OBJ_LIGHT_GROUP)
            ((pp_obj *)o)->is_light_group = true;
        pp_enter(ps, &at);
        csg_body(ps, o, &open);
        pp_leave(ps);
        return o;
    }
    /* object identifiers may stand for the shape in some POV-Ray forms;
    ** here the shape's parameters always come first */
    shape_body(ps, o, kw, &at);
    object_mods(ps, o, &open, lex_keyword_name(kw));
    return o;
}

/* ---- finishing top-level objects --------------------------------- */

/* The lights of light_group 'o' (POV-Ray's Promote_Local_Lights): its
** own and, in a nested group, those of the groups around it (already in
** o's range, from its parent), copied to one new range of the scene's
** group lights that every object in the group gets. Its objects see the
** scene's lights only with 'global_lights on' (3.7's default is off). */
static void light_group_lights(pp_state *ps, iris_object *o)
{
    int first = ps->scene->n_group_lights, n = 0;
    for (pp_light_node *l = ((pp_obj *)o)->lights; l; l = l->next, n++)
        pp_add_group_light(ps, l->light);
    for (int i = 0; i < o->light_group_count; i++, n++)
        pp_add_group_light(ps,
                           ps->scene->group_lights[o->light_group_first + i]);
    o->light_group_first = first;
    o->light_group_count = n;
    o->no_global_lights = !((pp_obj *)o)->global_lights;
}

/* cutaway_textures: in POV-Ray an untextured part of a difference takes,
** where it is hit, the texture of the difference's first object if that
** object contains the point (CSG::Determine_Textures), instead of the
** default texture. Every visible point of a difference lies inside its
** first object, so when that object is a textured simple shape its texture
** is the answer everywhere, and the parser can hand it down. Returns NULL
** when the rule does not apply: no cutaway_textures, a texture on the
** difference or above it (that one is inherited as usual), or a first
** object that is itself a CSG or untextured (POV-Ray then looks inside it
** point by point; iris keeps the default texture there). Intersections
** average the textures of all their textured members in POV-Ray; not done. */
static iris_texture *cutaway_texture(const iris_object *o,
                                     const iris_texture *inherited)
{
    if (!((const pp_obj *)o)->cutaway || inherited ||
        o->kind != IRIS_OBJ_DIFFERENCE || o->u.csg.n_children < 2)
        return NULL;
    const iris_object *first = o->u.csg.children[0];
    return is_csg(first) ? NULL : first->texture;
}

static void finalize(pp_state *ps, iris_object *o, iris_texture *tex,
                     iris_interior *inter, const iris_object *parent)
{
    if (parent) {
        o->no_shadow |= parent->no_shadow;
        o->no_image |= parent->no_image;
        o->no_reflection |= parent->no_reflection;
        o->double_illuminate |= parent->double_illuminate;
        o->hollow |= parent->hollow;
        /* POV-Ray's Post_Process: a target's children are targets with
        ** its spacing, their own 'target S' overridden (each child of a
        ** split union is shot at with it: src/photon/targets.c); the
        ** parent's reflection/refraction on or off overrides theirs */
        if (parent->photon_target) {
            o->photon_target = true;
            o->photon_density = parent->photon_density;
            o->photon_target_loc = parent->photon_target_loc;
        }
        o->photon_pass_through |= parent->photon_pass_through;
        if (parent->photon_refraction != IRIS_UNSET)
            o->photon_refraction = parent->photon_refraction;
        if (parent->photon_reflection != IRIS_UNSET)
            o->photon_reflection = parent->photon_reflection;
        if (!parent->photon_collect)
            o->photon_collect = false;
        o->light_group_first = parent->light_group_first;
        o->light_group_count = parent->light_group_count;
        o->no_global_lights = parent->no_global_lights;
        /* POV-Ray promotes the importance to children without their own
        ** (the parent's, else the #default's at this point) */
        if (!(o->radiosity_importance > 0.0))
            o->radiosity_importance =
                parent->radiosity_importance > 0.0
                    ? parent->radiosity_importance
                    : ps->scene->settings.rad_default_importance;
    }
    if (((pp_obj *)o)->is_light_group)
        light_group_lights(ps, o);
    iris_texture *t = o->texture ? o->texture : tex;
    iris_interior *in = o->interior ? o->interior : inter;
    if (o->interior == NULL && in)
        o->interior = in;
    if (is_csg(o)) {
        own_children(ps, o);
        iris_texture *cut = cutaway_texture(o, t);
        for (int i = 0; i < o->u.csg.n_children; i++)
            finalize(ps, o->u.csg.children[i], i > 0 && cut ? cut : t, in, o);
    } else if (!o->texture) {
        o->texture = t ? t : pp_default_texture(ps);
    }
    for (int i = 0; i < o->n_clipped_by; i++)
        finalize(ps, o->clipped_by[i], o->texture, NULL, NULL);
    if (o->bounded_by)
        finalize(ps, o->bounded_by, o->texture, NULL, NULL);
    /* Legacy finish{ior}: promoted to the interior as POV-Ray does. */
    if (!is_csg(o) && o->texture && o->texture->finish &&
        o->texture->finish->legacy_ior > 0 &&
        (!o->interior || o->interior->ior == 0)) {
        iris_interior *ni = pp_alloc(ps, sizeof *ni);
        if (o->interior)
            *ni = *o->interior;
        else
            iris_interior_defaults(ni);
        ni->ior = o->texture->finish->legacy_ior;
        o->interior = ni;
    }
    /* Lights inside CSG become scene lights (a light_group's light only
    ** its objects, above). */
    if (!((pp_obj *)o)->is_light_group)
        for (pp_light_node *l = ((pp_obj *)o)->lights; l; l = l->next)
            pp_add_light(ps, l->light);
}

void pp_finalize_object(pp_state *ps, iris_object *o)
{
    finalize(ps, o, NULL, NULL, NULL);
}

/* Drops the light_sources a CSG copy carries (recursively): a copy made
** for a geometry query must not add lights to the scene. */
static void strip_lights(pp_state *ps, iris_object *o)
{
    ((pp_obj *)o)->lights = NULL;
    if (is_csg(o)) {
        own_children(ps, o);
        for (int i = 0; i < o->u.csg.n_children; i++)
            strip_lights(ps, o->u.csg.children[i]);
    }
}

const iris_object *pp_query_object(pp_state *ps, const iris_object *o)
{
    for (int i = 0; i < PP_QUERY_CACHE; i++)
        if (ps->query_src[i] == o && ps->query_obj[i])
            return ps->query_obj[i];
    iris_object *c = pp_object_copy(ps, o);
    strip_lights(ps, c);
    finalize(ps, c, NULL, NULL, NULL);
    int slot = ps->query_next++ % PP_QUERY_CACHE;
    ps->query_src[slot] = o;
    ps->query_obj[slot] = c;
    return c;
}
