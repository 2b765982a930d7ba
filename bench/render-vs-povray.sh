#!/bin/sh
# SPDX-License-Identifier: MIT
# bench/render-vs-povray.sh: render time of iris against POV-Ray 3.7 on the
# same scenes, size, antialiasing and thread count, in one run. Prints a
# Markdown table and the median ratios. Per scene and renderer it takes the
# median of N runs of
#   - the wall time of the whole program (start-up, parse, render, write);
#   - the render time alone: POV-Ray's "Trace Time" plus "Photon Time"
#     plus "Radiosity Time" from its statistics, iris's time_render_s plus
#     time_photon_s (--stats; iris's radiosity pretrace is inside its eye
#     pass, so inside time_render_s);
#   - the CPU seconds of the trace alone, summed over the threads:
#     POV-Ray's "using N thread(s) with S CPU-seconds total" under its
#     Trace Time, iris's time_render_cpu_s (the eye pass's tile loop);
# and the PSNR of iris's image against POV-Ray's (tests/render/psnr).
#
# On a loaded machine the wall times (and so the render ratio) measure
# the scheduler as much as the programs: with other processes runnable a
# render thread gets a varying share of a core (measured at load 7 on two
# cores: one iris render's two threads had 0.45 to 1.1 cores between
# them, runs a minute apart). The CPU ratio does not depend on the
# load (thread CPU clocks do not count waiting); on an idle machine, each
# thread on a core of its own, the two ratios should agree.
#
# The two render times span the same work: POV-Ray's Trace Time is the
# longest time a render thread spends in TraceTask::Run (task.cpp starts
# its timer after the thread's set-up), printed to 1 ms; iris's
# time_render_s is the wall time of the eye pass, thread start and
# per-thread set-up included (0.03 ms on an 8 x 8 image). Neither holds
# parsing, the bounding build or writing the image. The default size is
# 320 x 240: at 160 x 120 POV-Ray's times are 12-40 ms, so its 1 ms
# resolution and its 1 ms floor are several percent of them; -s keeps
# the smaller (or a larger) size at hand.
#
#   build=/path/to/build sh bench/render-vs-povray.sh [-n RUNS] [-s WxH]
#                        [-t THREADS] [-b BASE_BUILD] [scene.pov ...]
#
# -b BASE_BUILD also times the iris of another build (an older version)
# in the same loop, run for run between the other two, so that both see
# the same machine load; two more columns give its render time and the
# ratio of this build's to it (below 1: this build is faster).
#
# Without scenes it uses the parity scenes in tests/render/scenes and the
# example scenes listed in bench/example-scenes.txt. Each scene's
# directory is copied to a scratch directory, where both renderers run.
set -u
here=$(cd "$(dirname "$0")" && pwd)
. "$here/lib.sh"
runs=3; size=320x240; threads=2; base=
while getopts n:s:t:b: opt; do
    case $opt in
    n) runs=$OPTARG ;; s) size=$OPTARG ;; t) threads=$OPTARG ;;
    b) base=$OPTARG ;;
    *) exit 2 ;;
    esac
done
shift $((OPTIND - 1))
bench_setup
if [ -n "$base" ] && [ ! -x "$base/iris" ]; then
    echo "bench: no iris binary in $base"
    exit 1
