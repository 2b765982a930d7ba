#!/bin/sh
# SPDX-License-Identifier: MIT
# tests/stability/area_light_cap.sh: an area light of more than
# IRIS_AREA_LIGHT_MAX_GRID = 1024 x 1024 sub-lights is rendered as a
# point light at its centre (each trace context keeps a table of that
# many shadow rays), and the parser says so at the sizes. Checks:
#   - 2000 x 2000 warns, located at the sizes (file:line:col: warning);
#   - 1024 x 1024 (the limit itself) does not;
#   - the 2000 x 2000 image is the point light's, pixel for pixel (the
#     same rays: imgtool psnr prints 99.00 for identical images), and
#     a 2 x 2 area light's is not (so the
#     comparison tells soft shadows from hard ones).
. "$top_srcdir/tests/tap.sh"
imgtool="$top_builddir/tests/cli/imgtool"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
# scene AREA_LIGHT_LINE > file: light at <0, 5, -3> over a sphere on a
# plane, so a point light and an area light differ in the shadow's edge
scene() {
    cat <<POV
#version 3.7;
camera { location <0, 2, -5> look_at 0 }
light_source { <0, 5, -3>, rgb 1
  $1 }
sphere { 0, 1 pigment { rgb 1 } }
plane { y, -1 pigment { rgb 0.5 } }
POV
}
scene "area_light 2*x, 2*z, 2000, 2000 adaptive 1" > huge.pov
scene "area_light 2*x, 2*z, 1024, 1024 adaptive 1" > limit.pov
scene "area_light 2*x, 2*z, 2, 2" > small.pov
scene "" > point.pov
tap_plan 4
"$IRIS" +W64 +H48 huge.pov -o huge.png > huge.log 2>&1
tap_ok "2000 x 2000 sub-lights: a warning at the sizes (line 4, col 24)" \
    grep -q "huge.pov:4:24: warning: area_light 2000 x 2000: more than 1048576 sub-lights; rendered as a point light" huge.log
"$IRIS" --parse-only limit.pov > limit.log 2>&1
tap_ok "1024 x 1024 sub-lights (the limit): no warning" \
    sh -c '! grep -q warning limit.log'
"$IRIS" -q +W64 +H48 point.pov -o point.png > point.log 2>&1
"$IRIS" -q +W64 +H48 small.pov -o small.png > small.log 2>&1
tap_is "... and the image is the point light's (identical: PSNR 99.00)" \
    "$("$imgtool" psnr point.png huge.png 2>&1)" "99.00"
p=$("$imgtool" psnr point.png small.png 2>&1 | cut -d' ' -f1)
tap_ok "a 2 x 2 area light's image is not the point light's (PSNR $p)" \
    test "$p" != 99.00
[ $tap_failed -eq 0 ]
