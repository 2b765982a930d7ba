# SPDX-License-Identifier: MIT
# bench/lib.sh: what the benchmark scripts share. Source it after setting
# 'build' (a configured, built tree: the iris binary and tests/cli/imgtool).
#
#   time_median N CMD...   runs CMD N times (output discarded) and prints
#                          the median wall time in seconds
#   ratio A B              prints A/B with three decimals
#   default_scenes         prints the parity scenes and the example scenes
#                          of example-scenes.txt, one path a line (the
#                          scenes a bench renders when given none)

time_once() {
    t0=$(date +%s.%N)
    "$@" >/dev/null 2>&1
    rc=$?
    t1=$(date +%s.%N)
    echo "$t0 $t1" | awk '{printf "%.4f\n", $2 - $1}'
    return $rc
}

time_median() {
    n=$1; shift
    i=0
    : >"$BENCH_TMP/times"
    while [ $i -lt "$n" ]; do
        time_once "$@" >>"$BENCH_TMP/times" || { echo "fail"; return 1; }
        i=$((i + 1))
    done
    sort -n "$BENCH_TMP/times" | awk '{a[NR] = $1} END {
        if (NR % 2) printf "%.4f\n", a[(NR + 1) / 2];
        else printf "%.4f\n", (a[NR / 2] + a[NR / 2 + 1]) / 2 }'
}

ratio() { echo "$1 $2" | awk '{ if ($2 > 0) printf "%.3f\n", $1 / $2; else print "-" }'; }

median_of() { sort -n | awk '{a[NR] = $1} END { if (NR == 0) print "-";
    else if (NR % 2) print a[(NR + 1) / 2]; else printf "%.3f\n", (a[NR / 2] + a[NR / 2 + 1]) / 2 }'; }

bench_setup() {
    : "${build:?set build to a configured and built tree}"
    IRIS="$build/iris"
    IMGTOOL="$build/tests/cli/imgtool"
    POVRAY=${POVRAY:-povray}
    BENCH_TMP=$(mktemp -d)
    trap 'rm -rf "$BENCH_TMP"' EXIT
    [ -x "$IRIS" ] || { echo "bench: no iris binary in $build"; exit 1; }
    command -v "$POVRAY" >/dev/null || { echo "bench: povray not found"; exit 1; }
}

default_scenes() {
    printf '%s\n' "$here"/../tests/render/scenes/*.pov
    [ -f "$here/example-scenes.txt" ] || return 0
    while read -r s; do
        case $s in ''|'#'*) continue ;; esac
        echo "/usr/share/doc/povray/examples/$s"
    done <"$here/example-scenes.txt"
}
