/* SPDX-License-Identifier: MIT */
/*
** noise.h: POV-Ray 3.7's solid noise, vector noise and turbulence.
**
** Patterns only look like POV-Ray's when the noise returns the same
** numbers, so this module reproduces POV-Ray's lattice noise (Perlin's
** "Hypertexture" noise as Skinner wrote it, generators 1 and 2) and its
** gradient noise (generator 3) from the same hash and random tables, which
** are rebuilt here from POV-Ray's seeds. Values are in [0, 1].
**
** Depends on: math. Used by: material (patterns, normals, warps).
*/
#ifndef IRIS_MATERIAL_NOISE_H
#define IRIS_MATERIAL_NOISE_H

#include "math/vec3.h"

/* Builds the tables once; every function below calls it, so calling it
** first is only an optimisation. Thread-safe. */
void noise_init(void);

/* POV-Ray's Noise(): generator 1 (original), 2 (range-corrected, the
** default) or 3 (Perlin gradient). Result in [0, 1]. */
double noise_value(vec3 p, int generator);

/* POV-Ray's DNoise(): a vector noise, each component roughly in [-1, 1]. */
vec3 noise_vector(vec3 p);

/* Turbulence parameters as a warp carries them. */
struct noise_turb {
    int octaves;
    double omega, lambda;
};

/* POV-Ray's Turbulence(): sum of octaves of noise_value. */
double noise_turbulence(vec3 p, const struct noise_turb *t, int generator);

/* POV-Ray's DTurbulence(): sum of octaves of noise_vector. */
vec3 noise_dturbulence(vec3 p, const struct noise_turb *t);

/* Entry 'i' (0..8191) of POV-Ray's noise hash table (AA jitter uses it). */
int noise_hash_entry(int i);

/* POV-Ray's random noise coefficient 'i' (0..266; RTable's values, before
** this module regroups them), for tests that rebuild the noise the plain
** way. 0 outside the range. */
double noise_coefficient(int i);

/* POV-Ray's PatternRands: entry i % 32768 of the first 32768 outputs of
** MT19937 (seed 5489), each over 2^32; cells, crackle, facets and
** black_hole's turbulence read it. */
double noise_pattern_rand(unsigned long i);
/* Entries i, i + 1 and i + 2 of it (a random point's offsets). */
vec3 noise_pattern_rand3(unsigned long i);

/* POV-Ray's Hash3d over the noise hash table, for cells and crackle. */
int noise_hash3d(int a, int b, int c);

/* The table lookup POV-Ray's wave patterns use for the source points and
** frequencies of 'waves' and 'ripples' (Initialize_Waves). 'i' in
** [0, number_of_waves). */
void noise_wave_source(int i, vec3 *source, double *frequency);

/* POV-Ray's cycloidal() and Triangle_Wave() shaping functions. */
double noise_cycloidal(double v);
double noise_triangle_wave(double v);

#endif
