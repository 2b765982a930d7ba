/* SPDX-License-Identifier: MIT */
/*
** internal.h: helpers shared by the files of src/spectrum (and by
** tools/burns.c, which integrates exactly as the runtime does).
*/
#ifndef IRIS_SPECTRUM_INTERNAL_H
#define IRIS_SPECTRUM_INTERNAL_H

/*
** Row *i and fraction *t of 'lambda' in a table of 'n' rows from 'first'
** nm every 'step' nm; 0 when outside the table.
*/
int spec_locate(double lambda, double first, double step, int n, int *i,
                double *t);

/*
** Integral over 380..780 nm of the 3-vector function 'f', Simpson's rule
** on each 1 nm interval: exact when f is at most cubic on each interval
** (products of the 1 nm and 5 nm linear interpolants).
*/
void spec_integrate_1nm(void (*f)(double lambda, void *ctx, double out[3]),
                        void *ctx, double sum[3]);

#endif
