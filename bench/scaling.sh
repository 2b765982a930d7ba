#!/bin/sh
# SPDX-License-Identifier: MIT
# bench/scaling.sh: how progressive rendering scales (issue 8) on the
# caustic scene bench/caustic_ball.pov: 1 vs 2 threads (one process) and
# 1 vs 2 MPI ranks (one thread each), N passes, ROUNDS interleaved runs
# of each, medians,
# the speed-ups, the CPU time of all processes and the work done per
# CPU-second against 1 thread (the figure to compare on a loaded
# machine); then one 2-rank run's
# per-rank times (IRIS_RANK_TIMES: work, agreements, snapshots, the
# final reduction). The 2-thread run is also timed with
# IRIS_NO_PREFETCH=1 (each pass's map built after the previous eye pass
# instead of during it: src/render/progressive.c, PREFETCH), to show what
# that gains. Then the communication: MPI ranks exchange nothing
# while rendering; at the end (and at each write point) rank 0 reduces the
# double sum buffer, width·height·4 channels·8 bytes. From the measured
# time per pass and the measured fixed cost of a run, the script estimates
# the speed-up at 100 ranks.
#
#   build=/path/to/build sh bench/scaling.sh [-n PASSES] [-s WxH] [-p PHOTONS]
#                                             [-r ROUNDS]
#
# The MPI rows need a build configured with MPI (mpirun found).
# The images are PNG: an EXR goes through the OpenImageIO module, whose
# ~250 libraries cost 0.45 s of CPU to load and relocate; that was most of
# the "fixed cost of a run" (0.80 s) this script used to report.
# On a loaded machine wall times mislead: the script also reports the CPU
# time (user + sys) of the 1-thread runs, per pass.
set -u
here=$(cd "$(dirname "$0")" && pwd)
passes=8
size=160x120
photons=100000
rounds=5
while getopts n:s:p:r: opt; do
    case $opt in
    n) passes=$OPTARG ;;
    r) rounds=$OPTARG ;;
    s) size=$OPTARG ;;
    p) photons=$OPTARG ;;
    *) exit 2 ;;
    esac
done
: "${build:?set build to a configured and built tree}"
. "$here/lib.sh"
IRIS="$build/iris"
[ -x "$IRIS" ] || { echo "scaling: no iris binary in $build"; exit 1; }
BENCH_TMP=$(mktemp -d) || exit 1
trap 'rm -rf "$BENCH_TMP"' EXIT
export IRIS_MODULE_DIR="${IRIS_MODULE_DIR:-$build/.libs}"
w=${size%x*}
h=${size#*x}
scene="$here/caustic_ball.pov"
args="-q $scene +W$w +H$h Declare=Photons=$photons --passes $passes --seed 1"
MPIRUN=$(sed -n 's/^MPIRUN = //p' "$build/Makefile")
# localhost only, as in tests/mpi/mpi.sh
export OMPI_MCA_plm=isolated OMPI_MCA_btl=self,vader
mpi() { n=$1; shift
    "$MPIRUN" --oversubscribe --allow-run-as-root -n "$n" "$IRIS" "$@"; }
# the same for /usr/bin/time, which cannot run a shell function
mpirun="$MPIRUN --oversubscribe --allow-run-as-root"

# One run of each configuration per round, the rounds interleaved, so a
# change in the machine's other load hits every configuration alike; the
# medians over the rounds. Each line of $BENCH_TMP/runs: "label wall cpu"
# (cpu = user + sys of the whole process tree: both ranks and mpirun).
once() { label=$1; shift
    /usr/bin/time -f "%e %U %S" -o "$BENCH_TMP/t" "$@" >/dev/null 2>&1 ||
        { echo "scaling: $label failed" >&2; return 1; }
    awk -v l="$label" '{ printf "%s %s %.3f\n", l, $1, $2 + $3 }' \
        "$BENCH_TMP/t" >>"$BENCH_TMP/runs"
}
: >"$BENCH_TMP/runs"
echo "scene: caustic_ball.pov, ${w}x${h}, $photons photons a pass, $passes passes, $rounds interleaved rounds, medians"
echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)"
i=0
while [ $i -lt "$rounds" ]; do
    # shellcheck disable=SC2086
    once t1 "$IRIS" $args --threads 1 -o "$BENCH_TMP/a.png"
    # shellcheck disable=SC2086
    once t2 "$IRIS" $args --threads 2 -o "$BENCH_TMP/b.png"
    # shellcheck disable=SC2086
    once t2n env IRIS_NO_PREFETCH=1 "$IRIS" $args --threads 2 \
        -o "$BENCH_TMP/b2.png"
    if [ -n "$MPIRUN" ]; then
        # shellcheck disable=SC2086
        once r1 $mpirun -n 1 "$IRIS" $args --threads 1 -o "$BENCH_TMP/c.png"
        # shellcheck disable=SC2086
        once r2 $mpirun -n 2 "$IRIS" $args --threads 1 -o "$BENCH_TMP/d.png"
    fi
    i=$((i + 1))
done
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
med() { awk -v l="$1" -v c="$2" '$1 == l { print $c }' "$BENCH_TMP/runs" |
    median_of; }
