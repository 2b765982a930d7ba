#!/bin/sh
# SPDX-License-Identifier: MIT
# bench/examples-psnr.sh: renders the POV-Ray example scenes with POV-Ray
# 3.7 and with iris at the same size and prints one Markdown table row per
# scene: iris's status, the PSNR of iris against POV-Ray, both render
# times, and the features that legitimately make the images differ
# (radiosity, media, photons, subsurface, clock-driven animation, rand()
# streams, a working gamma other than 1), then a summary.
#
#   build=/path/to/build sh bench/examples-psnr.sh [-j JOBS] [-1] [-s WxH]
#                                    [-o 'OPTS'] [DIR | scene.pov ...]
#
#   -j JOBS   scenes rendered at once (default 1); each renderer uses one
#             thread, so the times compare one core with one core
#   -1        only the first scene of every directory (a quick subset)
#   -s WxH    image size (default 160x120)
#   -o OPTS   extra POV-Ray switches given to both renderers after the
#             defaults, split at blanks: '+A0.3 +AM1 +R3 -J' compares the
#             antialiased images (jitter off keeps both deterministic);
#             with +UA among them the PSNR covers the alpha channel too
#             (psnr --rgba)
#   TIMEOUT   seconds per render (default 60); MEMLIMIT KiB (2000000)
#
# Each scene's directory is copied to a scratch directory first, because
# scenes include and write local files. POV-Ray runs as
# 'povray +I.. +O.. +W.. +H.. -D -V -GA +FN16 +WT1' (no antialiasing, the
# quality +Q9 of /etc/povray/3.7/povray.ini, so photons are on), iris as
# 'iris scene.pov -q -o x.png +FN16 +W.. +H.. --threads=1' (16-bit PNG, as
# POV-Ray's, written without loading the OpenImageIO module). The PSNR is
# tests/render/psnr's (sRGB display values, peak 1): build it with
# 'make -C $build tests/render/psnr'.
#
# Status: rendered; parse error (exit 2, the first diagnostic is shown);
# failed (exit 1); crash (a signal or another exit code); timeout;
# "no reference" when POV-Ray itself renders nothing.
set -u
here=$(cd "$(dirname "$0")" && pwd)
: "${build:?set build to a configured and built tree}"
case $build in /*) ;; *) build=$(pwd)/$build ;; esac
IRIS=${IRIS:-$build/iris}
PSNR=${PSNR:-$build/tests/render/psnr}
POVRAY=${POVRAY:-povray}
TIMEOUT=${TIMEOUT:-60}
MEMLIMIT=${MEMLIMIT:-2000000}
jobs=1; first_only=0; size=160x120; extra=""
while getopts j:1s:o: opt; do
    case $opt in
    j) jobs=$OPTARG ;; 1) first_only=1 ;; s) size=$OPTARG ;;
    o) extra=$OPTARG ;;
    *) exit 2 ;;
    esac
done
shift $((OPTIND - 1))
w=${size%x*}; h=${size#*x}
# +UA: alpha output, compared with the colour (the switches are
# case-insensitive)
psnr_mode=""
case " $(printf '%s' "$extra" | tr 'a-z' 'A-Z') " in
*" +UA "*) psnr_mode=--rgba ;;
esac
[ -x "$IRIS" ] || { echo "examples-psnr: no iris binary at $IRIS"; exit 1; }
[ -x "$PSNR" ] || make -C "$build" tests/render/psnr >/dev/null 2>&1 ||
    { echo "examples-psnr: cannot build $PSNR"; exit 1; }
command -v "$POVRAY" >/dev/null || { echo "examples-psnr: no povray"; exit 1; }

tmp=$(mktemp -d) || exit 1
# a signal ends the run (a trap alone would let the loop go on)
trap 'rm -rf "$tmp"' EXIT
trap 'exit 130' INT TERM

DIR=/usr/share/doc/povray/examples
if [ $# -eq 1 ] && [ -d "$1" ]; then
    DIR=$1
    set --
fi
if [ $# -eq 0 ]; then
    find "$DIR" -name '*.pov' | LC_ALL=C sort > "$tmp/all"
else
    for s in "$@"; do
        case $s in /*) echo "$s" ;; *) echo "$(pwd)/$s" ;; esac
    done > "$tmp/all"
fi
if [ $first_only -eq 1 ]; then
    awk '{ d = $0; sub(/\/[^\/]*$/, "", d); if (!(d in seen)) print; seen[d] = 1 }' \
        "$tmp/all" > "$tmp/list"
else
    cp "$tmp/all" "$tmp/list"
fi

# The features that make a POV-Ray image legitimately differ from iris's,
# found in the scene and the local files it includes.
features() {
    files="$1"
    for inc in $(sed -n 's/^[[:space:]]*#include[[:space:]]*"\([^"]*\)".*/\1/p' "$1"); do
        [ -f "$(dirname "$1")/$inc" ] && files="$files $(dirname "$1")/$inc"
    done
    tags=""
    # shellcheck disable=SC2086
    text=$(sed 's|//.*||' $files 2>/dev/null)
    for f in radiosity media photons clock subsurface rand; do
        if printf '%s\n' "$text" | grep -qw "$f"; then tags="$tags,$f"; fi
    done
    # a working gamma other than 1 (POV-Ray shades in that space)
    if printf '%s\n' "$text" |
        grep -E 'assumed_gamma[[:space:]]+[0-9.]+' |
        grep -vqE 'assumed_gamma[[:space:]]+1(\.0*)?([^0-9.]|$)'; then
        tags="$tags,gamma"
    fi
    echo "${tags#,}"
}

