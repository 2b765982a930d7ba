#!/bin/sh
# SPDX-License-Identifier: MIT
#
# alpha.sh: +UA output (TAP). tests/render/alpha/alpha.pov is rendered at
# 80x60 with +A0.3 by iris and by POV-Ray 3.7 with +UA, and the two PNGs
# must agree on the sRGB colour and on the alpha channel:
#   - PSNR over R, G, B (sRGB) and A (as stored) >= 50 dB. Both renderers
#     trace the same rays (no jitter-dependent feature is in the scene),
#     so only rounding separates them: measured 74.9 dB, the alpha alone
#     71.1 dB (one 8-bit step at a few antialiased edges). Without +UA the
#     same comparison gives 7 dB, so the bar cannot pass by accident.
#   - the alpha alone >= 50 dB (its own PSNR, so that a wrong alpha is
#     not hidden by three right colour channels).
# The EXR's A channel (premultiplied colour, OpenEXR's convention) must be
# the PNG's alpha where POV-Ray's highlight rule does not raise it: with
# the highlight removed (PHONG=0) the two alphas agree to >= 50 dB
# (measured 68.6: the PNG's 8-bit rounding).
#
# Environment: IRIS, POVRAY, top_srcdir, top_builddir (set by make check).
. "$top_srcdir/tests/tap.sh"
scene="$top_srcdir/tests/render/alpha/alpha.pov"
psnr="$top_builddir/tests/render/psnr"
if [ -z "$POVRAY" ] || ! command -v "$POVRAY" >/dev/null 2>&1; then
    tap_skip_all "POV-Ray is not installed"
fi
work=$(mktemp -d /tmp/iris-alpha.XXXXXX) || exit 1
trap 'rm -rf "$work"' EXIT INT TERM
size="+W80 +H60 +A0.3"
tap_plan 5

at_least() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a == "inf" || a + 0 >= b) }'; }

"$IRIS" "+I$scene" "+O$work/iris.png" $size -q +UA >"$work/iris.log" 2>&1
tap_result $? "iris renders with +UA"
(cd "$work" && "$POVRAY" "+I$scene" "+O$work/pov.png" $size -D -V +FN +UA \
    >"$work/pov.log" 2>&1)
"$IRIS" "+I$scene" "+O$work/opaque.png" $size -q >/dev/null 2>&1

set -- $("$psnr" --rgba "$work/iris.png" "$work/pov.png" 2>&1)
at_least "${1:-0}" 50
tap_result $? "RGBA against POV-Ray's +UA PNG: PSNR ${1:-?} dB >= 50"
set -- $("$psnr" --alpha "$work/iris.png" "$work/pov.png" 2>&1)
at_least "${1:-0}" 50
tap_result $? "alpha against POV-Ray's: PSNR ${1:-?} dB >= 50"
set -- $("$psnr" --rgba "$work/opaque.png" "$work/pov.png" 2>&1)
awk -v a="${1:-99}" 'BEGIN { exit !(a != "inf" && a + 0 < 20) }'
tap_result $? "without +UA the same comparison fails: PSNR ${1:-?} dB < 20"

"$IRIS" "+I$scene" "+O$work/flat.png" $size -q +UA Declare=PHONG=0 \
    >/dev/null 2>&1
"$IRIS" "+I$scene" "+O$work/flat.exr" $size -q +UA Declare=PHONG=0 \
    >/dev/null 2>&1
set -- $("$psnr" --alpha "$work/flat.exr" "$work/flat.png" 2>&1)
at_least "${1:-0}" 50
tap_result $? "the EXR's A channel is the PNG's alpha: PSNR ${1:-?} dB >= 50"
[ "$tap_failed" -eq 0 ]
