#!/bin/sh
# SPDX-License-Identifier: MIT
# bench/memory.sh: peak RSS of one photon pass against the photons it
# shoots (issue 8), on bench/caustic_ball.pov: for 1e5 .. MAX photons
# emitted, the photons stored, the peak RSS (GNU time's maximum resident
# set), the bytes per stored photon above a run of 1000 photons (the
# program, scene and image alone), and the wall and CPU seconds.
# 'count N' emits about 0.444 N photons on this scene (POV-Ray's count
# estimate covers the ball's whole bounding sphere, the beam only part of
# it), so the script asks for 2.25x the photons it wants emitted.
#
#   build=/path/to/build sh bench/memory.sh [-m MAX] [-t THREADS] [-c]
#
# -c colours the light (rgb <1, 0.8, 0.5>): every path is then chromatic
# and stores one record per sibling wavelength (three, src/photon/trace.h),
# where the white light's paths store one white record each.
#
# MAX defaults to 1e8 (2.9 GB peak with the white light, ~80 CPU seconds;
# session 7); the photon pass refuses counts that the memory available
# cannot hold (membudget.h).
set -u
here=$(cd "$(dirname "$0")" && pwd)
max=100000000
threads=2
colour=0
while getopts m:t:c opt; do
    case $opt in
    m) max=$OPTARG ;;
    t) threads=$OPTARG ;;
    c) colour=1 ;;
    *) exit 2 ;;
    esac
done
: "${build:?set build to a configured and built tree}"
IRIS="$build/iris"
[ -x "$IRIS" ] || { echo "memory: no iris binary in $build"; exit 1; }
[ -x /usr/bin/time ] || { echo "memory: needs GNU time (/usr/bin/time)"; exit 1; }
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
scene="$here/caustic_ball.pov"
light="white light"
if [ "$colour" = 1 ]; then
    sed 's/color rgb 1 cylinder/color rgb <1, 0.8, 0.5> cylinder/' "$scene" \
        >"$tmp/caustic_ball_colour.pov"
    grep -q 'rgb <1, 0.8, 0.5> cylinder' "$tmp/caustic_ball_colour.pov" ||
        { echo "memory: the light of $scene was not found"; exit 1; }
    scene="$tmp/caustic_ball_colour.pov"
    light="light rgb <1, 0.8, 0.5>"
fi

# run COUNT: prints "stored peak_kB wall_s cpu_s emitted"
run() {
    /usr/bin/time -f "%M %e %U %S" -o "$tmp/time" "$IRIS" -q "$scene" \
        +W160 +H120 Declare=Photons="$1" --seed 1 --threads "$threads" \
        -o "$tmp/img.png" --stats "$tmp/stats.json" || return 1
    st=$(sed -n 's/.*"photons_stored": \([0-9]*\).*/\1/p' "$tmp/stats.json")
    em=$(sed -n 's/.*"photons_emitted": \([0-9]*\).*/\1/p' "$tmp/stats.json")
    awk -v s="$st" -v e="$em" '{ printf "%s %s %s %.2f %s\n", s, $1, $2, $3 + $4, e }' "$tmp/time"
}

base=$(run 1000) || { echo "memory: the baseline run failed"; exit 1; }
base_kb=$(echo "$base" | cut -d' ' -f2)
echo "scene: caustic_ball.pov ($light) 160x120, $threads threads; baseline (1000 photons): $base_kb kB peak RSS; load: $(uptime | sed 's/.*load average: //')"
echo "| photons emitted | stored | peak RSS MB | bytes / stored photon | bytes / emitted photon | wall s | CPU s |"
echo "| ---: | ---: | ---: | ---: | ---: | ---: | ---: |"
n=100000
while awk -v n="$n" -v m="$max" 'BEGIN { exit !(n <= m * 1.0001) }'; do
    count=$(awk -v n="$n" 'BEGIN { printf "%d", n * 2.25 }')
    if r=$(run "$count"); then
        echo "$r" | awk -v b="$base_kb" '{
            printf "| %d | %d | %.0f | %.1f | %.1f | %s | %s |\n", $5, $1,
                $2 / 1024, ($2 - b) * 1024 / $1, ($2 - b) * 1024 / $5, $3, $4 }'
    else
        echo "| $n | (run failed: see above) | | | | | |"
    fi
    n=$((n * 10))
done
