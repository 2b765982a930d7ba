/* SPDX-License-Identifier: MIT */
/*
** meshcam.c: POV-Ray 3.7's mesh_camera (CreateCameraRay, MESH_CAMERA):
** every pixel's ray starts on a face of a mesh and leaves along the
** face's normal. What POV-Ray computes, per distribution type:
**   0  pixel (x, y) of a W-wide image is face y W + x of mesh number
**      'ray' (ray n of the pixel uses the n-th mesh);
**   1  the meshes' faces are counted as one list; ray n of pixel
**      (x, y) uses face y W + x + n F, F the total face count;
**   2  the image is cut into one column per mesh, side by side; mesh
**      m = floor(x / (W / M)) and face y floor(W / M) + x (x counted from
**      the image's left edge, not the column's, as POV-Ray does);
**   3  the pixel's uv point, u = (x - 0.5) / W, v = 1 - (y + 0.5) / H,
**      is looked up in the first mesh's uv map: the first face (in mesh
**      order) whose uv triangle holds it gives the origin by its
**      barycentric weights.
** (x, y) above are POV-Ray 3.7's image position, iris's + (0.5, -0.5)
** (camera.h), clipped to the image.
** POV-Ray 3.7 holds a mesh's vertices and normals in single precision
** (MESH_DATA's SNGL_VECT): the corners and normals are rounded so here too.
** For 0-2 the origin is the face's centroid (summed in single precision); the direction is the face
** normal (P3 - P1) x (P2 - P1), normalised (POV-Ray's
** Compute_Mesh_Triangle), or with 'smooth' (3 only) the unit vertex
** normals weighted by the barycentric coordinates (POV-Ray's
** Smooth_Mesh_Normal, not normalised). The origin then moves
** location.z along the normal; a direction.z below -1e-10 reverses the
** ray; finally the mesh's own transform applies (point, and the normal
** by the inverse transpose). Pixels without a face get no ray.
*/
#include "config.h"

#include <math.h>

#include "math/transform.h"
#include "render/meshcam.h"

/* 'v' rounded to single precision, as POV-Ray 3.7 stores a mesh's
** vertices and normals (MESH_DATA's SNGL_VECT arrays). */
static vec3 v3_single(vec3 v)
{
    return v3((float)v.x, (float)v.y, (float)v.z);
}

/* The flat normal of the triangle p1 p2 p3, in the mesh's own space, as
** POV-Ray keeps it: normalised in double, stored in single precision. */
static vec3 face_normal(vec3 p1, vec3 p2, vec3 p3)
{
    return v3_single(v3_norm(v3_cross(v3_sub(p3, p1), v3_sub(p2, p1))));
}

/* The corners of triangle 't' as POV-Ray holds them (single precision):
** a ray that grazes an edge or a shadow's rim goes the same way only
** from the same origin, to the last bit. */
static void tri_points(const iris_mesh_data *m, int t, vec3 p[3])
{
    for (int k = 0; k < 3; k++)
        p[k] = v3_single(m->vertices[m->tri_vertices[3 * t + k]]);
}

/* Origin and direction from the face centroid of triangle 't'. */
static void centroid_ray(const iris_mesh_data *m, int t, vec3 *o, vec3 *d)
{
    vec3 p[3];
    tri_points(m, t, p);
    /* POV-Ray adds the single-precision corners and divides by 3 in
    ** single precision too */
    float x = (float)p[0].x + (float)p[1].x + (float)p[2].x;
    float y = (float)p[0].y + (float)p[1].y + (float)p[2].y;
    float z = (float)p[0].z + (float)p[1].z + (float)p[2].z;
    *o = v3(x / 3.0f, y / 3.0f, z / 3.0f);
    *d = face_normal(p[0], p[1], p[2]);
}

/*
** Distribution 3: the first face whose uv triangle holds (u, v). POV-Ray
** narrows the search with a 10 x 10 grid of uv cells; the first hit in
** face order is the same for points inside [0, 1)^2.
*/
static bool uv_ray(const iris_mesh_data *m, bool smooth, double u, double v,
                   vec3 *o, vec3 *d)
{
    if (!m->uvs || !m->tri_uvs)
        return false;
    for (int t = 0; t < m->n_triangles; t++) {
        iris_vec2 a = m->uvs[m->tri_uvs[3 * t]];
        iris_vec2 b = m->uvs[m->tri_uvs[3 * t + 1]];
        iris_vec2 c = m->uvs[m->tri_uvs[3 * t + 2]];
        double scale = (b.u - a.u) * (c.v - a.v) - (c.u - a.u) * (b.v - a.v);
        if (scale == 0.0)
            continue;          /* a uv triangle without area holds nothing */
        double b1 = ((b.u - u) * (c.v - v) - (c.u - u) * (b.v - v)) / scale;
        double b2 = ((c.u - u) * (a.v - v) - (a.u - u) * (c.v - v)) / scale;
        double b3 = ((a.u - u) * (b.v - v) - (b.u - u) * (a.v - v)) / scale;
        if (b1 < 0 || b2 < 0 || b3 < 0)
            continue;
        vec3 p[3];
        tri_points(m, t, p);
        *o = v3_add(v3_add(v3_scale(p[0], b1), v3_scale(p[1], b2)),
                    v3_scale(p[2], b3));
        *d = face_normal(p[0], p[1], p[2]);
        if (smooth && m->normals && m->tri_normals) {
            /* POV-Ray stores mesh normals normalised and does not
            ** normalise their blend (Smooth_Mesh_Normal): the blend's
            ** length scales the location.z offset */
            const int32_t *ni = &m->tri_normals[3 * t];
            vec3 n = v3_add(
                v3_add(v3_scale(v3_single(v3_norm(m->normals[ni[0]])), b1),
                       v3_scale(v3_single(v3_norm(m->normals[ni[1]])), b2)),
                v3_scale(v3_single(v3_norm(m->normals[ni[2]])), b3));
            if (v3_len(n) > 0)
                *d = n;
        }
        return true;
    }
    return false;
}

