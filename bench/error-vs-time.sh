#!/bin/sh
# SPDX-License-Identifier: MIT
# bench/error-vs-time.sh: progressive iris against POV-Ray 3.7 on caustics,
# error against wall time, in one run (issue 6).
#
#   build=/path/to/build sh bench/error-vs-time.sh [-s SIZE] [-t THREADS]
#       [-T SECONDS] [-c "1e4 1e5 1e6 1e7"] [-o OUTDIR] [-a]
#
# The clear-ball caustic (bench/caustic_ball.pov) is measured against its
# semi-analytic reference (tools/ball_reference). POV-Ray renders it once
# per photon count (count N through Declare=Photons=N, OpenEXR output), as
# the plain clear ball and again with reflection {fresnel} conserve_energy
# (Declare=Fresnel=1: only then do its photons lose the reflected share);
# each run's wall time and error are one point; iris renders it once with
# --time-limit SECONDS and --error-log, which gives its whole curve (the
# log's times count from the start of rendering; the process's start-up
# and parse, timed with --parse-only, are added to every point, so the
# times are whole wall times like POV-Ray's, without the reading of the
# reference image, which is the benchmark's instrument). Errors are
# linear RGB over all pixels: rel_rmse = RMS(image - reference) /
# RMS(reference) (passlog.c).
#
# With -a the photon scenes of scenes/ follow, against a long iris run
# (4 x SECONDS, another seed) as the reference: POV-Ray's error there also
# holds every difference of its model (RGB vs spectral, docs/photons.md),
# so only the trend of iris's curve is meaningful.
#
# Output in OUTDIR (default ./error-vs-time): NAME-iris.csv,
# NAME-povray.csv, NAME-povray-fresnel.csv (same columns), NAME.png (the
# log-log plot) and the table on stdout. The goals of issue 6 for the
# ball: iris reaches POV-Ray's lowest error within 1/5 of POV-Ray's time
# at 1e6 photons, and rel_rmse <= 3% within 16 s (2 cores, 128 x 128).
set -u
here=$(cd "$(dirname "$0")" && pwd)
size=128 threads=2 tmax=32 counts="1e4 1e5 1e6 1e7" outdir=error-vs-time
all=0
while getopts s:t:T:c:o:a opt; do
    case $opt in
    s) size=$OPTARG ;;
    t) threads=$OPTARG ;;
    T) tmax=$OPTARG ;;
    c) counts=$OPTARG ;;
    o) outdir=$OPTARG ;;
    a) all=1 ;;
    *) exit 2 ;;
    esac
done
: "${build:?set build to a configured and built tree}"
IRIS="$build/iris"
POVRAY=${POVRAY:-povray}
export IRIS_MODULE_DIR=${IRIS_MODULE_DIR:-$build/.libs}
make -C "$build" tools/ball_reference tools/error_plot >/dev/null || exit 1
ref_tool="$build/tools/ball_reference"
plot="$build/tools/error_plot"
command -v "$POVRAY" >/dev/null || { echo "bench: povray not found"; exit 1; }
mkdir -p "$outdir" || exit 1
outdir=$(cd "$outdir" && pwd)
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
header="time_s,passes,photons,rmse,rel_rmse,bias"

now() { date +%s.%N; }
sub() { echo "$1 $2" | awk '{ printf "%.3f", $1 - $2 }'; }

# POV-Ray at each photon count: one CSV line per run.
# pov_curve SCENE REF NAME [SUFFIX DECLARE]: writes NAME-povraySUFFIX.csv
pov_curve() {
    scene=$1 ref=$2 name=$3 suffix=${4:-} extra=${5:-}
    csv="$outdir/$name-povray$suffix.csv"
    echo "$header" >"$csv"
    for c in $counts; do
        n=$(echo "$c" | awk '{ printf "%d", $1 }')
        if [ "$name" = caustic_ball ]; then
            src=$scene
            decl="Declare=Photons=$n"
        else # a copy of the scene with 'count N' instead of its spacing
            src="$tmp/$name-$n.pov"
            sed -e "s/photons *{ *spacing [0-9.eE+-]*/photons { count $n/" \
                "$scene" >"$src"
            decl=""
        fi
        t0=$(now)
        (cd "$(dirname "$scene")" && "$POVRAY" +I"$src" +O"$tmp/pov.exr" \
            +W"$size" +H"$size" -D -V +FE +WT"$threads" $decl $extra \
            +L"$(dirname "$scene")" >"$tmp/pov.log" 2>&1)
        t1=$(now)
        shot=$(sed -n 's/.*Number of photons shot: *\([0-9]*\).*/\1/p' \
            "$tmp/pov.log")
        err=$("$plot" --error "$ref" "$tmp/pov.exr") || continue
        echo "$(sub "$t1" "$t0"),1,${shot:-0},$err" >>"$csv"
    done
}

