/* SPDX-License-Identifier: MIT */
/*
** scene.c: the top level of a scene file: camera (resolved in POV-Ray's
** fixed order), objects, lights, global_settings, background, sky_sphere
** and fog.
*/
#include "config.h"

#include <math.h>
#include <string.h>

#include "math/vec3.h"
#include "pp.h"

void pp_add_object(pp_state *ps, iris_object *o)
{
    iris_scene *sc = ps->scene;
    if (sc->n_objects == ps->cap_objects) {
        int cap = ps->cap_objects ? ps->cap_objects * 2 : 16;
        iris_object **a = pp_alloc(ps, (size_t)cap * sizeof *a);
        if (sc->n_objects)
            memcpy(a, sc->objects, (size_t)sc->n_objects * sizeof *a);
        sc->objects = a;
        ps->cap_objects = cap;
    }
    sc->objects[sc->n_objects++] = o;
}

void pp_add_light(pp_state *ps, iris_light *l)
{
    iris_scene *sc = ps->scene;
    if (sc->n_lights == ps->cap_lights) {
        int cap = ps->cap_lights ? ps->cap_lights * 2 : 8;
        iris_light **a = pp_alloc(ps, (size_t)cap * sizeof *a);
        if (sc->n_lights)
            memcpy(a, sc->lights, (size_t)sc->n_lights * sizeof *a);
        sc->lights = a;
        ps->cap_lights = cap;
    }
    sc->lights[sc->n_lights++] = l;
}

int pp_add_group_light(pp_state *ps, iris_light *l)
{
    iris_scene *sc = ps->scene;
    if (sc->n_group_lights == ps->cap_group_lights) {
        int cap = ps->cap_group_lights ? ps->cap_group_lights * 2 : 8;
        iris_light **a = pp_alloc(ps, (size_t)cap * sizeof *a);
        if (sc->n_group_lights)
            memcpy(a, sc->group_lights,
                   (size_t)sc->n_group_lights * sizeof *a);
        sc->group_lights = a;
        ps->cap_group_lights = cap;
    }
    sc->group_lights[sc->n_group_lights] = l;
    return sc->n_group_lights++;
}

static void add_fog(pp_state *ps, iris_fog *f)
{
    iris_scene *sc = ps->scene;
    if (sc->n_fogs == ps->cap_fogs) {
        int cap = ps->cap_fogs ? ps->cap_fogs * 2 : 4;
        iris_fog **a = pp_alloc(ps, (size_t)cap * sizeof *a);
        if (sc->n_fogs)
            memcpy(a, sc->fogs, (size_t)sc->n_fogs * sizeof *a);
        sc->fogs = a;
        ps->cap_fogs = cap;
    }
    sc->fogs[sc->n_fogs++] = f;
}

