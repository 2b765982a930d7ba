/* SPDX-License-Identifier: MIT */
/*
** photon_world.h: an analytic test double of the ray queries the photon
** shooter uses (struct pmap_world): spheres, planes, axis-aligned boxes and
** convex intersections of planes, with exact intersections, so photon
** transport can be checked against optics without Embree.
*/
#ifndef IRIS_TESTS_PHOTON_WORLD_H
#define IRIS_TESTS_PHOTON_WORLD_H

#include "photon/pmap.h"

/* A scene under construction: objects, materials and one light. */
struct tw_scene {
    iris_scene scene;
    iris_object *objs[8];
    iris_light *lights[2];
    iris_object obj_store[8];
    iris_object *children[8][8];
    iris_object child_store[8][8];
    iris_texture tex[8];
    iris_pigment pig[8];
    iris_finish fin[8];
    iris_interior inter[8];
    iris_ior_spec spec[8];
    iris_light light_store[2];
};

/* Starts an empty scene with photons on (spacing, gather max). */
void tw_init(struct tw_scene *t, double spacing, int gather_max);

/* Adds objects; returns the object. Material: rgbft colour, diffuse,
** ior (0 = no interior). Planes: normal·p <= d is inside. */
iris_object *tw_sphere(struct tw_scene *t, vec3 c, double r,
                       iris_colour col, double diffuse, double ior);
iris_object *tw_plane(struct tw_scene *t, vec3 n, double d, iris_colour col,
                      double diffuse);
iris_object *tw_box(struct tw_scene *t, vec3 lo, vec3 hi, iris_colour col,
                    double diffuse, double ior);
/* A convex solid, the intersection of half-spaces n_i·p <= d_i. */
iris_object *tw_convex(struct tw_scene *t, int n, const vec3 *normals,
                       const double *d, iris_colour col, double ior);

/* Adds a light (colour 1, photons refraction on). */
iris_light *tw_light(struct tw_scene *t, vec3 location, vec3 point_at,
                     bool parallel);

/* The world of the test double for scene 't'. */
struct pmap_world tw_world(struct tw_scene *t);

/* The photon light of map 'm' on a white diffuse floor y = 0, the mean over
** 24 x 24 points of [-0.8, 0.8]^2 (closer than the gather diameter: every
** photon of the region counts, so the mean has almost no estimate noise,
** ~0.5 %). */
void tw_floor_mean(const struct photon_map *m, double out[3]);

/* The mean rgb of n gathered points and the rms of their chromaticity
** (r/(r+g+b), b/(r+g+b)) about its mean: the colour noise the sibling
** tests compare. Every point must have some light. */
void tw_chroma_stats(const double (*pt)[3], int n, double mean[3],
                     double *chroma_rms);

#endif