# iris with a time limit: its error log, times shifted to wall time.
# iris_curve SCENE REF NAME
iris_curve() {
    scene=$1 ref=$2 name=$3
    rm -f "$tmp/iris.csv"
    "$IRIS" -q "$scene" +W"$size" +H"$size" --threads "$threads" \
        --time-limit "$tmax" --reference "$ref" --error-log "$tmp/iris.csv" \
        -o "$outdir/$name-iris.exr"
    # The log counts from the start of rendering. Before it come the
    # process start and the parse (timed here with --parse-only) and the
    # reading of the reference, which loads OpenImageIO (~0.3-1 s): that
    # is the benchmark's instrument, not rendering, and is not counted
    # (a run writing PNG never loads it).
    t0=$(now)
    "$IRIS" -q --parse-only "$scene" +W"$size" +H"$size"
    t1=$(now)
    off=$(sub "$t1" "$t0")
    awk -F, -v off="$off" 'BEGIN { OFS = "," } NR == 1 { print; next }
        { $1 = sprintf("%.3f", $1 + off); print }' "$tmp/iris.csv" \
        >"$outdir/$name-iris.csv"
}

# The table: POV-Ray's points, iris at powers of two seconds; the plot.
report() {
    name=$1
    echo
    echo "## $name ($size x $size, $threads threads)"
    echo
    echo "| renderer | photons | passes | wall s | rel. RMSE | bias |"
    echo "| --- | ---: | ---: | ---: | ---: | ---: |"
    series=""
    for f in "$outdir/$name-povray.csv" "$outdir/$name-povray-fresnel.csv"; do
        [ -f "$f" ] || continue
        label="POV-Ray"
        case $f in *-fresnel.csv) label="POV-Ray fresnel" ;; esac
        awk -F, -v l="$label" 'NR > 1 {
            printf "| %s | %d | 1 | %.2f | %.4f | %+.4f |\n", l, $3, $1, $5, $6
        }' "$f"
        series="$series ${label% *}$([ "$label" = POV-Ray ] || echo -fresnel)=$f"
    done
    awk -F, 'NR > 1 { line[NR] = $0; n = NR }
        END { want = 0.5
              for (i = 2; i <= n; i++) {
                  split(line[i], f, ",")
                  if (f[1] >= want || i == n) {
                      printf "| iris | %d | %d | %.2f | %.4f | %+.4f |\n",
                          f[3], f[2], f[1], f[5], f[6]
                      while (want <= f[1]) want *= 2
                  }
              } }' "$outdir/$name-iris.csv"
    # shellcheck disable=SC2086 # series holds NAME=file words
    "$plot" "$outdir/$name.png" iris="$outdir/$name-iris.csv" $series \
        >"$tmp/legend" && echo && echo "plot: $outdir/$name.png" &&
        sed 's/^/  /' "$tmp/legend"
}

# goals POV-CSV LABEL: issue 6's goals against one POV-Ray curve
goals() {
    pov=$1 iris="$outdir/caustic_ball-iris.csv"
    best=$(awk -F, 'NR > 1 && (m == "" || $5 < m) { m = $5 } END { print m }' "$pov")
    t1m=$(awk -F, 'NR > 1 && $3 + 0 > 0 { print $1, $3 }' "$pov" |
        awk '{ d = $2 / 1e6; d = d > 1 ? d : 1 / d
               if (b == "" || d < b) { b = d; t = $1 } } END { print t }')
    reach=$(awk -F, -v m="$best" 'NR > 1 && $5 <= m { print $1; exit }' "$iris")
    at16=$(awk -F, 'NR > 1 { if ($1 <= 16) e = $5; t = $1 }
        END { print (t >= 16 ? e : "-") }' "$iris")
    echo
    echo "Against $2:"
    echo "  POV-Ray's lowest rel. RMSE: $best; its time at ~1e6 photons: ${t1m:-?} s"
    echo "  iris reaches it after: ${reach:-never (within $tmax s)} s" \
        "(goal: <= $(echo "${t1m:-0}" | awk '{ printf "%.2f", $1 / 5 }') s)"
    echo "  iris rel. RMSE at 16 s: ${at16:--} (goal: <= 0.03)"
}

# The clear ball against its semi-analytic reference. POV-Ray twice: the
# plain clear ball (its photons refract at full power: ~10% too bright) and
# with reflection {fresnel} conserve_energy (its photons then lose the
# reflected share, as iris's always do).
"$ref_tool" "$size" "$size" "$outdir/caustic_ball-ref.exr" || exit 1
pov_curve "$here/caustic_ball.pov" "$outdir/caustic_ball-ref.exr" \
    caustic_ball "" Declare=Fresnel=0
pov_curve "$here/caustic_ball.pov" "$outdir/caustic_ball-ref.exr" \
    caustic_ball -fresnel Declare=Fresnel=1
iris_curve "$here/caustic_ball.pov" "$outdir/caustic_ball-ref.exr" caustic_ball
report caustic_ball
goals "$outdir/caustic_ball-povray.csv" "POV-Ray, plain clear ball"
goals "$outdir/caustic_ball-povray-fresnel.csv" \
    "POV-Ray, reflection {fresnel} conserve_energy"

[ "$all" -eq 1 ] || exit 0
# (sh has no local variables: the loop's names differ from the functions')
for sn in glass_sphere prism lens gem cornell_glass; do
    sp="$here/../scenes/$sn.pov"
    [ -f "$sp" ] || continue
    "$IRIS" -q "$sp" +W"$size" +H"$size" --threads "$threads" --seed 99 \
        --time-limit $((tmax * 4)) -o "$outdir/$sn-ref.exr" || continue
    pov_curve "$sp" "$outdir/$sn-ref.exr" "$sn"
    iris_curve "$sp" "$outdir/$sn-ref.exr" "$sn"
    report "$sn"
done