/* camera { [CAMERA_ID] [type] items... transforms... }
** Items are applied in POV-Ray's order whatever order they are written
** in: right, direction, angle, up, sky, location, look_at; then the
** transforms (semantics §3.8). */
/*
** mesh_camera { RAYS_PER_PIXEL DISTRIBUTION [MAX_DISTANCE]
**               (mesh {...} | mesh2 {...})+ [smooth] }
** POV-Ray's Parse_Mesh_Camera: rays_per_pixel >= 1, distribution 0..3,
** 2 and 3 with one ray per pixel, distribution 0 with at least as many
** meshes as rays, smooth only with distribution 3; no commas between
** the numbers (POV-Ray reads three floats). The meshes stay out
** of the scene (src/render/meshcam.c renders from them).
*/
static void mesh_camera(pp_state *ps, iris_camera *c, const pp_token *at)
{
    pp_expect(ps, T_LBRACE, "'{' after mesh_camera");
    c->kind = IRIS_CAM_MESH;
    c->mesh_rays_per_pixel = pp_int(ps);
    if (c->mesh_rays_per_pixel < 1)
        pp_error(ps, at, "mesh_camera rays per pixel must be at least 1");
    c->mesh_distribution = pp_int(ps);
    if (c->mesh_distribution < 0 || c->mesh_distribution > 3)
        pp_error(ps, at, "mesh_camera distribution type must be 0 to 3");
    if (c->mesh_distribution >= 2 && c->mesh_rays_per_pixel != 1)
        pp_error(ps, at, "mesh_camera rays per pixel must be 1 for "
                 "distribution 2 or 3");
    c->mesh_max_distance = 0;
    pp_next(ps);
    pp_unget(ps);
    if (pp_starts_expr(ps)) {
        pp_token dt = ps->tok;
        c->mesh_max_distance = pp_float(ps);
        /* POV-Ray ends the eye ray there; trace.c has one distance limit
        ** for all rays, so iris keeps that one and says so */
        if (c->mesh_max_distance > 0)
            pp_warning(ps, &dt, "mesh_camera maximum ray distance is not "
                       "rendered: eye rays are not cut short");
    }
    int n = 0, cap = 0;
    iris_object **meshes = NULL;
    for (;;) {
        pp_next(ps);
        pp_token ot = ps->tok;
        if (ot.kind != T_MESH && ot.kind != T_MESH2)
            break;
        pp_unget(ps);
        iris_object *o = pp_object(ps);
        if (!o || o->kind != IRIS_OBJ_MESH)
            pp_unexpected(ps, &ot, "mesh_camera");
        if (n == cap) {
            cap = cap ? cap * 2 : 4;
            iris_object **g = pp_alloc(ps, (size_t)cap * sizeof *g);
            for (int i = 0; i < n; i++)
                g[i] = meshes[i];
            meshes = g;
        }
        meshes[n++] = o;
    }
    c->mesh_smooth = ps->tok.kind == T_SMOOTH;
    if (c->mesh_smooth) {
        if (c->mesh_distribution != 3)
            pp_error(ps, &ps->tok, "mesh_camera smooth needs distribution 3");
        pp_next(ps);
    }
    if (ps->tok.kind != T_RBRACE)
        pp_unexpected(ps, &ps->tok, "mesh_camera");
    if (n == 0)
        pp_error(ps, at, "mesh_camera needs a mesh or mesh2");
    if (c->mesh_distribution == 0 && c->mesh_rays_per_pixel > n)
        pp_error(ps, at, "mesh_camera rays per pixel must not exceed the "
                 "number of meshes for distribution 0");
    if (c->mesh_distribution == 3) {
        if (n > 1)
            pp_warning(ps, at, "mesh_camera distribution 3 uses only the "
                       "first mesh");
        if (!meshes[0]->u.mesh.uvs || !meshes[0]->u.mesh.tri_uvs)
            pp_error(ps, at, "mesh_camera distribution 3 needs a mesh with "
                     "uv coordinates");
    }
    c->n_meshes = n;
    c->meshes = meshes;
}

