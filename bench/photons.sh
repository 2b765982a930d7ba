#!/bin/sh
# SPDX-License-Identifier: MIT
# bench/photons.sh: the photon pass of iris against POV-Ray 3.7's on the
# same scenes, in one run. For iris (tools/photon_bench: parse, Embree
# build, then the photon pass alone): photons traced per second per thread
# at 1 and T threads (shooting and transport only: the kd-tree build is
# the "build s" column), the same per CPU second at 1 thread (what a
# shared machine's load does not change), bytes per stored photon, gather
# queries per second of wall and of CPU time (k = the scene's gather max,
# one thread). For POV-Ray: its own "Photon Time" (shooting and its
# build) and photon counts from a +Q9 render at a small size (the photon
# pass does not depend on the image size).
#
#   build=/path/to/build sh bench/photons.sh [-t THREADS] [-s] [-w] [scene.pov ...]
#
# iris shoots with the scene's material context, evaluating each surface
# hit's texture as a render does (render.c): the table is what users get.
# -s shoots without it (textures taken as solid pigments: photon_bench
# -m 0), the way the tables of sessions 1-5 were made.
# Scenes the wavefront tracer takes (src/photon/wavefront.h: spheres,
# planes and convex objects: boxes, convex prisms, capped cylinders and
# their intersections; uniform textures) are shot by it; -w shoots every scene with the
# scalar tracer (photon_bench -w 0), as sessions 1-7 did. The last column
# says which tracer shot each scene (its kernel: avx2 or generic).
# Without scenes it uses the photon scenes of scenes/. Build the driver
# first: make -C "$build" tools/photon_bench.
set -u
here=$(cd "$(dirname "$0")" && pwd)
threads=2
mat=1
wf=1
while getopts t:sw opt; do
    case $opt in
    t) threads=$OPTARG ;;
    s) mat=0 ;;
    w) wf=0 ;;
    *) exit 2 ;;
    esac
done
shift $((OPTIND - 1))
: "${build:?set build to a configured and built tree}"
bench="$build/tools/photon_bench"
[ -x "$bench" ] || make -C "$build" tools/photon_bench >/dev/null || exit 1
POVRAY=${POVRAY:-povray}
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
if [ $# -eq 0 ]; then
    set -- "$here"/caustic_ball.pov \
        "$here"/../scenes/glass_sphere.pov "$here"/../scenes/prism.pov \
        "$here"/../scenes/lens.pov "$here"/../scenes/gem.pov \
        "$here"/../scenes/cornell_glass.pov
fi
# key=value from a photon_bench line
field() { echo "$1" | tr ' ' '\n' | sed -n "s/^$2=//p"; }
echo "| scene | iris shot | iris stored | B/photon | iris shoot s (1 / $threads thr) | build s (1 / $threads thr) | photons/s/thread (1 / $threads thr) | photons/CPU-s | gathers/s | gathers/CPU-s | POV-Ray shot | POV-Ray stored | POV-Ray photon s ($threads thr) | tracer |"
echo "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | --- |"
for scene in "$@"; do
    [ -f "$scene" ] || continue
    # POV-Ray runs in $tmp: the scene's path must not be relative
    case $scene in /*) ;; *) scene=$PWD/$scene ;; esac
    name=$(basename "$scene" .pov)
    one=$("$bench" -t 1 -m "$mat" -w "$wf" "$scene" 2>/dev/null | tail -1)
    many=$("$bench" -t "$threads" -q 0 -m "$mat" -w "$wf" "$scene" \
        2>/dev/null | tail -1)
    if [ "$(field "$one" wavefront)" = 0 ]; then
        tracer=scalar
    else
        tracer="wavefront ($(field "$one" kernel))"
    fi
    if command -v "$POVRAY" >/dev/null 2>&1; then
        (cd "$tmp" && "$POVRAY" +I"$scene" +O"$tmp/out.png" +W64 +H48 -D -V \
            +FN +Q9 +WT"$threads" >"$tmp/pov.log" 2>&1)
        pshot=$(sed -n 's/.*Number of photons shot: *\([0-9]*\).*/\1/p' "$tmp/pov.log")
        pstored=$(sed -n 's/.*Surface photons stored: *\([0-9]*\).*/\1/p' "$tmp/pov.log")
        ptime=$(sed -n 's/.*Photon Time:.*(\([0-9.]*\) seconds).*/\1/p' "$tmp/pov.log")
    else
        pshot=-; pstored=-; ptime=-
    fi
    echo "| $name | $(field "$one" shot) | $(field "$one" stored) |" \
        "$(field "$one" bytes_per_photon) |" \
        "$(field "$one" shoot_s) / $(field "$many" shoot_s) |" \
        "$(field "$one" build_s) / $(field "$many" build_s) |" \
        "$(field "$one" photons_per_s_per_thread) / $(field "$many" photons_per_s_per_thread) |" \
        "$(field "$one" photons_per_cpu_s) |" \
        "$(field "$one" gathers_per_s) | $(field "$one" gathers_per_cpu_s) |" \
        "${pshot:--} | ${pstored:--} | ${ptime:--} | $tracer |"
done
