#!/bin/sh
# SPDX-License-Identifier: MIT
# tests/progressive/progressive.sh: progressive photon mapping (issue 6)
# through the iris command: --passes, --time-limit, --checkpoint,
# --resume, --reference, --error-log, SIGINT. Exact comparisons use
# imgdiff (largest absolute difference of linear values, 0 = identical).
. "$top_srcdir/tests/tap.sh"
tap_plan 22
scene="$top_srcdir/tests/progressive/ball.pov"
imgdiff="$top_builddir/tests/progressive/imgdiff"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
r() { "$IRIS" -q "$scene" +W24 +H24 "$@"; }

# --passes 1 is the ordinary render
r -o "$tmp/plain.exr" && r -o "$tmp/p1.exr" --passes 1
tap_is "--passes 1 gives the ordinary render" \
    "$("$imgdiff" "$tmp/plain.exr" "$tmp/p1.exr")" "0"

# Passes average: 4 passes differ from 1 (new photons, new jitter)
r -o "$tmp/p4.exr" --passes 4 --stats "$tmp/s4.json"
d=$("$imgdiff" "$tmp/p1.exr" "$tmp/p4.exr")
tap_ok "4 passes differ from 1" test "$d" != "0"
tap_ok "--stats counts the passes" grep -q '"passes": 4' "$tmp/s4.json"

# The image does not depend on the thread count
r -o "$tmp/p4t1.exr" --passes 4 --threads 1
r -o "$tmp/p4t2.exr" --passes 4 --threads 2
tap_is "same image for 1 and 2 threads" \
    "$("$imgdiff" "$tmp/p4t1.exr" "$tmp/p4t2.exr")" "0"
tap_is "... and for the default thread count" \
    "$("$imgdiff" "$tmp/p4.exr" "$tmp/p4t2.exr")" "0"

# On 2 threads the next pass's map is built during the eye pass
# (progressive.c PREFETCH): passes 1, 2 and 3 of 4 (pass 0's map is
# render.c's, built before any eye pass).
# The same image as without it, bit for bit: a map of the wrong pass or
# seed, or one freed while in use, would change it. 1000 photons and 48x48
# pixels: the map costs ~1/10 of the eye pass, so even a loaded machine
# does not make the loop wait for it (which would stop the prefetching,
# below).
pf() { env IRIS_RANK_TIMES=1 IRIS_NO_PREFETCH="$1" "$IRIS" -q "$scene" \
    +W48 +H48 Declare=Photons=1000 --passes 4 --threads 2 -o "$2"; }
pf 0 "$tmp/pf.exr" 2>"$tmp/pf.txt"
pf 1 "$tmp/npf.exr" 2>"$tmp/npf.txt"
tap_is "2 threads: maps built during the eye pass, the same image" \
    "$("$imgdiff" "$tmp/pf.exr" "$tmp/npf.exr")" "0"
tap_is "... 3 maps prefetched, none with IRIS_NO_PREFETCH=1" \
    "$(sed -n 's/.*prefetched \([0-9]*\) maps.*/\1/p' "$tmp/pf.txt" \
        "$tmp/npf.txt" | tr '\n' ' ')" "3 0 "
# A map that costs far more than the eye pass (50000 photons, 2x2
# pixels: ~1000 times) is not worth building beside it: after two passes
# that waited for it, the rest are built after the eye pass. Passes 1 and
# 2 are prefetched before any wait is seen; pass 1's wait may be hidden
# by pass 0's eye pass (the first, with the run's first-time costs), then
# pass 3's too: 2 or 3 of 8, not 7.
env IRIS_RANK_TIMES=1 "$IRIS" -q "$scene" +W2 +H2 Declare=Photons=50000 \
    --passes 8 --threads 2 -o "$tmp/pfs.exr" 2>"$tmp/pfs.txt"
n=$(sed -n 's/.*prefetched \([0-9]*\) maps.*/\1/p' "$tmp/pfs.txt")
tap_ok "a map slower than the eye pass: $n of 8 maps prefetched (2-3)" \
    test "${n:-0}" -ge 2 -a "${n:-0}" -le 3

# Checkpoint + resume = an uninterrupted run with the same total passes
r -o "$tmp/c2.exr" --passes 2 --checkpoint "$tmp/run.ckpt"
tap_ok "--checkpoint writes the accumulation" test -s "$tmp/run.ckpt"
r -o "$tmp/c4.exr" --passes 4 --resume "$tmp/run.ckpt" --threads 1
tap_is "resume continues exactly (2 + 2 passes = 4 passes)" \
    "$("$imgdiff" "$tmp/p4.exr" "$tmp/c4.exr")" "0"
"$IRIS" -q "$scene" +W20 +H24 -o "$tmp/bad.exr" --resume "$tmp/run.ckpt" \
    2>"$tmp/err"
tap_is "a checkpoint of another size is refused (exit 1)" "$?" "1"
printf 'not a checkpoint' >"$tmp/junk.ckpt"
r -o "$tmp/bad.exr" --resume "$tmp/junk.ckpt" 2>"$tmp/err"
rc=$?
grep -q "not an iris checkpoint" "$tmp/err"
tap_is "a damaged checkpoint is refused with a message" "$rc:$?" "1:0"

