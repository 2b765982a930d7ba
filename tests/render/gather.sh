#!/bin/sh
# SPDX-License-Identifier: MIT
# tests/render/gather.sh: the final gather of radiosity{}
# (src/render/gather.c) against analytic answers, and its determinism.
# No light source lights the first three scenes: every pixel is the
# gather's radiosity term pigment x E x diffuse, with E the mean radiance
# over the cosine-weighted hemisphere (POV-Ray 3.7's radiosity; POV-Ray
# renders open_sky and glow identically and graded_sky within 63 dB).
. "$top_srcdir/tests/tap.sh"
tap_plan 4
dir="$top_srcdir/tests/render/gather"
imgstat="$top_builddir/tests/progressive/imgstat"
imgdiff="$top_builddir/tests/progressive/imgdiff"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
r() { s=$1; shift; "$IRIS" -q "$s" +W32 +H24 "$@" 2>/dev/null; }
# within(value, expected, relative tolerance)
within() { awk -v v="$1" -v e="$2" -v t="$3" \
    'BEGIN { d = v - e; if (d < 0) d = -d; exit !(d <= t * e) }'; }

# Uniform white background: every gather ray returns exactly 1, so the
# plane is 0.7 up to float rounding (tolerance 1e-5).
r "$dir/open_sky.pov" -o "$tmp/open.exr"
set -- $("$imgstat" "$tmp/open.exr")
tap_ok "open sky: albedo x background = 0.7 (got $1 $2 $3)" \
    within "$1" 0.7 0.00001

# Sky radiance cos(theta): E = 2/3, pixel 0.7 x 2/3. The only error is
# the quadrature of 35 fixed directions (midpoint rule in cos^2 theta,
# measured +0.04%); 0.5% also rejects a uniform (0.35) or a
# cos^2-weighted (0.525) direction set.
r "$dir/graded_sky.pov" -o "$tmp/graded.exr"
set -- $("$imgstat" "$tmp/graded.exr")
tap_ok "graded sky: cosine-weighted irradiance 0.7 x 2/3 = 0.4667 within 0.5% (got $1)" \
    within "$1" 0.466667 0.005

# Light that no light source emits: an emissive sphere of radiance 0.5
# around the plane; exact as for the open sky.
r "$dir/glow.pov" -o "$tmp/glow.exr"
set -- $("$imgstat" "$tmp/glow.exr")
tap_ok "emission lights the plane: 0.7 x 0.5 = 0.35 (got $1)" \
    within "$1" 0.35 0.00003

# The cache is filled by a pretrace in a fixed order and tile-local
# lists: the image must not depend on the thread count (exactly).
room="$top_srcdir/tests/render/scenes/81_radiosity_room.pov"
"$IRIS" -q "$room" +W96 +H64 --threads=1 -o "$tmp/t1.exr" 2>/dev/null
"$IRIS" -q "$room" +W96 +H64 --threads=3 -o "$tmp/t3.exr" 2>/dev/null
tap_is "thread count does not change the image" \
    "$("$imgdiff" "$tmp/t1.exr" "$tmp/t3.exr")" "0"

exit $((tap_failed > 0))
