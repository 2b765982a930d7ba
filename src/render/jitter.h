/* SPDX-License-Identifier: MIT */
/*
** jitter.h: POV-Ray's position-keyed antialiasing jitter.
**
** Depends on: material (the noise hash table). Used by: eyepass.c.
*/
#ifndef IRIS_RENDER_JITTER_H
#define IRIS_RENDER_JITTER_H

/* The jitter of the subsample at image position (x, y), each component
** in [-0.5, 0.5): a pure function of the position, as POV-Ray's. */
void jitter2d(double x, double y, double *jx, double *jy);

#endif
