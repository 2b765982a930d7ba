/* SPDX-License-Identifier: MIT */
/*
** tables.h: the measured spectral data compiled into the program.
**
** tables.c is generated from the CSV files of data/ by tools/gen_tables (`make
** regen-tables`); burns_table.c by tools/burns (`make regen-burns`). Use
** the interpolating functions of spectrum.h rather than these arrays.
*/
#ifndef IRIS_SPECTRUM_TABLES_H
#define IRIS_SPECTRUM_TABLES_H

/* First wavelength and length of the 1 nm tables (360..830 nm). */
#define SPEC_TAB_FIRST 360
#define SPEC_TAB_N 471

/* The 5 nm tables (F illuminants, Burns' curves): 380..780 nm. */
#define SPEC_TAB5_FIRST 380
#define SPEC_TAB5_N 81

extern const double spec_tab_cmf[SPEC_TAB_N][3];
extern const double spec_tab_d65[SPEC_TAB_N];
extern const double spec_tab_a[SPEC_TAB_N];
extern const double spec_tab_f[SPEC_TAB5_N][12];

/* One glass of the built-in Sellmeier catalogue (lambda in um). */
struct spec_glass {
    const char *name;
    double b[4], c[4];
    double lambda_min_um, lambda_max_um;
};

extern const struct spec_glass spec_tab_glass[];
extern const int spec_tab_n_glass;

/*
** Burns' three reflectance curves rho_R, rho_G, rho_B at 380..780 nm,
** 5 nm (tools/burns.c). They sum to 1 at every wavelength.
*/
extern const double spec_tab_burns[SPEC_TAB5_N][3];

#endif