iris_camera *pp_camera(pp_state *ps, const iris_camera *base)
{
    pp_token open = ps->tok;
    pp_expect(ps, T_LBRACE, "'{' after camera");
    iris_camera *c = pp_alloc(ps, sizeof *c);
    if (base)
        *c = *base;
    else
        iris_camera_defaults(c);
    c->loc = pp_loc(ps, &open);
    bool has_right = false, has_dir = false, has_angle = false;
    bool has_up = false, has_sky = false, has_loc = false, has_look = false;
    bool has_focal = false;
    /* copied from a declared camera (POV-Ray 3.5+ then takes only
    ** transforms: its Parse_Camera 'only_mods' path, no resizing) */
    bool copied = false;
    iris_vec3 right = c->right, dir = c->direction, up = c->up;
    iris_vec3 sky = c->sky, loc = c->location, look = c->look_at;
    double angle = 0;
    iris_transform xf;
    xf_identity(&xf);
    bool has_xf = false;
    pp_token look_tok = open, dir_tok = open;
    for (;;) {
        pp_next(ps);
        pp_token at = ps->tok;
        switch (at.kind) {
        case T_RBRACE:
            goto resolve;
        case T_IDENT:
            if (at.val.kind == V_CAMERA) {
                *c = *at.val.u.cam;
                right = c->right; dir = c->direction; up = c->up;
                sky = c->sky; loc = c->location; look = c->look_at;
                copied = true;
                break;
            }
            goto bad;
        case T_PERSPECTIVE: c->kind = IRIS_CAM_PERSPECTIVE; break;
        case T_ORTHOGRAPHIC: c->kind = IRIS_CAM_ORTHOGRAPHIC; break;
        case T_FISHEYE: c->kind = IRIS_CAM_FISHEYE; break;
        case T_ULTRA_WIDE_ANGLE: c->kind = IRIS_CAM_ULTRA_WIDE; break;
        case T_OMNIMAX: c->kind = IRIS_CAM_OMNIMAX; break;
        case T_PANORAMIC: c->kind = IRIS_CAM_PANORAMIC; break;
        case T_SPHERICAL: c->kind = IRIS_CAM_SPHERICAL; break;
        case T_CYLINDER:
            c->kind = IRIS_CAM_CYLINDER;
            c->cylinder_type = pp_int(ps);
            if (c->cylinder_type < 1 || c->cylinder_type > 4)
                pp_error(ps, &at, "cylinder camera type must be 1 to 4");
            break;
        case T_MESH_CAMERA:
            mesh_camera(ps, c, &at);
            break;
        case T_LOCATION: loc = pp_vector(ps); has_loc = true; break;
        case T_DIRECTION:
            dir = pp_vector(ps);
            has_dir = true;
            dir_tok = at;
            break;
        case T_RIGHT: right = pp_vector(ps); has_right = true; break;
        case T_UP: up = pp_vector(ps); has_up = true; break;
        case T_SKY: sky = pp_vector(ps); has_sky = true; break;
        case T_LOOK_AT: look = pp_vector(ps); has_look = true; look_tok = at; break;
        case T_ANGLE: {
            angle = pp_float(ps);
            has_angle = true;
            if (angle < 0)
                pp_error(ps, &at, "negative viewing angle");
            /* the spherical camera's optional vertical angle: 'angle H, V'
            ** or 'angle H V' (POV-Ray: an optional comma, then a float if
            ** one follows) */
            bool comma = pp_accept(ps, T_COMMA);
            bool more = comma;
            if (!comma && c->kind == IRIS_CAM_SPHERICAL &&
                !pp_next_is_directive(ps)) {
                pp_next(ps);
                more = pp_starts_expr(ps) && ps->tok.kind != T_LT;
                pp_unget(ps);
            }
            if (more) {
                pp_next(ps);
                pp_token vt = ps->tok;
                pp_unget(ps);
                double v = pp_float(ps);
                if (!(v >= 0))
                    pp_error(ps, &vt, "negative vertical camera angle");
                c->v_angle = v;
            }
            break;
        }
        case T_APERTURE: c->aperture = pp_float(ps); break;
        case T_BLUR_SAMPLES: {
            /* blur_samples [MIN,] MAX: one value is the maximum with no
            ** minimum (POV-Ray's Parse_Camera) */
            int first = pp_int(ps), second = 0;
            if (first <= 0)
                pp_error(ps, &at, "illegal number of focal blur samples");
            if (pp_accept(ps, T_COMMA) || pp_float_follows(ps))
                second = pp_int(ps); /* POV-Ray: 'blur_samples 4 16' too */
            if (second == 0) {
                c->blur_samples = first;
                c->blur_samples_min = 0;
            } else if (first > second) {
                pp_error(ps, &at, "focal blur samples minimum must not be "
                         "larger than maximum");
            } else {
                c->blur_samples = second;
                c->blur_samples_min = first;
            }
            /* The renderer keeps a table entry per sample and may trace
            ** them all per pixel: 'blur_samples 1e9' allocated 24 GB.
            ** POV-Ray has no limit; its examples use at most a few hundred */
            if (c->blur_samples > 65536)
                pp_error(ps, &at, "blur_samples %d out of range [1, 65536]",
                         c->blur_samples);
            break;
        }
        case T_FOCAL_POINT:
            c->focal_point = pp_vector(ps);
            has_focal = true;
            break;
        case T_CONFIDENCE: {
            double k = pp_float(ps);
            if (k > 0.0 && k < 1.0)
                c->confidence = k;
            else
                pp_warning(ps, &at, "illegal confidence value; the default "
                           "is used");
            break;
        }
        case T_VARIANCE: {
            double k = pp_float(ps);
            if (k >= 0.0 && k <= 1.0)
                c->variance = k;
            else
                pp_warning(ps, &at, "illegal variance value; the default "
                           "is used");
            break;
        }
        case T_BOKEH:
            pp_warn_once(ps, &at, T_BOKEH, "bokeh");
            pp_expect(ps, T_LBRACE, "'{'");
            pp_skip_block(ps);
            break;
        case T_NORMAL:
            c->normal = pp_normal(ps, c->normal);
            break;
        default: {
            iris_transform x;
            if (pp_transform_item(ps, &x)) {
                xf_compose(&xf, &xf, &x);
                has_xf = true;
                break;
            }
        }
        bad: {
            pp_unexpected(ps, &at, "camera");
        }
        }
    }
resolve:
    /* right, direction, angle, up, sky, location, look_at */
    c->right = right;
    c->direction = dir;
    if (has_angle) {
        /* POV-Ray's Parse_Camera: 180 or more is an error for the
        ** perspective and orthographic cameras; 0 leaves the direction
        ** as it is (users write 'angle 0' for "no angle") but still
        ** counts as an angle for the orthographic size below */
        if (!(angle < 180) && (c->kind == IRIS_CAM_PERSPECTIVE ||
                               c->kind == IRIS_CAM_ORTHOGRAPHIC))
            pp_error(ps, &open, "camera angle must be smaller than 180 "
                     "degrees");
        c->angle = angle;
        if ((c->kind == IRIS_CAM_PERSPECTIVE ||
             c->kind == IRIS_CAM_ORTHOGRAPHIC) && angle > 0) {
            double len = 0.5 * v3_len(c->right) / tan(angle * M_PI / 360);
            c->direction = v3_scale(v3_norm(c->direction), len);
        }
    }
    c->up = up;
    c->sky = sky;
    c->location = loc;
    if (has_look) {
        c->look_at = look;
        iris_vec3 d = v3_sub(look, c->location);
        if (v3_len(d) == 0)
            pp_error(ps, &look_tok, "look_at equals the camera location");
        double handed = v3_dot(v3_cross(c->up, c->direction), c->right);
        double dlen = v3_len(c->direction);
        iris_vec3 dn = v3_norm(d);
        iris_vec3 r = v3_cross(c->sky, dn);
        /* POV-Ray's test (parser.cpp Parse_Camera): every component of
        ** sky x direction below EPSILON (1e-10) keeps the right vector
        ** as given, and up is rebuilt from it as below */
        if (fabs(r.x) < 1e-10 && fabs(r.y) < 1e-10 && fabs(r.z) < 1e-10) {
            pp_warning(ps, &look_tok, "camera sky is parallel to the view "
                       "direction; the right vector is kept (as POV-Ray)");
            r = c->right;
        }
        double rlen = v3_len(c->right), ulen = v3_len(c->up);
        c->direction = v3_scale(dn, dlen);
        if (v3_len(r) > 0) {
            r = v3_norm(r);
            /* up = direction x right, not normalised (POV-Ray: only a
            ** right kept from the input can be off the perpendicular);
            ** only right carries handedness */
            c->up = v3_scale(v3_cross(dn, r), ulen);
            c->right = v3_scale(r, handed > 0 ? rlen : -rlen);
        }
    }
    /* orthographic cameras without explicit size (or with an angle) cover
    ** the view at the look_at point, also without a look_at: then the
    ** default one, <0, 0, 1>, or the copied camera's (POV-Ray's
    ** Parse_Camera; t-o-k's Icosahedron: location -24*z angle 15). A
    ** copy of a declared camera with nothing but transforms is not
    ** resized again: it was sized when it was declared (POV-Ray's
    ** 'only_mods' path; templates/Basic_Scenes/Orthographic_isometric.pov,
    ** 'camera { Camera_1 }', was 13 dB after the rule above took the
    ** default look_at into account) */
    bool only_copied = copied && !has_angle && !has_up && !has_right &&
                       !has_look && !has_dir && !has_loc;
    if (c->kind == IRIS_CAM_ORTHOGRAPHIC && !only_copied &&
        ((!has_up && !has_right) || has_angle)) {
        double k1 = v3_len(v3_sub(c->look_at, c->location));
        double k2 = v3_len(c->direction);
        if (k1 > 1e-10 && k2 > 1e-10) {
            c->right = v3_scale(c->right, k1 / k2);
            c->up = v3_scale(c->up, k1 / k2);
        }
    }
    /* POV-Ray renders a zero direction black without a word: say so */
    if (v3_len(c->direction) == 0 &&
        (c->kind == IRIS_CAM_PERSPECTIVE || c->kind == IRIS_CAM_ORTHOGRAPHIC))
        pp_warning(ps, &dir_tok, "camera direction has zero length: the "
                   "image will be black");
    /* the focal distance, before the camera's transforms as in POV-Ray:
    ** from focal_point when given, else kept from a camera this one
    ** copies, else the length of direction; 0 becomes 1 */
    if (has_focal)
        c->focal_distance = v3_len(v3_sub(c->focal_point, c->location));
    else if (c->focal_distance < 0)
        c->focal_distance = v3_len(c->direction);
    if (c->focal_distance == 0)
        c->focal_distance = 1;
    (void)has_dir; (void)has_sky; (void)has_loc;
    if (has_xf) {
        c->location = xf_point(&xf, c->location);
        c->direction = xf_dir(&xf, c->direction);
        c->right = xf_dir(&xf, c->right);
        c->up = xf_dir(&xf, c->up);
        c->sky = xf_dir(&xf, c->sky);
        c->look_at = xf_point(&xf, c->look_at);
        c->focal_point = xf_point(&xf, c->focal_point);
    }
    return c;
}