now() { date +%s.%N; }

# One scene: writes "rel|status|psnr|pov_s|iris_s|features|diagnostic".
one() {
    scene=$1; id=$2
    rel=${scene#"$DIR"/}
    work="$tmp/w$id"
    mkdir -p "$work/p" "$work/i"
    cp -R "$(dirname "$scene")/." "$work/p/" 2>/dev/null
    cp -R "$(dirname "$scene")/." "$work/i/" 2>/dev/null
    base=$(basename "$scene")
    t0=$(now)
    ( cd "$work/p" && ulimit -v "$MEMLIMIT" 2>/dev/null
      exec timeout "$TIMEOUT" "$POVRAY" "+I$base" "+O$work/pov.png" \
          "+W$w" "+H$h" -D -V -GA +FN16 +WT1 $extra ) >"$work/pov.log" 2>&1 </dev/null
    t1=$(now)
    ( cd "$work/i" && ulimit -v "$MEMLIMIT" 2>/dev/null
      exec timeout "$TIMEOUT" "$IRIS" "$base" -q -o "$work/iris.png" +FN16 \
          "+W$w" "+H$h" --threads=1 $extra ) >"$work/iris.log" 2>&1 </dev/null
    rc=$?
    t2=$(now)
    tp=$(echo "$t0 $t1" | awk '{printf "%.2f", $2 - $1}')
    ti=$(echo "$t1 $t2" | awk '{printf "%.2f", $2 - $1}')
    diag=""
    case $rc in
    0) status=rendered ;;
    2) status="parse error"
       diag=$(grep -m 1 -i 'error' "$work/iris.log" || grep -m 1 . "$work/iris.log") ;;
    1) status=failed; diag=$(grep -m 1 . "$work/iris.log") ;;
    124) status=timeout ;;
    *) status="crash ($rc)"; diag=$(grep -m 1 . "$work/iris.log") ;;
    esac
    diag=$(printf '%s' "$diag" | sed "s|$work/i/||g; s/|/\\\\|/g" | cut -c 1-100)
    db="-"
    if [ ! -s "$work/pov.png" ]; then
        [ $rc -eq 0 ] && status="rendered, no reference"
    elif [ $rc -eq 0 ]; then
        # shellcheck disable=SC2086 (no mode: no argument)
        db=$("$PSNR" $psnr_mode "$work/iris.png" "$work/pov.png" 2>/dev/null |
             cut -d' ' -f1)
        [ -n "$db" ] || db="-"
    fi
    [ -n "${KEEP:-}" ] && mkdir -p "$KEEP/$(dirname "$rel")" &&
        cp "$work/pov.png" "$KEEP/${rel%.pov}.pov.png" 2>/dev/null &&
        cp "$work/iris.png" "$KEEP/${rel%.pov}.iris.png" 2>/dev/null
    echo "$rel|$status|$db|$tp|$ti|$(features "$scene")|$diag" >"$tmp/r$id"
    rm -rf "$work"
}

n=$(wc -l < "$tmp/list")
# At most 'jobs' scenes at once: a slot is a line in a FIFO, taken before
# a scene starts and given back when it ends.
mkfifo "$tmp/slots"
exec 3<>"$tmp/slots"
k=0
while [ $k -lt "$jobs" ]; do echo >&3; k=$((k + 1)); done
i=0
while IFS= read -r scene; do
    i=$((i + 1))
    read -r _ <&3
    { one "$scene" "$i"; echo >&3; } &
done < "$tmp/list"
wait
exec 3>&-

echo "| scene | iris | PSNR dB | POV-Ray s | iris s | features | first diagnostic |"
echo "| --- | --- | ---: | ---: | ---: | --- | --- |"
i=0
while [ $i -lt "$n" ]; do
    i=$((i + 1))
    [ -f "$tmp/r$i" ] || continue
    awk -F'|' '{ printf "|"; for (i = 1; i <= NF; i++) printf " %s |", $i
                 print "" }' "$tmp/r$i"
    cat "$tmp/r$i" >> "$tmp/results"
done
echo
awk -F'|' -v n="$n" '
    { st[$2]++ }
    $2 == "rendered" && $3 != "-" {
        v = ($3 == "inf") ? 99 : $3 + 0
        psnr[++np] = v
        if ($6 == "") clean[++nc] = v
    }
    function median(a, m,   i, j, t) {
        for (i = 1; i <= m; i++) for (j = i + 1; j <= m; j++)
            if (a[j] < a[i]) { t = a[i]; a[i] = a[j]; a[j] = t }
        if (m == 0) return "-"
        return (m % 2) ? a[(m + 1) / 2] : (a[m / 2] + a[m / 2 + 1]) / 2
    }
    END {
        printf "scenes: %d\n", n
        for (s in st) printf "  %s: %d\n", s, st[s]
        printf "median PSNR of %d compared renders: %s dB\n", np, median(psnr, np)
        printf "median PSNR without tagged features (%d): %s dB\n", nc, median(clean, nc)
        split("0 15 20 25 30 35 40", lo, " ")
        for (b = 1; b <= 7; b++) {
            c = 0
            for (i = 1; i <= np; i++)
                if (psnr[i] >= lo[b] && (b == 7 || psnr[i] < lo[b + 1])) c++
            printf "  PSNR %s%s: %d\n", lo[b], b == 7 ? "+" : "-" lo[b + 1], c
        }
    }' "$tmp/results"
