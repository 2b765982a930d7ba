/* SPDX-License-Identifier: MIT */
/*
** pmap.h: internals of the photon map shared by the files of src/photon
** and by the unit tests.
**
** The shooter reaches the scene only through struct pmap_world, a small
** table of ray queries. photon_map_build() fills it from accel; the unit
** tests fill it with an analytic test double, so the transport can be
** checked against exact optics without the Embree build.
*/
#ifndef IRIS_PHOTON_PMAP_H
#define IRIS_PHOTON_PMAP_H

#include <stdbool.h>
#include <stdio.h> /* accel.h uses FILE */

#include "accel/accel.h"
#include "photon/photon.h"
#include "photon/pmedia.h"
#include "photon/pstore.h"

/* The ray queries the shooter needs (see accel.h for their meaning). */
struct pmap_world {
    const void *ctx;
    bool (*intersect)(const void *ctx, const ray *r, double tmin,
                      double tmax, unsigned skip, struct hit *h);
    bool (*object_bounds)(const void *ctx, const iris_object *obj, vec3 *lo,
                          vec3 *hi);
    bool (*inside)(const void *ctx, const iris_object *obj, vec3 p);
    double epsilon;            /* secondary-ray offset */
};

struct photon_map {
    const iris_scene *scene;
    struct pstore store;
    int gather_min, gather_max;
    double radius;             /* initial search radius */
    double expand_tol;
    int expand_min;
    double cone_k;             /* cone filter constant (1) */
    double estimate_scale;     /* progressive pass: the estimate radius is
                                  this times the k-nearest radius (1) */
    double white[3][3];        /* rgb of a white photon on pigment p:
                                  white·p (pmap_white_matrix) */
    struct photon_map *global; /* the global map (global.c), or NULL */
    float (*irr)[9];           /* global map only: 'store' holds the
                                  irradiance points (global.c), irr[i] the
                                  3x3 matrix of point i; dir_q its normal */
    double irr_radius;         /* global map: lookup radius of the points */
    struct pmedia_map *media;  /* media photons (pmedia.h), or NULL */
};

/* True when 'scene' asks for diffuse interreflection (radiosity{}) and
** has a light to bounce. */
bool pmap_wants_global(const iris_scene *scene);

/* Builds the global photon map (global.c); *out NULL when not wanted.
** Adds its counts to 'stats' (shot_global, stored_global, bytes, times). */
IRIS_NODISCARD enum iris_status
pmap_build_global(const iris_scene *scene, const struct pmap_world *w,
                  const struct photon_options *opts, struct photon_map **out,
                  struct photon_stats *stats);

/* The indirect light of the global map 'g' at 'in' (global.c). */
void pmap_global_shade(const struct photon_map *g,
                       const struct photon_shade_input *in, double rgb[3]);

struct ptrace_out;
/* Concatenates the raw photons of 'n' batch buffers in order into one
** new array (*all; NULL when there are none) and frees the buffers.
** Returns IRIS_ENOMEM when a batch failed or the array cannot be had. */
IRIS_NODISCARD enum iris_status pmap_concat(struct ptrace_out *outs,
                                            int64_t n,
                                            struct pstore_raw **all,
                                            size_t *total);

/* photon_map_build() against any world. */
IRIS_NODISCARD enum iris_status
pmap_build(const iris_scene *scene, const struct pmap_world *w,
           const struct photon_options *opts, struct photon_map **out,
           struct photon_stats *stats);

/* A photon map over the photons 'all' (n of them; freed here, whatever
** happens), built with 'threads' threads; the caller sets the estimate's
** parameters. */
enum iris_status pmap_from_raw(const iris_scene *scene,
                               struct pstore_raw *all, size_t n, int threads,
                               struct photon_map **out);

/* The estimate's parameters of a caustic map whose store is built: gather
** counts, expansion, the (automatic or given) radius (shoot.c; also for
** a map read by photon_file.c). */
void pmap_caustic_setup(struct photon_map *m, const iris_photon_settings *ps,
                        const struct photon_options *opts);

/* Whether 'w' answers from the scene's own geometry (accel or the fast
** path, photon.c), not a test double: the wavefront tracer (wavefront.c)
** intersects the scene's shapes itself only then. */
bool pmap_world_is_scene(const struct pmap_world *w);

/* The shooting rule of semantics §2.2b for one light and target. */
bool pmap_shoots(const iris_light *l, const iris_object *target);

/* A spot or cylinder light's attenuation of a photon leaving 'origin' in
** direction 'dir' (1 for other lights); 'axis' is the unit vector from
** the light to its point_at. Fade is applied where the photon lands. */
double pmap_light_atten(const iris_light *l, vec3 axis, vec3 origin, vec3 dir);

/*
** Unpolarised Fresnel reflectance for a cosine 'cos_i' in [0,1] of the
** incidence angle and relative index eta = n_i/n_t; 1 at and past the
** critical angle. *cos_t gets the cosine of the refraction angle.
*/
double pmap_fresnel(double cos_i, double eta, double *cos_t);

/*
** The mean over the spectrum of Burns' reflectance curve of pigment rgb
** times the RGB weight: out[k][c] = (1/400)·integral rho_{e_c}(lambda)·
** w_k(lambda) dlambda, so a white photon of power P on pigment p adds
** P·out·p (the identity for a white pigment). Midpoint rule, 0.1 nm.
*/
void pmap_white_matrix(double out[3][3]);

/* The gather radius POV-Ray picks automatically (semantics §2.6). */
double pmap_auto_radius(const struct pstore *s, int gather_max);
/* The same with 'threads' threads (the same result). */
double pmap_auto_radius_mt(const struct pstore *s, int gather_max,
                           int threads);

#endif