/*
** global_subsurface: 'subsurface' '{' { samples INT [','] INT |
**                                      radiosity BOOL } '}'
** POV-Ray 3.7's Parse_Global_Settings: the block switches subsurface
** light transport on (render/subsurface.h).
*/
static void global_subsurface(pp_state *ps, iris_global_settings *g)
{
    pp_expect(ps, T_LBRACE, "'{'");
    g->subsurface = true;
    for (;;) {
        pp_next(ps);
        pp_token at = ps->tok;
        switch (at.kind) {
        case T_RBRACE:
            return;
        case T_SAMPLES:
            g->sss_samples_diffuse = pp_int(ps);
            pp_accept(ps, T_COMMA);
            g->sss_samples_single = pp_int(ps);
            if (g->sss_samples_diffuse < 0 || g->sss_samples_single < 0 ||
                g->sss_samples_diffuse > 1000000 ||
                g->sss_samples_single > 1000000)
                pp_error(ps, &at, "subsurface samples must be in 0..1000000");
            break;
        case T_RADIOSITY:
            g->sss_radiosity = fabs(pp_float(ps)) >= 1.0; /* (int)v != 0 */
            if (g->sss_radiosity)
                pp_warning(ps, &at, "subsurface radiosity is parsed but not "
                           "rendered");
            break;
        default:
            pp_unexpected(ps, &at, "subsurface");
        }
    }
}