bool meshcam_ray(const iris_camera *cam, int width, int height, double x,
                 double y, int ray_number, ray *r)
{
    if (cam->n_meshes < 1 || ray_number < 0)
        return false;
    double w = width > 0 ? width : 1, h = height > 0 ? height : 1;
    /* POV-Ray 3.7's image position of iris's (x, y) (camera.h): its
    ** camera code sees x + 0.5 and y - 0.5, so the index methods use
    ** pixel row y - 1 (row 0 twice) and column x */
    x += 0.5;
    y -= 0.5;
    /* POV-Ray keeps the position inside the image: the index methods
    ** would read outside their faces otherwise */
    x = fmax(0.0, fmin(x, w - 1.0));
    y = fmax(0.0, fmin(y, h - 1.0));
    unsigned ux = (unsigned)x, uy = (unsigned)y, uw = (unsigned)w;
    const iris_object *ob = NULL;
    vec3 o, d;
    switch (cam->mesh_distribution) {
    case 0: {
        if (ray_number >= cam->n_meshes)
            return false;
        ob = cam->meshes[ray_number];
        const iris_mesh_data *m = &ob->u.mesh;
        unsigned long face = (unsigned long)uy * uw + ux;
        if (face >= (unsigned long)m->n_triangles)
            return false;
        centroid_ray(m, (int)face, &o, &d);
        break;
    }
    case 1: {
        unsigned long total = 0;
        for (int i = 0; i < cam->n_meshes; i++)
            total += (unsigned long)cam->meshes[i]->u.mesh.n_triangles;
        unsigned long face = (unsigned long)uy * uw + ux +
                             (unsigned long)ray_number * total;
        if (face >= total)
            return false;
        for (int i = 0; i < cam->n_meshes; i++) {
            const iris_mesh_data *m = &cam->meshes[i]->u.mesh;
            if (face < (unsigned long)m->n_triangles) {
                ob = cam->meshes[i];
                centroid_ray(m, (int)face, &o, &d);
                break;
            }
            face -= (unsigned long)m->n_triangles;
        }
        if (!ob)
            return false;
        break;
    }
    case 2: {
        unsigned n = (unsigned)cam->n_meshes;
        unsigned mesh_no = (unsigned)(x / (w / n));
        if (mesh_no >= n)
            return false;
        ob = cam->meshes[mesh_no];
        const iris_mesh_data *m = &ob->u.mesh;
        unsigned long face = (unsigned long)uy * (uw / n) + ux;
        if (face >= (unsigned long)m->n_triangles)
            return false;
        centroid_ray(m, (int)face, &o, &d);
        break;
    }
    default: {
        ob = cam->meshes[0];
        double u = (x - 0.5) / w, v = 1.0 - (y + 0.5) / h;
        if (!uv_ray(&ob->u.mesh, cam->mesh_smooth, u, v, &o, &d))
            return false;
        break;
    }
    }
    if (!(v3_len(d) > 0))
        return false;          /* a degenerate face has no normal */
    o = v3_madd(o, d, cam->location.z);
    if (cam->direction.z < -1e-10)
        d = v3_neg(d);
    if (ob->has_transform) {
        o = xf_point(&ob->transform, o);
        d = xf_normal(&ob->transform, d);
    }
    double len = v3_len(d);
    if (!(len > 0) || !isfinite(len) || !isfinite(o.x) || !isfinite(o.y) ||
        !isfinite(o.z))
        return false;
    r->o = o;
    r->d = v3_scale(d, 1.0 / len);
    return true;
}

bool meshcam_origin_box(const iris_camera *cam, vec3 *lo, vec3 *hi)
{
    *lo = v3(INFINITY, INFINITY, INFINITY);
    *hi = v3_neg(*lo);
    /* an origin is a point of a face (a vertex blend with weights summing
    ** to 1) moved by location.z times a normal of length <= 1 (a unit
    ** normal, or a blend of unit normals) */
    double off = fabs(cam->location.z);
    for (int i = 0; i < cam->n_meshes; i++) {
        const iris_object *ob = cam->meshes[i];
        const iris_mesh_data *m = &ob->u.mesh;
        vec3 a = v3(INFINITY, INFINITY, INFINITY), b = v3_neg(a);
        for (int k = 0; k < m->n_vertices; k++) {
            vec3 p = m->vertices[k];
            a = v3(fmin(a.x, p.x), fmin(a.y, p.y), fmin(a.z, p.z));
            b = v3(fmax(b.x, p.x), fmax(b.y, p.y), fmax(b.z, p.z));
        }
        if (!(a.x <= b.x && a.y <= b.y && a.z <= b.z))
            continue;
        a = v3_sub(a, v3(off, off, off));
        b = v3_add(b, v3(off, off, off));
        for (int c = 0; c < 8; c++) {
            vec3 p = v3(c & 1 ? b.x : a.x, c & 2 ? b.y : a.y,
                        c & 4 ? b.z : a.z);
            if (ob->has_transform)
                p = xf_point(&ob->transform, p);
            *lo = v3(fmin(lo->x, p.x), fmin(lo->y, p.y), fmin(lo->z, p.z));
            *hi = v3(fmax(hi->x, p.x), fmax(hi->y, p.y), fmax(hi->z, p.z));
        }
    }
    return lo->x <= hi->x && lo->y <= hi->y && lo->z <= hi->z &&
           isfinite(lo->x + lo->y + lo->z + hi->x + hi->y + hi->z);
}
