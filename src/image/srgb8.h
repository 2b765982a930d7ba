/* SPDX-License-Identifier: MIT */
/*
** srgb8.h: the texel values iris_image_read() makes of 8-bit sRGB data,
** recognised again by value, so that what is computed from them (their
** sRGB encoding, a gamma power) can be looked up in a table instead of
** calling pow() for every texel a ray samples.
**
** An image is kept as linear floats (image_io.c decodes each 8-bit
** sample b as (float)iris_srgb_decode(b / 255)); shading re-encodes them
** (bump maps and image_pattern read the stored values, pre-3.7 scenes and
** 'gamma' overrides too). A value is recognised only when it is exactly
** one of those floats, so a table indexed by it gives the same bits as
** the computation; any other value (16-bit or float data) is not, and the
** caller computes.
*/
#ifndef IRIS_IMAGE_SRGB8_H
#define IRIS_IMAGE_SRGB8_H

/*
** The recognised values: sample b's as libpng's samples are scaled
** (b · (1/255) in float, index b) and as OpenImageIO may scale them (b /
** 255 in float, index 256 + b); the two differ in the last bit for some b.
*/
#define SRGB8_N 512

/* The index (0 .. SRGB8_N - 1) of texel value 'v', or -1 when 'v' is not
** a value decoded from 8-bit data. */
int srgb8_index(float v);

/* The texel value of index 'k' (0 .. SRGB8_N - 1). */
float srgb8_value(int k);

/* iris_srgb_encode(v), to the bit, by table when 'v' is recognised. */
double srgb8_encode(float v);

#endif