/* global_settings { photons { ... } } */
static void global_photons(pp_state *ps, iris_photon_settings *p)
{
    pp_expect(ps, T_LBRACE, "'{'");
    /* the values POV-Ray sets when the block is present (§2.2) */
    p->enabled = true;
    p->spacing = 1;
    p->count = 0;
    p->gather_min = 20;
    p->gather_max = 100;
    p->radius = -1;
    p->radius_mul = 1;
    p->jitter = 0.4;
    p->max_trace_level = -1;
    p->adc_bailout = -1;
    p->autostop = 0.5;
    p->expand_tol = 0.2;
    p->expand_min = 35;
    p->media_max_steps = 0;
    p->media_factor = 1;
    for (;;) {
        pp_next(ps);
        pp_token at = ps->tok;
        switch (at.kind) {
        case T_RBRACE:
            if (p->gather_max <= 0)
                p->enabled = false;
            return;
        case T_SPACING:
            p->loc = pp_loc(ps, &at); /* where a photon cap points */
            p->spacing = pp_float(ps);
            break;
        case T_COUNT:
            p->loc = pp_loc(ps, &at);
            p->count = pp_int(ps);
            break;
        case T_GATHER:
            p->gather_min = pp_int(ps);
            pp_accept(ps, T_COMMA); /* optional in POV-Ray */
            p->gather_max = pp_int(ps);
            break;
        case T_RADIUS:
            p->radius = pp_float(ps);
            /* up to three more, commas optional (POV-Ray: Parse_Comma,
            ** Allow_Float) */
            for (int i = 0; i < 3 && (pp_accept(ps, T_COMMA) ||
                                      pp_float_follows(ps)); i++) {
                double v = pp_float(ps);
                if (i == 0)
                    p->radius_mul = v;
            }
            break;
        case T_JITTER: p->jitter = pp_float(ps); break;
        case T_MAX_TRACE_LEVEL: p->max_trace_level = pp_int(ps); break;
        case T_ADC_BAILOUT: p->adc_bailout = pp_float(ps); break;
        case T_AUTOSTOP: p->autostop = pp_float(ps); break;
        case T_EXPAND_THRESHOLDS:
            p->expand_tol = pp_float(ps);
            pp_accept(ps, T_COMMA); /* optional in POV-Ray */
            p->expand_min = pp_int(ps);
            break;
        case T_MEDIA:
            p->media_max_steps = pp_int(ps);
            if (pp_accept(ps, T_COMMA))
                p->media_factor = pp_float(ps);
            break;
        case T_SAVE_FILE: {
            p->file_loc = pp_loc(ps, &at); /* photon_file.c's errors */
            const char *s = pp_string(ps);
            p->save_file = pp_strdup(ps, s, strlen(s));
            if (p->load_file) /* as POV-Ray: one or the other */
                pp_error(ps, &at, "photons: save_file and load_file together");
            break;
        }
        case T_LOAD_FILE: {
            p->file_loc = pp_loc(ps, &at);
            const char *s = pp_string(ps);
            p->load_file = pp_strdup(ps, s, strlen(s));
            if (p->save_file)
                pp_error(ps, &at, "photons: save_file and load_file together");
            break;
        }
        default: {
            pp_unexpected(ps, &at, "global photons");
        }
        }
    }
}

