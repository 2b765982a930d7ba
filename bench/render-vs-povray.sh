#!/bin/sh
# SPDX-License-Identifier: MIT
# bench/render-vs-povray.sh: render time of iris against POV-Ray 3.7 on the
# same scenes, size, antialiasing and thread count, in one run. Prints a
# Markdown table (median of N runs per renderer, the ratio iris/POV-Ray,
# and the PSNR of iris against POV-Ray) and the median ratio.
#
#   build=/path/to/build sh bench/render-vs-povray.sh [-n RUNS] [-s WxH]
#                        [-t THREADS] [scene.pov ...]
#
# Without scenes it uses the parity scenes in tests/render/scenes and the
# example scenes listed in bench/example-scenes.txt.
set -u
here=$(cd "$(dirname "$0")" && pwd)
. "$here/lib.sh"
runs=3; size=160x120; threads=2
while getopts n:s:t: opt; do
    case $opt in
    n) runs=$OPTARG ;; s) size=$OPTARG ;; t) threads=$OPTARG ;;
    *) exit 2 ;;
    esac
done
shift $((OPTIND - 1))
bench_setup
w=${size%x*}; h=${size#*x}
if [ $# -eq 0 ]; then
    set -- "$here"/../tests/render/scenes/*.pov
    if [ -f "$here/example-scenes.txt" ]; then
        while read -r s; do
            case $s in ''|'#'*) continue ;; esac
            set -- "$@" "/usr/share/doc/povray/examples/$s"
        done <"$here/example-scenes.txt"
    fi
fi
common="+W$w +H$h +A0.3 +AM1 +R3"
echo "| scene | POV-Ray s | iris s | iris/POV-Ray | PSNR dB |"
echo "| --- | ---: | ---: | ---: | ---: |"
for scene in "$@"; do
    [ -f "$scene" ] || continue
    name=$(basename "$scene" .pov)
    dir=$(dirname "$scene")
    tp=$(cd "$dir" && time_median "$runs" "$POVRAY" "+I$scene" "+O$BENCH_TMP/p.png" $common +WT"$threads" -D -V +Q9 +FN16)
    ti=$(cd "$dir" && time_median "$runs" "$IRIS" "$scene" -q -o "$BENCH_TMP/i.exr" $common --threads="$threads")
    psnr=$("$IMGTOOL" psnr "$BENCH_TMP/p.png" "$BENCH_TMP/i.exr" 2>/dev/null || echo "-")
    r=$( [ "$tp" = fail ] || [ "$ti" = fail ] && echo "-" || ratio "$ti" "$tp")
    echo "| $name | $tp | $ti | $r | $psnr |"
    echo "$r" >>"$BENCH_TMP/ratios"
done
grep -v -- - "$BENCH_TMP/ratios" 2>/dev/null | median_of | sed 's/^/median iris\/POV-Ray time ratio: /'
