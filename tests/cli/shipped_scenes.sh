#!/bin/sh
# SPDX-License-Identifier: MIT
# tests/cli/shipped_scenes.sh: every scene in scenes/ (the demo and the
# seed paper's photon scenes, README "scenes/: example scenes, each renders
# in POV-Ray too") renders in iris, photons included, at 48x36: exit 0 and
# every pixel finite and non-negative (imgtool stats: bad = 0), and the
# image not black (mean > 0.01: each scene is lit). And each parses and
# renders in POV-Ray 3.7 (+Q5: without its photon pass, which takes
# seconds to minutes; the scene text is what is checked), so the files
# stay POV-Ray scenes with the iris extensions behind #ifdef (iris_version).
. "$top_srcdir/tests/tap.sh"
scenes=$(ls "$top_srcdir"/scenes/*.pov | sort)
n=$(printf '%s\n' "$scenes" | grep -c .)
tap_plan $((2 * n))
imgtool="$top_builddir/tests/cli/imgtool"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
for s in $scenes; do
    sc=$(basename "$s" .pov)
    "$IRIS" -q "$s" +W48 +H36 -o "$sc.exr" 2>"$sc.err"
    rc=$?
    st=$("$imgtool" stats "$sc.exr" 2>/dev/null)
    echo "# $sc: exit $rc, min max mean bad: $st"
    tap_ok "$sc renders in iris: finite, lit" sh -c "test $rc = 0 &&
        echo '$st' | awk '{ exit !(\$4 == 0 && \$3 > 0.01) }'"
    if [ -z "$POVRAY" ] || ! command -v "$POVRAY" >/dev/null 2>&1; then
        tap_result 0 "$sc in POV-Ray # SKIP no POV-Ray (\$POVRAY)"
        continue
    fi
    "$POVRAY" "+I$s" "+O$sc.png" +W32 +H24 +Q5 -D -V >"$sc.pov.log" 2>&1
    rc=$?
    tap_ok "$sc renders in POV-Ray 3.7 (exit $rc)" sh -c "test $rc = 0 &&
        test -s '$sc.png'"
done
[ "$tap_failed" -eq 0 ]