/*
** radiosity { count N [, POOL] | brightness F | recursion_limit N |
**             error_bound F | low_error_factor F | minimum_reuse F |
**             maximum_reuse F | nearest_count N [, M] | pretrace_start F |
**             pretrace_end F | gray_threshold F | max_sample F |
**             adc_bailout F | always_sample [BOOL] | normal [BOOL] |
**             media [BOOL] | subsurface [BOOL] | importance F |
**             save_file S | load_file S }
** After 'radiosity'. POV-Ray 3.7's defaults apply to what is not given
** (render/gather.c reads them); subsurface, importance (an object's,
** pp_radiosity_block) and the files are accepted and ignored with a
** warning.
*/
static void global_radiosity(pp_state *ps, iris_global_settings *g)
{
    iris_radiosity_settings *r = &g->rad;
    pp_expect(ps, T_LBRACE, "'{'");
    *r = (iris_radiosity_settings){
        .count = 35, .brightness = 1.0, .recursion_limit = 2,
        .error_bound = 1.8, .low_error_factor = 0.5,
        .minimum_reuse = 0.015, .maximum_reuse = 0.2, .nearest_count = 5,
        .pretrace_start = 0.08, .pretrace_end = 0.04,
        .gray_threshold = 0.0, .max_sample = -1.0, .adc_bailout = 0.01,
        .always_sample = false };
    for (;;) {
        pp_next(ps);
        pp_token at = ps->tok;
        switch (at.kind) {
        case T_RBRACE:
            return;
        case T_COUNT:
            r->count = pp_int(ps);
            if (r->count < 1 || r->count > 100000)
                pp_error(ps, &at, "radiosity count must be 1 to 100000");
            if (pp_accept(ps, T_COMMA) || pp_float_follows(ps))
                pp_int(ps); /* the direction pool: iris's set is fixed */
            break;
        case T_BRIGHTNESS: r->brightness = pp_float(ps); break;
        case T_RECURSION_LIMIT:
            r->recursion_limit = pp_int(ps);
            if (r->recursion_limit < 1)
                pp_error(ps, &at, "recursion_limit must be >= 1");
            break;
        case T_ERROR_BOUND:
            r->error_bound = pp_float(ps);
            if (!(r->error_bound > 0.0))
                pp_error(ps, &at, "error_bound must be > 0");
            break;
        case T_LOW_ERROR_FACTOR: r->low_error_factor = pp_float(ps); break;
        case T_MINIMUM_REUSE: r->minimum_reuse = pp_float(ps); break;
        case T_MAXIMUM_REUSE: r->maximum_reuse = pp_float(ps); break;
        case T_NEAREST_COUNT:
            r->nearest_count = pp_int(ps);
            if (r->nearest_count < 1 || r->nearest_count > 20)
                pp_error(ps, &at, "nearest_count must be 1 to 20");
            if (pp_accept(ps, T_COMMA) || pp_float_follows(ps))
                pp_int(ps); /* the pretrace's minimum: not used */
            break;
        case T_PRETRACE_START: r->pretrace_start = pp_float(ps); break;
        case T_PRETRACE_END: r->pretrace_end = pp_float(ps); break;
        case T_GRAY_THRESHOLD: r->gray_threshold = pp_float(ps); break;
        case T_MAX_SAMPLE: r->max_sample = pp_float(ps); break;
        case T_ADC_BAILOUT: r->adc_bailout = pp_float(ps); break;
        case T_ALWAYS_SAMPLE: r->always_sample = pp_bool_opt(ps); break;
        /* plain warnings: pp_warn_once's flag for 'media' would also
        ** silence the one for atmospheric media */
        case T_MEDIA: r->media = pp_bool_opt(ps); break;
        case T_NORMAL: r->normal = pp_bool_opt(ps); break;
        case T_SUBSURFACE:
            pp_bool_opt(ps);
            pp_warning(ps, &at, "radiosity subsurface is parsed but not "
                       "rendered");
            break;
        case T_IMPORTANCE:
            /* POV-Ray 3.7 takes it in an object's or #default's
            ** radiosity {} only (pp_radiosity_block) */
            pp_float(ps);
            pp_warning(ps, &at, "radiosity importance belongs in an "
                       "object's or #default's radiosity {}: ignored here");
            break;
        case T_SAVE_FILE: case T_LOAD_FILE:
            pp_string(ps);
            pp_warning(ps, &at, "radiosity save_file/load_file are parsed "
                       "but not used");
            break;
        default:
            pp_unexpected(ps, &at, "radiosity");
        }
    }
}