t1=$(med t1 2); t2=$(med t2 2)
# The last column: the work done per CPU-second against the 1-thread
# run's (its CPU over this run's; the same work): below 1 where the second
# thread or rank costs CPU of its own (start-up, waiting that spins, two
# threads sharing a core's units or caches). On a loaded machine, where
# wall times mislead, it is the figure to compare.
cpu1=$(med t1 3)
echo "| run | wall s | speed-up | CPU s (all processes) | work per CPU-s |"
echo "| --- | ---: | ---: | ---: | ---: |"
echo "| 1 process, 1 thread | $t1 | 1.000 | $cpu1 | 1.000 |"
echo "| 1 process, 2 threads | $t2 | $(ratio "$t1" "$t2") | $(med t2 3) | $(ratio "$cpu1" "$(med t2 3)") |"
t2n=$(med t2n 2)
echo "| 1 process, 2 threads, IRIS_NO_PREFETCH=1 | $t2n | $(ratio "$t1" "$t2n") | $(med t2n 3) | $(ratio "$cpu1" "$(med t2n 3)") |"
r1=-; r2=-
if [ -n "$MPIRUN" ]; then
    r1=$(med r1 2); r2=$(med r2 2)
    echo "| mpirun -n 1, 1 thread | $r1 | $(ratio "$t1" "$r1") | $(med r1 3) | $(ratio "$cpu1" "$(med r1 3)") |"
    echo "| mpirun -n 2, 1 thread each | $r2 | $(ratio "$t1" "$r2") (vs -n 1: $(ratio "$r1" "$r2")) | $(med r2 3) | $(ratio "$cpu1" "$(med r2 3)") |"
    # Where each rank's time goes (progressive.c, IRIS_RANK_TIMES), and
    # the critical path in CPU seconds: the busier rank's process CPU
    # (waiting ranks sleep), which the machine's other load does not
    # inflate as it does wall time; against the 1-process run's CPU it
    # estimates the speed-up on an idle machine (leaving out mpirun's own
    # start and end: see the 'mpirun -n 1' row). Median of 3 runs.
    for k in 1 2 3; do
        # shellcheck disable=SC2086
        IRIS_RANK_TIMES=1 mpi 2 $args --threads 1 -o "$BENCH_TMP/f.png" \
            2>&1 >/dev/null | sed -n 's/^iris: //p' >"$BENCH_TMP/rt$k"
    done
    sed 's/^/  /' "$BENCH_TMP/rt1"
    crit=$(for k in 1 2 3; do
        awk '{ c = $(NF - 1); if (c > m) m = c } END { print m }' \
            "$BENCH_TMP/rt$k"; done | median_of)
    echo "critical path (the busier rank's CPU): $crit s, against $(med t1 3) s of CPU in one process: $(ratio "$(med t1 3)" "$crit")x on an idle machine"
else
    echo "(no MPI in this build: the rank rows are skipped)"
fi

# The fixed cost of a run (parse, acceleration structure, pass 0's map,
# process start) from a 1-pass run; the rest divided by N is one pass.
# shellcheck disable=SC2086
t0=$(time_median 3 "$IRIS" -q "$scene" +W$w +H$h Declare=Photons=$photons \
    --seed 1 --threads 1 -o "$BENCH_TMP/e.png")
bytes=$((w * h * 4 * 8))
echo
echo "fixed cost of a run (1 pass): $t0 s; one pass: $(echo "$t1 $t0 $passes" |
    awk '{ printf "%.4f", ($1 - $2) / ($3 - 1) }') s (1 thread)"
echo "communication: one reduction of $bytes bytes (${w}x${h} x 4 channels x 8 bytes) a write point, none per pass"
# At R = 100 ranks with P = 100·k passes: compute (P/R)·t_pass, plus the
# fixed cost (every rank parses and builds its structures in parallel, so
# it does not shrink), plus a tree reduction: log2(R) steps of 'bytes' at
# an assumed 1 GB/s (10 Gb Ethernet) and 50 us latency per step.
echo "$t1 $t0 $passes $bytes $r1 $r2" | awk '{
    tp = ($1 - $2) / ($3 - 1); fixed = $2; B = $4
    if (tp <= 0) { print "estimate: pass time not measurable"; exit }
    red = log(100) / log(2) * (B / 1e9 + 50e-6)
    printf "reduction at 100 ranks (tree, 1 GB/s, 50 us/step): %.2f ms\n", red * 1000
    n = split("100 1000 10000", P, " ")
    for (i = 1; i <= n; i++) {
        ser = fixed + P[i] * tp
        par = fixed + (P[i] / 100) * tp + red
        printf "estimated speed-up at 100 ranks, %d passes: %.1f (serial %.1f s, 100 ranks %.2f s)\n", P[i], ser / par, ser, par
    }
    if ($5 != "-" && $6 != "-" && $5 > 0)
        printf "measured overhead of 2 ranks over an ideal halving: %.3f s\n", $6 - ($5 - fixed) / 2 - fixed
}'
# CPU time per pass (1 thread): independent of the machine's other load
cpu_of() { /usr/bin/time -f "%U %S" "$@" 2>&1 >/dev/null | tail -1 |
    awk '{ printf "%.3f\n", $1 + $2 }'; }
if [ -x /usr/bin/time ]; then
    # shellcheck disable=SC2086
    c1=$(cpu_of "$IRIS" -q "$scene" +W$w +H$h Declare=Photons=$photons \
        --seed 1 --threads 1 -o "$BENCH_TMP/f.png")
    # shellcheck disable=SC2086
    cn=$(cpu_of "$IRIS" $args --threads 1 -o "$BENCH_TMP/g.png")
    echo "CPU time (1 thread): 1 pass $c1 s, $passes passes $cn s," \
        "$(echo "$cn $c1 $passes" | awk '{ printf "%.4f", ($1 - $2) / ($3 - 1) }') s a pass"
fi
echo "(the reduction is negligible; MPI_Init overlaps the first round (mpi_passes.c), the blocks after it are shared by the ranks' speeds and waiting ranks sleep; what is left is mpirun's start and end, every rank's own parse and start-up, and the first round's spread: see the rank times above)"
