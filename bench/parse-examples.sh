#!/bin/sh
# SPDX-License-Identifier: MIT
# bench/parse-examples.sh: parses every POV-Ray example scene with
# 'iris --parse-only' and prints one line per scene (status, time, first
# diagnostic) and the totals. Each scene's directory is copied to a
# scratch directory first, because scenes include and write local files.
# Every parse runs under a time limit and a memory limit, so a hang or a
# runaway allocation shows up as "timeout" or "crash", never stalls the run.
#
# usage: build=/path/to/build bench/parse-examples.sh [--povray] [DIR]
#   IRIS      the iris binary (default $build/iris)
#   PARSEDUMP the parser driver of the tests (default
#             $build/tests/parse/parsedump, built by make check): when it
#             exists, the 'parser_s' column is the time iris_parse_file()
#             itself took (parsedump -t), the counterpart of POV-Ray's own
#             "Parse Time", which also excludes its start-up
#   DIR       where the scenes are (default /usr/share/doc/povray/examples)
#   --povray  also run POV-Ray on each scene (tiny image) and report its
#             own "Parse Time" next to ours, and the number of light
#             sources each found (column 'lights' iris/POV-Ray; a mismatch
#             is flagged with '!')
#   TIMEOUT   seconds per scene (default 30); MEMLIMIT KiB (default 2000000)
#   W, H      image size given to every parser (default 16x12, POV-Ray's
#             render is that small so that its time is mostly parsing)
#
# Status: ok (parsed), error (stopped with a diagnostic: the first one is
# shown), timeout, crash (killed by a signal or an unexpected exit code).
# The goal is no timeout/crash and >= 90% ok.

build=${build:-.}
IRIS=${IRIS:-$build/iris}
PARSEDUMP=${PARSEDUMP:-$build/tests/parse/parsedump}
POVRAY=${POVRAY:-povray}
TIMEOUT=${TIMEOUT:-30}
# Both parsers see the same image_width/image_height (scenes such as the
# mesh_camera demos build one triangle per pixel while parsing).
W=${W:-16}
H=${H:-12}
MEMLIMIT=${MEMLIMIT:-2000000}
with_pov=0
if [ "$1" = "--povray" ]; then
    with_pov=1
    shift
fi
DIR=${1:-/usr/share/doc/povray/examples}

[ -x "$IRIS" ] || { echo "parse-examples: no iris binary at $IRIS (set build or IRIS)"; exit 1; }
[ -d "$DIR" ] || { echo "parse-examples: no scenes in $DIR"; exit 1; }
case $IRIS in /*) ;; *) IRIS=$(pwd)/$IRIS ;; esac
case $PARSEDUMP in /*) ;; *) PARSEDUMP=$(pwd)/$PARSEDUMP ;; esac

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
trap 'exit 130' INT TERM

now() { date +%s.%N; }

n=0; n_ok=0; n_err=0; n_to=0; n_crash=0
printf '%-50s %-7s %7s %8s %8s  %s\n' scene status iris_s parser_s povray_s \
    first_diagnostic
find "$DIR" -name '*.pov' | LC_ALL=C sort > "$tmp/list"
while IFS= read -r scene; do
    n=$((n + 1))
    rel=${scene#"$DIR"/}
    src=$(dirname "$scene")
    work="$tmp/w$n"
    mkdir -p "$work"
    cp -R "$src/." "$work/" 2>/dev/null
    base=$(basename "$scene")
    t0=$(now)
    ( cd "$work" && ulimit -v "$MEMLIMIT" 2>/dev/null
      exec timeout "$TIMEOUT" "$IRIS" --parse-only +W$W +H$H "$base" ) \
        >"$tmp/out" 2>&1 </dev/null
    rc=$?
    t1=$(now)
    secs=$(echo "$t0 $t1" | awk '{printf "%.3f", $2 - $1}')
    case $rc in
        0) status=ok; n_ok=$((n_ok + 1)) ;;
        2) status=error; n_err=$((n_err + 1)) ;;
        124) status=timeout; n_to=$((n_to + 1)) ;;
        *) status=crash; n_crash=$((n_crash + 1)) ;;
    esac
    diag=$(grep -m1 -E ': error: ' "$tmp/out" | cut -c1-110)
    [ "$status" = crash ] && diag="exit $rc $diag"
    psecs=-
    if [ -x "$PARSEDUMP" ]; then
        ( cd "$work" && ulimit -v "$MEMLIMIT" 2>/dev/null
          exec timeout "$TIMEOUT" "$PARSEDUMP" -t -w -s "${W}x$H" "$base" ) \
            >"$tmp/dump" 2>"$tmp/ptime" </dev/null
        psecs=$(sed -n 's/^parse time: \([0-9.]*\) s$/\1/p' "$tmp/ptime" |
                awk '{printf "%.3f", $1}')
        [ -n "$psecs" ] || psecs=-
    fi
    pov=-
    if [ $with_pov -eq 1 ]; then
        ( cd "$work" && exec timeout 120 "$POVRAY" "+I$base" +O"$tmp/pov.png" \
            +W$W +H$H -D +Q0 +FN ) >"$tmp/pov" 2>&1 </dev/null
        pov=$(grep -m1 'Parse Time' "$tmp/pov" | sed 's/.*(\([0-9.]*\) seconds).*/\1/')
        [ -n "$pov" ] || pov=fail
        lp=$(grep -m1 'Light Sources:' "$tmp/pov" | awk '{print $3}')
        li=$(grep -c '^light ' "$tmp/dump" 2>/dev/null)
        if [ -n "$lp" ] && [ "$status" = ok ]; then
            lights="$li/$lp"
            [ "$li" = "$lp" ] || lights="$lights!"
            diag="lights $lights $diag"
        fi
    fi
    printf '%-50s %-7s %7s %8s %8s  %s\n' "$rel" "$status" "$secs" "$psecs" \
        "$pov" "$diag" | tee -a "$tmp/table"
    rm -rf "$work"
done < "$tmp/list"

pct=$(echo "$n_ok $n" | awk '{ if ($2) printf "%.1f", 100 * $1 / $2; else print 0 }')
sum_col() { awk -v c="$1" '$c ~ /^[0-9.]+$/ { s += $c; n++ }
    END { if (n) printf "%.2f s over %d scenes", s, n; else print "-" }' "$tmp/table"; }
echo
echo "scenes: $n  ok: $n_ok ($pct%)  error: $n_err  timeout: $n_to  crash: $n_crash"
echo "time: iris --parse-only $(sum_col 3); parser alone $(sum_col 4);" \
    "POV-Ray parse $(sum_col 5)"
# The fair comparison: the scenes both parsers parsed, both times internal.
awk '$2 == "ok" && $4 ~ /^[0-9.]+$/ && $5 ~ /^[0-9.]+$/ {
        n++; i += $4; p += $5 }
     END { if (n && p > 0)
         printf "same %d scenes: iris parser %.2f s, POV-Ray %.2f s, " \
                "ratio iris/POV-Ray %.2f\n", n, i, p, i / p }' "$tmp/table"
[ $n_to -eq 0 ] && [ $n_crash -eq 0 ]