/* global_settings { ... } */
static void global_settings(pp_state *ps)
{
    pp_expect(ps, T_LBRACE, "'{' after global_settings");
    iris_global_settings *g = &ps->scene->settings;
    for (;;) {
        pp_next(ps);
        pp_token at = ps->tok;
        switch (at.kind) {
        case T_RBRACE: return;
        case T_ASSUMED_GAMMA: {
            double gm = pp_float(ps);
            if (!(gm > 0))
                pp_error(ps, &at, "assumed_gamma must be > 0");
            g->assumed_gamma = gm;
            /* Colours stay as written: see gamma.c */
            ps->gamma_given = true;
            break;
        }
        case T_MAX_TRACE_LEVEL: {
            int n = pp_int(ps);
            g->max_trace_level = n < 1 ? 1 : n > 256 ? 256 : n;
            break;
        }
        case T_ADC_BAILOUT: g->adc_bailout = pp_float(ps); break;
        case T_AMBIENT_LIGHT: g->ambient_light = pp_colour(ps); break;
        case T_IRID_WAVELENGTH: {
            iris_colour c = pp_colour(ps);
            g->irid_wavelength = v3(c.r, c.g, c.b);
            break;
        }
        case T_NUMBER_OF_WAVES: g->number_of_waves = pp_int(ps); break;
        case T_NOISE_GENERATOR: {
            int n = pp_int(ps);
            if (n < 1 || n > 3)
                pp_error(ps, &at, "noise_generator must be 1, 2 or 3");
            g->noise_generator = n;
            ps->noise_explicit = true;
            break;
        }
        case T_CHARSET: pp_next(ps); break;
        case T_HF_GRAY_16: pp_bool_opt(ps); break;
        case T_MAX_INTERSECTIONS: pp_float(ps); break;
        case T_MM_PER_UNIT: g->mm_per_unit = pp_float(ps); break;
        case T_PHOTONS: global_photons(ps, &g->photons); break;
        case T_RADIOSITY:
            g->radiosity = true;
            global_radiosity(ps, g);
            break;
        case T_SUBSURFACE:
            global_subsurface(ps, g);
            break;
        default: {
            pp_unexpected(ps, &at, "global_settings");
        }
        }
    }
}

