#!/bin/sh
# SPDX-License-Identifier: MIT
# bench/ray-counts.sh: the work each renderer does, ray for ray. Renders
# the scenes of bench/render-vs-povray.sh (the parity scenes and
# bench/example-scenes.txt) with POV-Ray (+V: its render statistics) and
# iris (--stats: the same events, counted where POV-Ray counts them, see
# src/render/trace.h struct trace_counts), one thread each, and prints a
# Markdown table: per scene POV-Ray's camera rays ("Pixels" + "Samples"),
# reflected + refracted + transmitted rays and shadow ray tests, iris's
# over POV-Ray's for each, and whether all seven counts agree
# (tests/render/raycounts.sh checks a few scenes exactly).
#
# Where the counts agree, a difference in time is a difference in the cost
# of a ray (callgrind tells where); where iris casts more rays, the
# difference is structural (which pixels it supersamples, which shadow
# rays it tests).
#
#   build=/path/to/build sh bench/ray-counts.sh [-s WxH] [scene.pov ...]
set -u
here=$(cd "$(dirname "$0")" && pwd)
. "$here/lib.sh"
size=160x120
while getopts s: opt; do
    case $opt in
    s) size=$OPTARG ;;
    *) exit 2 ;;
    esac
done
shift $((OPTIND - 1))
bench_setup
w=${size%x*}; h=${size#*x}
# no scene given: the parity scenes and the example scenes (paths have no
# blanks, so word splitting is safe)
[ $# -eq 0 ] && set -- $(default_scenes)
common="+W$w +H$h +A0.3 +AM1 +R3"

# POV-Ray's statistic 'label' from its log, 0 when not printed.
pov_stat() {
    v=$(sed -n "s/.*$1: *\([0-9][0-9]*\).*/\1/p" "$2" | head -n 1)
    echo "${v:-0}"
}
iris_stat() {
    v=$(sed -n "s/.*\"$1\": \([0-9][0-9]*\).*/\1/p" "$2")
    echo "${v:-0}"
}

echo "| scene | POV-Ray camera rays | iris/POV-Ray | POV-Ray secondary rays | iris/POV-Ray | POV-Ray shadow tests | iris/POV-Ray | all seven equal |"
echo "| --- | ---: | ---: | ---: | ---: | ---: | ---: | --- |"
n=0; n_eq=0; n_more=0
for scene in "$@"; do
    [ -f "$scene" ] || continue
    case $scene in /*) ;; *) scene=$(pwd)/$scene ;; esac
    name=$(basename "$scene" .pov)
    work="$BENCH_TMP/work"
    rm -rf "$work"; mkdir -p "$work"
    cp -R "$(dirname "$scene")/." "$work/" 2>/dev/null
    p="$BENCH_TMP/p.log"; j="$BENCH_TMP/i.json"
    # shellcheck disable=SC2086
    (cd "$work" && "$POVRAY" "+I$scene" "+O$BENCH_TMP/p.png" $common +WT1 \
        -D +V +Q9 >"$p" 2>&1)
    rm -f "$j"
    # shellcheck disable=SC2086
    (cd "$work" && "$IRIS" "$scene" -q -o "$BENCH_TMP/i.png" $common \
        --threads=1 --stats="$j" >/dev/null 2>&1)
    if ! grep -q '^Rays:' "$p" || [ ! -s "$j" ]; then
        echo "| $name | fail | - | - | - | - | - | - |"
        continue
    fi
    pc=$(( $(pov_stat Pixels "$p") + $(pov_stat Samples "$p") ))
    ps=$(( $(pov_stat "Reflected Rays" "$p") + $(pov_stat "Refracted Rays" "$p") + $(pov_stat "Transmitted Rays" "$p") ))
    pt=$(pov_stat "Shadow Ray Tests" "$p")
    ph=$(sed -n 's/^Shadow Ray Tests: *[0-9]* *Succeeded: *\([0-9]*\).*/\1/p' "$p" | head -n 1)
    pr=$(sed -n 's/^Rays: *\([0-9][0-9]*\).*/\1/p' "$p")
    ic=$(iris_stat rays_camera "$j")
    is=$(( $(iris_stat rays_reflected "$j") + $(iris_stat rays_refracted "$j") + $(iris_stat rays_transmitted "$j") ))
    it=$(iris_stat shadow_tests "$j")
    all="$(pov_stat Pixels "$p") $(pov_stat Samples "$p") $pr $(pov_stat "Reflected Rays" "$p") $(pov_stat "Refracted Rays" "$p") $(pov_stat "Transmitted Rays" "$p") $pt ${ph:-0}"
    got="$(pov_stat Pixels "$p") $(( ic - $(pov_stat Pixels "$p") )) $(iris_stat rays "$j") $(iris_stat rays_reflected "$j") $(iris_stat rays_refracted "$j") $(iris_stat rays_transmitted "$j") $it $(iris_stat shadow_hits "$j")"
    eq=no
    [ "$all" = "$got" ] && eq=yes
    n=$((n + 1))
    [ $eq = yes ] && n_eq=$((n_eq + 1))
    [ $((ic + is + it)) -gt $((pc + ps + pt)) ] && n_more=$((n_more + 1))
    echo "| $name | $pc | $(ratio "$ic" "$pc") | $ps | $(ratio "$is" "$ps") | $pt | $(ratio "$it" "$pt") | $eq |"
done
echo
echo "scenes: $n; every count equal: $n_eq; iris casting more rays in all: $n_more"
