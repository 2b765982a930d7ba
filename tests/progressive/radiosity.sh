#!/bin/sh
# SPDX-License-Identifier: MIT
# tests/progressive/radiosity.sh: the global photon map (radiosity{},
# src/photon/global.c) through the whole pipeline: plan, photon pass,
# the final gather whose rays read it (src/render/gather.c), progressive
# passes. The furnace scene has an
# analytic answer: total = a/(1 - a) = 0.6667 for albedo a = 0.4, of
# which the direct light is a = 0.4.
. "$top_srcdir/tests/tap.sh"
tap_plan 7
scene="$top_srcdir/tests/progressive/furnace.pov"
imgstat="$top_builddir/tests/progressive/imgstat"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
r() { "$IRIS" -q "$scene" +W32 +H24 "$@" 2>/dev/null; }
# within(value, expected, relative tolerance)
within() { awk -v v="$1" -v e="$2" -v t="$3" \
    'BEGIN { d = v - e; if (d < 0) d = -d; exit !(d <= t * e) }'; }

"$IRIS" --plan "$scene" >"$tmp/plan" 2>/dev/null
tap_ok "--plan keeps the global map" grep -q "global photon map (radiosity): yes" "$tmp/plan"

# +Q8 has no radiosity (POV-Ray's rule); the furnace has ambient 0
r -o "$tmp/direct.exr" +Q8
set -- $("$imgstat" "$tmp/direct.exr")
tap_ok "direct light alone is a = 0.4 (got $1)" within "$1" 0.4 0.001

# Without photons the final gather (src/render/gather.c) adds exactly one
# bounce: its rays see the direct light a everywhere, so a + a^2 = 0.56
# (uniform radiance: no quadrature error; 0.1% for float rounding).
r -o "$tmp/bounce1.exr" --no-photons
set -- $("$imgstat" "$tmp/bounce1.exr")
tap_ok "gather without photons: one bounce a + a^2 = 0.56 (got $1)" \
    within "$1" 0.56 0.001

# One pass: 4e5 photons; the image mean averages 768 pixels over the
# whole sphere, each a blend of 400-photon estimates (5% noise, strongly
# correlated over a few pixels): the mean is within ~1%. Bound 2.5%.
r -o "$tmp/p1.exr"
set -- $("$imgstat" "$tmp/p1.exr")
tap_ok "one pass: total a/(1-a) = 0.6667 within 2.5% (got $1)" \
    within "$1" 0.666667 0.025
sd1=$4
tap_ok "grey stays grey (r = b = $1 $3)" test "$1" = "$3"

# Four passes average independent maps with a shrinking radius: still
# unbiased, and the pixel noise falls (about 1/2; bound: below 0.8 of one
# pass's).
r -o "$tmp/p4.exr" --passes 4
set -- $("$imgstat" "$tmp/p4.exr")
tap_ok "4 passes: 0.6667 within 2.5% (got $1)" within "$1" 0.666667 0.025
tap_ok "4 passes: pixel noise falls ($4 < 0.8 x $sd1)" \
    awk -v a="$4" -v b="$sd1" 'BEGIN { exit !(a < 0.8 * b) }'
exit $((tap_failed > 0))