/* The scene: items until the end of the file. */
void pp_scene_items(pp_state *ps)
{
    for (;;) {
        pp_next(ps);
        pp_token at = ps->tok;
        switch (at.kind) {
        case T_EOF:
            return;
        case T_CAMERA: {
            iris_camera *c = pp_camera(ps, NULL);
            ps->scene->camera = *c;
            ps->scene->has_camera = true;
            break;
        }
        case T_LIGHT_SOURCE:
            pp_add_light(ps, pp_light(ps));
            break;
        case T_GLOBAL_SETTINGS:
            global_settings(ps);
            break;
        case T_BACKGROUND: {
            pp_expect(ps, T_LBRACE, "'{' after background");
            iris_colour c = pp_colour(ps);
            pp_expect(ps, T_RBRACE, "'}'");
            ps->scene->background = c;
            ps->scene->has_background = true;
            break;
        }
        case T_SKY_SPHERE:
            ps->scene->sky_sphere = pp_sky_sphere(ps, NULL);
            break;
        case T_FOG:
            add_fog(ps, pp_fog(ps));
            break;
        case T_MEDIA:
            pp_add_atmosphere_media(ps, pp_media(ps));
            break;
        case T_RAINBOW:
            pp_rainbow(ps);
            break;
        case T_SEMI:
            break;
        case T_DEFAULT:
            pp_default_block(ps);
            break;
        case T_DECLARE: case T_INCLUDE: case T_VERSION:
            pp_bare_directive(ps, &at);
            break;
        default: {
            pp_unget(ps);
            iris_object *o = pp_object(ps);
            if (!o) {
                char buf[80];
                pp_next(ps);
                if (at.kind == T_IDENT && at.val.kind == V_NONE)
                    pp_error(ps, &at, "undeclared identifier '%.*s'",
                             (int)at.len, pp_tok_text(ps, &at));
                if (at.kind == T_IDENT)
                    pp_error(ps, &at, "a %s identifier cannot stand alone "
                             "here (wrap objects as object { %.*s })",
                             pp_kind_name(at.val.kind), (int)at.len,
                             pp_tok_text(ps, &at));
                pp_error(ps, &at, "expected an object, light, camera or "
                         "scene setting, found %s",
                         pp_tok_name(ps, &at, buf, sizeof buf));
            }
            pp_finalize_object(ps, o);
            /* A wrapper around a bare light carries no geometry. */
            if (!(o->kind == IRIS_OBJ_UNION && o->u.csg.n_children == 0))
                pp_add_object(ps, o);
            break;
        }
        }
    }
}
