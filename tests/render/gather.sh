#!/bin/sh
# SPDX-License-Identifier: MIT
# tests/render/gather.sh: the final gather of radiosity{}
# (src/render/gather.c) against analytic answers, and its determinism.
# No light source lights the first three scenes: every pixel is the
# gather's radiosity term pigment x E x diffuse, with E the mean radiance
# over the cosine-weighted hemisphere (POV-Ray 3.7's radiosity; POV-Ray
# renders open_sky and glow identically and graded_sky within 63 dB).
. "$top_srcdir/tests/tap.sh"
tap_plan 15
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

# Radiosity importance 0.5 (#default): each sample shades 18 of its 35
# rays, counted 35/18 times each, and must still average the sky: under
# radiance (1 + x) / 2, E = 1/2, pixel 0.35. Measured -0.7% (+1.5% with
# all 35 rays: the quadrature of a sky linear in x); 3% rejects rays
# drawn from one side (ranked in the spiral's own golden-angle order the
# first half lay in one half-plane: up to 50% off).
r "$dir/xgraded_importance.pov" -o "$tmp/xgraded.exr"
set -- $("$imgstat" "$tmp/xgraded.exr")
tap_ok "importance 0.5: x-graded sky 0.7 x 1/2 = 0.35 within 3% (got $1)" \
    within "$1" 0.35 0.03

# Light that no light source emits: an emissive sphere of radiance 0.5
# around the plane; exact as for the open sky.
r "$dir/glow.pov" -o "$tmp/glow.exr"
set -- $("$imgstat" "$tmp/glow.exr")
tap_ok "emission lights the plane: 0.7 x 0.5 = 0.35 (got $1)" \
    within "$1" 0.35 0.00003

# Ambient where radiosity does not run: POV-Ray 3.7 drops finish ambient
# under radiosity{} at +Q9 only; at +Q8 the block is inert and ambient
# lights the plane (ambient_sky.pov: 0.56 and 0.35, exact up to float
# rounding, 1e-5).
r "$dir/ambient_sky.pov" -o "$tmp/amb9.exr"
set -- $("$imgstat" "$tmp/amb9.exr")
tap_ok "+Q9: radiosity term 0.7 x 0.8 = 0.56, ambient dropped (got $1)" \
    within "$1" 0.56 0.00001
r "$dir/ambient_sky.pov" -o "$tmp/amb8.exr" +Q8
set -- $("$imgstat" "$tmp/amb8.exr")
tap_ok "+Q8: no radiosity, ambient 0.7 x 0.5 = 0.35 (got $1)" \
    within "$1" 0.35 0.00001

# No light source, so no global photon map: the gather recurses down to
# recursion_limit L as POV-Ray's radiosity does, and the glowing furnace
# renders p (1 + a + ... + a^L) with p = 0.5, a = 0.4 (emit_furnace.pov;
# POV-Ray 3.7 renders the same three values). The radiance is uniform, so
# the only error is float rounding: 1e-4 relative. A missing level is
# off by 10% (L = 2) or 4% (L = 3), a level too many by 2% or 0.8%.
for lv in 1:0.7 2:0.78 3:0.812; do
    L=${lv%%:*}; want=${lv#*:}
    r "$dir/emit_furnace.pov" Declare=L=$L -o "$tmp/emit$L.exr"
    set -- $("$imgstat" "$tmp/emit$L.exr")
    tap_ok "recursion_limit $L without lights: p (1 + ... + a^$L) = $want (got $1)" \
        within "$1" "$want" 0.0001
done

# With a light the later bounces come from the global photon map, which
# stops where POV-Ray's radiosity does: a + ... + a^(L+1) for a = 0.4
# (lit_furnace.pov). The image mean averages 768 pixels of 400-photon
# estimates (measured +0.08% and +0.09%); 1.5% still tells L = 2 from
# L = 3 (4.1% apart) and from every bounce (a/(1-a) = 0.6667, +6.8%).
for lv in 2:0.624 3:0.6496; do
    L=${lv%%:*}; want=${lv#*:}
    r "$dir/lit_furnace.pov" Declare=L=$L -o "$tmp/lit$L.exr"
    set -- $("$imgstat" "$tmp/lit$L.exr")
    tap_ok "recursion_limit $L with a light: a + ... + a^$((L + 1)) = $want within 1.5% (got $1)" \
        within "$1" "$want" 0.015
done

# The cache is filled by a pretrace in a fixed order and tile-local
# lists: the image must not depend on the thread count (exactly), also
# when the gather recurses (80, 81: beside the global map; 82: no light
# source), with two levels of records.
for s in 80_radiosity_sky 81_radiosity_room 82_radiosity_emissive_room; do
    room="$top_srcdir/tests/render/scenes/$s.pov"
    "$IRIS" -q "$room" +W96 +H64 --threads=1 -o "$tmp/t1.exr" 2>/dev/null
    "$IRIS" -q "$room" +W96 +H64 --threads=3 -o "$tmp/t3.exr" 2>/dev/null
    tap_is "$s: thread count does not change the image" \
        "$("$imgdiff" "$tmp/t1.exr" "$tmp/t3.exr")" "0"
done

# A lit scene whose only light is its light sources' (no emission, sky,
# fog, ... : gather_sources.c proves it) skips the deeper gathers beside
# the global map, which would all return 0. Skipping must not change a
# pixel: the same room with a glowing sphere no ray can see (no_image,
# no_reflection, no_shadow: the proof fails, every level is traced)
# renders the same image exactly.
room="$top_srcdir/tests/render/scenes/81_radiosity_room.pov"
{ cat "$room"
  echo 'sphere { <0, 2.5, 0>, 0.1 pigment { rgb 1 } finish { emission 1 }'
  echo '  no_image no_reflection no_shadow }'; } > "$tmp/hidden.pov"
"$IRIS" -q "$room" +W96 +H64 --threads=1 -o "$tmp/skip.exr" 2>/dev/null
"$IRIS" -q "$tmp/hidden.pov" +W96 +H64 --threads=1 -o "$tmp/full.exr" 2>/dev/null
tap_is "81_radiosity_room: skipping the zero deeper gathers changes no pixel" \
    "$("$imgdiff" "$tmp/skip.exr" "$tmp/full.exr")" "0"

exit $((tap_failed > 0))
