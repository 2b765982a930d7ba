/* SPDX-License-Identifier: MIT */
/*
** gamma.c: colours in the working space of assumed_gamma.
**
** POV-Ray 3.7 keeps every colour of the scene as written: the numbers are
** values of the working space (assumed_gamma G), shading is done on them,
** and only the output converts working values to light (v -> v^G) before
** the file's encoding. Checked with POV-Ray 3.7.0.10 at assumed_gamma
** 2.2: a flat rgb 0.5 and an ambient 0.5 of rgb 1 both write 128 = sRGB
** of 0.5^2.2; rgb 0.2 writes 48, rgb 0.5 with ambient 0.3 diffuse 0.4
** writes 89 (= sRGB of 0.35^2.2). So the parser leaves rgb colours alone;
** the renderer applies v^G when it writes pixels.
**
** The exception is srgb: such a colour is decoded from sRGB to light and
** then encoded into the working space (c^(1/G)); POV-Ray prints 0.496227
** for (srgb 0.5).red under assumed_gamma 2.2. POV-Ray 3.7 refuses an srgb
** colour before assumed_gamma is known ("Cannot parse sRGB colors before
** assumed_gamma"); iris warns and uses a working gamma of 1.
*/
#include "config.h"

#include <math.h>

#include "pp.h"

double pp_srgb_decode(double c)
{
    if (c <= 0.04045)
        return c / 12.92;
    return pow((c + 0.055) / 1.055, 2.4);
}

double pp_srgb_to_working(pp_state *ps, const pp_token *at, double c)
{
    if (!ps->gamma_given && !ps->srgb_warned) {
        ps->srgb_warned = true;
        pp_warning(ps, at, "sRGB colour before assumed_gamma (POV-Ray 3.7 "
                   "refuses this): converted for a working gamma of 1");
    }
    double lin = pp_srgb_decode(c);
    double g = ps->scene->settings.assumed_gamma;
    if (!ps->gamma_given || !(g > 0) || fabs(g - 1) < 1e-12 || !(lin > 0))
        return lin;
    return pow(lin, 1 / g);
}