fi
PSNR="$build/tests/render/psnr"
[ -x "$PSNR" ] || make -C "$build" tests/render/psnr >/dev/null 2>&1
w=${size%x*}; h=${size#*x}
# no scene given: the parity scenes and the example scenes (paths have no
# blanks, so word splitting is safe)
[ $# -eq 0 ] && set -- $(default_scenes)
common="+W$w +H$h +A0.3 +AM1 +R3"

# The seconds in POV-Ray's "<what> Time: ... (S seconds)" line, 0 if none.
pov_seconds() {
    sed -n "s/.*$1 Time:.*(\([0-9.]*\) seconds).*/\1/p" "$2" | head -n 1 |
        awk '{ print ($1 == "" ? 0 : $1) }'
}

# The CPU seconds on the "using N thread(s) with S CPU-seconds total" line
# under POV-Ray's "Trace Time", 0 if none.
pov_trace_cpu() {
    sed -n '/Trace Time:/{n;s/.*with \([0-9.]*\) CPU-seconds.*/\1/p;}' "$1" |
        head -n 1 | awk '{ print ($1 == "" ? 0 : $1) }'
}

# The value of "key" in iris's --stats JSON, 0 if none.
json_value() {
    sed -n "s/.*\"$1\": *\([0-9.eE+-]*\).*/\1/p" "$2" | head -n 1 |
        awk '{ print ($1 == "" ? 0 : $1) }'
}

# time_once with the program's output kept in file $1.
time_once_log() {
    log=$1; shift
    t0=$(date +%s.%N)
    "$@" >"$log" 2>&1
    rc=$?
    t1=$(date +%s.%N)
    echo "$t0 $t1" | awk '{printf "%.4f\n", $2 - $1}'
    return $rc
}

median_file() { sort -n "$1" | awk '{a[NR] = $1} END {
    if (NR == 0) print "fail"; else if (NR % 2) printf "%.4f\n", a[(NR + 1) / 2];
    else printf "%.4f\n", (a[NR / 2] + a[NR / 2 + 1]) / 2 }'; }

if [ -n "$base" ]; then
    echo "| scene | POV-Ray s | iris s | iris/POV-Ray | POV-Ray render s | iris render s | render ratio | POV-Ray trace CPU s | iris trace CPU s | CPU ratio | PSNR dB | base render s | iris/base render |"
    echo "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |"
else
    echo "| scene | POV-Ray s | iris s | iris/POV-Ray | POV-Ray render s | iris render s | render ratio | POV-Ray trace CPU s | iris trace CPU s | CPU ratio | PSNR dB |"
    echo "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |"
fi
: >"$BENCH_TMP/ratios"; : >"$BENCH_TMP/rratios"; : >"$BENCH_TMP/bratios"
: >"$BENCH_TMP/cratios"
for scene in "$@"; do
    [ -f "$scene" ] || continue
    case $scene in /*) ;; *) scene=$(pwd)/$scene ;; esac
    name=$(basename "$scene" .pov)
    work="$BENCH_TMP/work"
    rm -rf "$work"; mkdir -p "$work"
    cp -R "$(dirname "$scene")/." "$work/" 2>/dev/null
    : >"$BENCH_TMP/pw"; : >"$BENCH_TMP/iw"; : >"$BENCH_TMP/pr"; : >"$BENCH_TMP/ir"
    : >"$BENCH_TMP/br"; : >"$BENCH_TMP/pc"; : >"$BENCH_TMP/ic"
    ok=yes
    i=0
    while [ $i -lt "$runs" ]; do
        i=$((i + 1))
        # shellcheck disable=SC2086
        tp=$(cd "$work" && time_once_log "$BENCH_TMP/p.log" "$POVRAY" \
            "+I$scene" "+O$BENCH_TMP/p.png" $common +WT"$threads" -D -V +Q9 \
            +FN16) || ok=no
        # shellcheck disable=SC2086
        ti=$(cd "$work" && time_once "$IRIS" "$scene" -q -o "$BENCH_TMP/i.png" +FN16 \
            $common --threads="$threads" --stats="$BENCH_TMP/i.json") || ok=no
        echo "$tp" >>"$BENCH_TMP/pw"
        echo "$ti" >>"$BENCH_TMP/iw"
        echo "$(pov_seconds Trace "$BENCH_TMP/p.log") $(pov_seconds Photon "$BENCH_TMP/p.log") $(pov_seconds Radiosity "$BENCH_TMP/p.log")" |
            awk '{ print $1 + $2 + $3 }' >>"$BENCH_TMP/pr"
        pov_trace_cpu "$BENCH_TMP/p.log" >>"$BENCH_TMP/pc"
        json_value time_render_cpu_s "$BENCH_TMP/i.json" >>"$BENCH_TMP/ic"
        echo "$(json_value time_render_s "$BENCH_TMP/i.json") $(json_value time_photon_s "$BENCH_TMP/i.json")" |
            awk '{ print $1 + $2 }' >>"$BENCH_TMP/ir"
        if [ -n "$base" ]; then
            # shellcheck disable=SC2086
            (cd "$work" && "$base/iris" "$scene" -q -o "$BENCH_TMP/b.png" \
                +FN16 $common --threads="$threads" \
                --stats="$BENCH_TMP/b.json" >/dev/null 2>&1) &&
            echo "$(json_value time_render_s "$BENCH_TMP/b.json") $(json_value time_photon_s "$BENCH_TMP/b.json")" |
                awk '{ print $1 + $2 }' >>"$BENCH_TMP/br"
        fi
    done
    if [ $ok = no ]; then
        if [ -n "$base" ]; then
            echo "| $name | fail | fail | - | - | - | - | - | - | - | - | - | - |"
        else
            echo "| $name | fail | fail | - | - | - | - | - | - | - | - |"
        fi
        continue
    fi
    tp=$(median_file "$BENCH_TMP/pw"); ti=$(median_file "$BENCH_TMP/iw")
    rp=$(median_file "$BENCH_TMP/pr"); ri=$(median_file "$BENCH_TMP/ir")
    psnr=$("$PSNR" "$BENCH_TMP/i.png" "$BENCH_TMP/p.png" 2>/dev/null | cut -d' ' -f1)
    r=$(ratio "$ti" "$tp"); rr=$(ratio "$ri" "$rp")
    cp_=$(median_file "$BENCH_TMP/pc"); ci=$(median_file "$BENCH_TMP/ic")
    # an iris without time_render_cpu_s reports 0: no ratio then
    cr=$(echo "$ci" | awk '{ print ($1 > 0 ? "y" : "n") }')
    if [ "$cr" = y ]; then cr=$(ratio "$ci" "$cp_"); else cr=-; fi
    if [ -n "$base" ]; then
        rb=-; br=-
        if [ -s "$BENCH_TMP/br" ]; then
            rb=$(median_file "$BENCH_TMP/br"); br=$(ratio "$ri" "$rb")
        fi
        echo "| $name | $tp | $ti | $r | $rp | $ri | $rr | $cp_ | $ci | $cr | ${psnr:--} | $rb | $br |"
        echo "$br" >>"$BENCH_TMP/bratios"
    else
        echo "| $name | $tp | $ti | $r | $rp | $ri | $rr | $cp_ | $ci | $cr | ${psnr:--} |"
    fi
    echo "$cr" >>"$BENCH_TMP/cratios"
    echo "$r" >>"$BENCH_TMP/ratios"
    echo "$rr" >>"$BENCH_TMP/rratios"
done
echo
grep -v -- - "$BENCH_TMP/ratios" | median_of | sed 's/^/median iris\/POV-Ray wall-time ratio: /'
grep -v -- - "$BENCH_TMP/rratios" | median_of | sed 's/^/median iris\/POV-Ray render-time ratio: /'
grep -v -- - "$BENCH_TMP/cratios" | median_of | sed 's/^/median iris\/POV-Ray trace CPU ratio: /'
if [ -n "$base" ]; then
    grep -v -- - "$BENCH_TMP/bratios" | median_of | sed 's/^/median iris\/base render-time ratio: /'
fi