# Error log against a reference: an independent long run (96 passes,
# another seed). The relative RMSE must fall from 4 to 16 passes, below
# 0.8 times (expected 4^-1/3 = 0.63 for the photon estimate's bias and
# noise, 0.5 for the eye jitter's noise; measured 0.6). The first passes
# are not compared: pass 1 samples pixel centres, as the reference's does,
# and the coarse pixels' jitter noise first grows the error.
r -o "$tmp/ref.exr" --passes 96 --seed 7
r -o "$tmp/e.exr" --passes 16 --reference "$tmp/ref.exr" \
    --error-log "$tmp/err.csv"
tap_is "the error log has a header and one line a pass" \
    "$(head -1 "$tmp/err.csv"),$(($(wc -l <"$tmp/err.csv") - 1))" \
    "time_s,passes,photons,rmse,rel_rmse,bias,16"
tap_ok "... with passes 1..16 and increasing photons and time" awk -F, '
    NR > 1 { if ($2 != NR - 1 || $3 <= p || $1 < t || NF != 6) bad = 1;
             p = $3; t = $1 } END { exit bad }' "$tmp/err.csv"
first=$(awk -F, '$2 == 4 { print $5 }' "$tmp/err.csv")
last=$(awk -F, '$2 == 16 { print $5 }' "$tmp/err.csv")
tap_ok "relative RMSE falls: $first (4 passes) -> $last (16)" \
    awk -v a="$first" -v b="$last" 'BEGIN { exit !(b < 0.8 * a && b > 0) }'
r -o "$tmp/e.exr" --error-log "$tmp/x.csv" 2>/dev/null
tap_is "--error-log without --reference is a usage error" "$?" "2"

# --time-limit stops on time (whole seconds of wall time; a loaded
# machine may add a few)
t0=$(date +%s)
r -o "$tmp/t.png" --time-limit 1 --stats "$tmp/t.json"
t1=$(date +%s)
n=$(sed -n 's/.*"passes": \([0-9]*\).*/\1/p' "$tmp/t.json")
tap_ok "--time-limit 1 ran $n passes in $((t1 - t0)) s" \
    test "$n" -ge 2 -a $((t1 - t0)) -le 4

# SIGINT: the average so far is written, exit 130, checkpoint usable
# (iris itself in the background: a subshell running it would ignore
# SIGINT, as background jobs of a non-interactive shell do)
"$IRIS" -q "$scene" +W24 +H24 -o "$tmp/int.exr" --time-limit 60 \
    --checkpoint "$tmp/int.ckpt" &
pid=$!
i=0
while [ ! -s "$tmp/int.exr" ] && [ $i -lt 300 ]; do sleep 0.1; i=$((i + 1)); done
sleep 0.5
kill -INT $pid
wait $pid
tap_is "SIGINT exits 130" "$?" "130"
tap_ok "... after writing the image and the checkpoint" \
    test -s "$tmp/int.exr" -a -s "$tmp/int.ckpt"

# Memory stays flat as passes accumulate: each pass's map (count 80000:
# ~36000 photons stored, 0.6 MB packed, 2.3 MB raw while building) is
# freed before the next; 8 passes may not use 1.5 MB more than 2. PNG
# output: OpenImageIO (EXR) would add its own allocations to the peak.
"$IRIS" -q "$scene" +W8 +H8 Declare=Photons=80000 --passes 2 \
    -o "$tmp/m.png" --stats "$tmp/m2.json"
"$IRIS" -q "$scene" +W8 +H8 Declare=Photons=80000 --passes 8 \
    -o "$tmp/m.png" --stats "$tmp/m8.json"
m2=$(sed -n 's/.*"peak_rss_bytes": \([0-9]*\).*/\1/p' "$tmp/m2.json")
m8=$(sed -n 's/.*"peak_rss_bytes": \([0-9]*\).*/\1/p' "$tmp/m8.json")
tap_ok "flat memory: peak RSS $m2 (2 passes), $m8 (8 passes)" \
    test $((m8 - m2)) -lt 1500000
# --node-memory (the machine's limit for all MPI ranks on it; one
# process here): a bad size is a usage error; a limit below what pass 0
# needs stops the run with the located error (exit 2)
"$IRIS" -q "$scene" +W8 +H8 --node-memory=12X -o "$tmp/nm.png" \
    2>"$tmp/nm.err"
rc=$?
tap_ok "--node-memory=12X is a usage error naming the option" \
    test "$rc" = 2 -a -n "$(grep -- '--node-memory=12X: expected a size' "$tmp/nm.err")"
"$IRIS" -q "$scene" +W8 +H8 --node-memory=1M -o "$tmp/nm.png" \
    2>"$tmp/nm.err"
rc=$?
tap_ok "--node-memory=1M: exit 2, the error names it (rc $rc)" \
    test "$rc" = 2 -a -n "$(grep 'error: photons: .* --node-memory leaves' "$tmp/nm.err")"
[ "$tap_failed" -eq 0 ]
