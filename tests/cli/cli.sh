#!/bin/sh
# SPDX-License-Identifier: MIT
# tests/cli/cli.sh: the iris command end to end, as a user runs it.
. "$top_srcdir/tests/tap.sh"
tap_plan 14
scenes="$top_srcdir/tests/cli/scenes"
imgtool="$top_builddir/tests/cli/imgtool"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

out=$("$IRIS" --version); tap_is "--version names the program" "${out%% *}" "iris"
"$IRIS" --help >"$tmp/help" 2>&1; tap_is "--help exits 0" "$?" "0"
grep -q -- "--parse-only" "$tmp/help"; tap_is "--help lists the options" "$?" "0"

"$IRIS" +Zbogus "$scenes/minimal.pov" 2>"$tmp/err"; rc=$?
tap_is "an unknown option exits 2" "$rc" "2"
grep -q "unknown option '+Zbogus'" "$tmp/err"; tap_is "... and names the option" "$?" "0"

"$IRIS" "$tmp/does-not-exist.pov" 2>/dev/null; tap_is "a missing scene exits 2" "$?" "2"

"$IRIS" --parse-only "$scenes/broken.pov" 2>"$tmp/err"; rc=$?
tap_is "a scene error exits 2" "$rc" "2"
grep -q "broken.pov:1:[0-9]*: error:" "$tmp/err"; tap_is "... with file:line:col: error:" "$?" "0"

cp "$scenes/minimal.pov" "$tmp/min.pov"
"$IRIS" -q "$tmp/min.pov" +W40 +H30 -o "$tmp/min.pov" 2>/dev/null
rc=$?; cmp -s "$scenes/minimal.pov" "$tmp/min.pov"; same=$?
tap_is "the scene file is never overwritten by the image" "$rc:$same" "2:0"

# The plane lit along its normal is 0.35 linear; POV-Ray's PNG holds 160.
"$IRIS" -q "$scenes/minimal.pov" +W41 +H31 -o "$tmp/min.png" --stats="$tmp/s.json"
tap_is "renders the minimal scene to PNG" "$?" "0"
tap_is "... at the requested size" "$("$imgtool" size "$tmp/min.png")" "41 31"
px=$("$imgtool" pixel "$tmp/min.png" 20 15 | awk '{printf "%d", $1 * 1000 + 0.5}')
# 8-bit sRGB 160 decodes to 0.3515; 159..161 span 0.3467..0.3564
tap_ok "... the lit plane is 0.35 (8-bit 160)" test "$px" -ge 346 -a "$px" -le 357

"$IRIS" -q "$scenes/minimal.pov" +W41 +H31 -o "$tmp/min.exr"
px=$("$imgtool" pixel "$tmp/min.exr" 20 15 | awk '{printf "%d", $1 * 10000 + 0.5}')
# linear float: 0.35 within 0.5% (shading is exact here; float rounding)
tap_ok "renders to linear EXR: the plane is 0.35" test "$px" -ge 3483 -a "$px" -le 3517

keys="time_parse_s time_build_s time_photon_s time_render_s time_render_cpu_s time_write_s time_total_s photons_emitted photons_stored photon_bytes rays_traced peak_rss_bytes threads passes"
missing=""
for k in $keys; do grep -q "\"$k\":" "$tmp/s.json" 2>/dev/null || missing="$missing $k"; done
tap_is "--stats writes every key" "$missing" ""
