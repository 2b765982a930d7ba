#!/bin/sh
# SPDX-License-Identifier: MIT
# tests/mpi/mpi.sh: progressive passes across MPI ranks (issue 8) on
# localhost. The ranks share the passes (the first round one each, then
# in proportion to their speeds) and rank 0 reduces the double sums; a
# pass is the same whichever rank runs it, so the image of R ranks equals the one of one rank up to the order
# of the double additions: about 1e-16 relative before the image is
# rounded to float, so at most one float ulp (6e-8 relative) after. The
# check allows 1e-6 relative to the brightest linear value of the image
# (imgdiff: largest absolute difference; imgtool stats: the largest value).
. "$top_srcdir/tests/tap.sh"
[ -n "$MPIRUN" ] || tap_skip_all "iris was built without MPI"
tap_plan 24
scene="$top_srcdir/tests/progressive/ball.pov"
imgdiff="$top_builddir/tests/progressive/imgdiff"
imgtool="$top_builddir/tests/cli/imgtool"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# Localhost only: no ssh launcher, shared memory and self transports; CI
# runs as root.
export OMPI_MCA_plm=isolated OMPI_MCA_btl=self,vader \
    OMPI_MCA_rmaps_base_oversubscribe=1
mpi() { n=$1; shift
    "$MPIRUN" --oversubscribe --allow-run-as-root -n "$n" "$IRIS" "$@"; }
r() { "$IRIS" -q "$scene" +W24 +H24 --threads 1 "$@"; }
near() { # near A.exr B.exr: largest difference <= 1e-6 * largest value
    d=$("$imgdiff" "$1" "$2") || return 1
    hi=$("$imgtool" stats "$1" | awk '{ print $2 }')
    echo "# largest difference $d, largest value $hi"
    awk -v d="$d" -v h="$hi" 'BEGIN { exit !(h > 0 && d <= 1e-6 * h) }'
}

r -o "$tmp/p5.exr" --passes 5 --seed 3
mpi 1 -q "$scene" +W24 +H24 --threads 1 -o "$tmp/r1.exr" --passes 5 --seed 3
tap_ok "1 rank under mpirun = no mpirun" near "$tmp/p5.exr" "$tmp/r1.exr"
mpi 2 -q "$scene" +W24 +H24 --threads 1 -o "$tmp/r2.exr" --passes 5 \
    --seed 3 --stats "$tmp/s2.json"
tap_ok "2 ranks = 1 rank within 1e-6 relative" near "$tmp/p5.exr" "$tmp/r2.exr"
r -o "$tmp/p3.exr" --passes 3 --seed 3
d=$("$imgdiff" "$tmp/p3.exr" "$tmp/r2.exr")
tap_ok "... and not rank 0's passes alone (3 passes differ by $d)" \
    awk -v d="$d" 'BEGIN { exit !(d + 0 > 0) }'
tap_ok "--stats counts the passes of both ranks (5)" \
    grep -q '"passes": 5' "$tmp/s2.json"

# Rank 0 alone speaks: one "wrote" line, not two
mpi 2 "$scene" +W24 +H24 --threads 1 -o "$tmp/w.exr" --passes 2 \
    2>"$tmp/log" >/dev/null
tap_is "one rank reports" "$(grep -c 'iris: wrote' "$tmp/log")" "1"

# The error log during the run, from rank 0 only: the first round after
# the first is always reported (later ones when the reduction costs at
# most 5% of the time), then the end; pass counts increase, none twice.
"$IRIS" -q "$scene" +W24 +H24 --threads 1 --passes 8 --seed 3 \
    -o "$tmp/ref8.exr"
mpi 2 -q "$scene" +W24 +H24 --threads 1 --passes 8 --seed 3 \
    -o "$tmp/e8.exr" --reference "$tmp/ref8.exr" --error-log "$tmp/err.csv"
passes=$(tail -n +2 "$tmp/err.csv" | cut -d, -f2 | tr '\n' ' ')
tap_ok "error log on 2 ranks: a line during the run ($passes)" \
    test "$(tail -n +2 "$tmp/err.csv" | wc -l)" -ge 2 -a \
    "$(tail -n +2 "$tmp/err.csv" | head -1 | cut -d, -f2)" = 2
tap_ok "... increasing pass counts ending at 8, one line each" \
    awk -F, 'NR > 1 { if ($2 <= last) exit 1; last = $2 }
             END { exit !(last == 8) }' "$tmp/err.csv"

# Checkpoint and resume across ranks: 2 passes, then 3 more
mpi 2 -q "$scene" +W24 +H24 --threads 1 -o "$tmp/c2.exr" --passes 2 \
    --seed 3 --checkpoint "$tmp/run.ckpt"
mpi 2 -q "$scene" +W24 +H24 --threads 1 -o "$tmp/c5.exr" --passes 5 \
    --seed 3 --resume "$tmp/run.ckpt"
tap_ok "2 + 3 passes resumed on 2 ranks = 5 passes" \
    near "$tmp/p5.exr" "$tmp/c5.exr"

# Where the time goes (IRIS_RANK_TIMES): one line per rank from rank 0;
# with a fixed pass count the first round needs no agreement and the
# ranks agree after rounds 1, 3, 7 and at the end (the gap doubles:
# progressive.c next_gap), 4 agreements for 8 rounds instead of 9, one a
# round. The blocks after the first are shared by the ranks' speeds
# (block_share): rank 0 also writes the intermediate EXR images (passes
# 2, 4 and 8; the first loads the OpenImageIO module, ~0.4 s of CPU,
# against ~0.03 s a 24x24 pass), so rank 1 must run more of the 16
# passes than rank 0.
IRIS_RANK_TIMES=1 mpi 2 -q "$scene" +W24 +H24 --threads 1 --passes 16 \
    --seed 3 -o "$tmp/g.exr" 2>"$tmp/times" >/dev/null
sed 's/^/# /' "$tmp/times"
tap_ok "rank times: both ranks, 16 passes, <= 4 agreements" \
    awk '/^iris: rank [01]: [0-9]+ passes/ { n++; p += $4; if ($9 > 4) bad = 1 }
         END { exit !(n == 2 && p == 16 && !bad) }' "$tmp/times"
tap_ok "... the faster rank 1 ran more passes than rank 0" \
    awk '/^iris: rank 0:/ { p0 = $4 } /^iris: rank 1:/ { p1 = $4 }
         END { exit !(p1 > p0) }' "$tmp/times"
r -o "$tmp/p16.exr" --passes 16 --seed 3
tap_ok "... and the image of 16 passes on 1 rank" \
    near "$tmp/p16.exr" "$tmp/g.exr"

# The time limit: ranks agree on when to stop
t0=$(date +%s)
mpi 2 -q "$scene" +W24 +H24 --threads 1 -o "$tmp/t.exr" --time-limit 1 \
    --stats "$tmp/t.json"
rc=$?
t1=$(date +%s)
n=$(sed -n 's/.*"passes": \([0-9]*\).*/\1/p' "$tmp/t.json")
tap_ok "--time-limit 1 on 2 ranks: $n passes in $((t1 - t0)) s" \
    test "$rc" = 0 -a "${n:-0}" -ge 2 -a $((t1 - t0)) -le 6
tap_ok "... an even count (whole rounds of 2 passes)" \
    test $((${n:-1} % 2)) = 0
# Memory per node: the ranks on one node share its memory (membudget.c),
# so each rank's photon pass gets 1/R of a node-wide limit. The caustic
# ball with Photons=2e6 shoots 8.9e5 photons, a 56.9 MB estimated peak
# (shoot.c's message). Under --node-memory 100M one rank has 100 MB less
# its ~12 MB resident set: it fits; two ranks have 50 MB less that each,
# which cannot hold 56.9 MB whatever their resident set: rank 0 fails its
# pass 0 with the located error, the other rank learns it at its first
# agreement, no rank hangs (timeout 120 s: rc 124).
ball="$top_srcdir/bench/caustic_ball.pov"
big() { n=$1; shift
    timeout 120 "$MPIRUN" --oversubscribe --allow-run-as-root -n "$n" \
        "$IRIS" -q "$ball" +W32 +H24 --threads 1 Declare=Photons=2000000 \
        --passes 4 --node-memory 100M "$@"; }
big 1 -o "$tmp/m1.png" 2>"$tmp/m1.err"
tap_is "--node-memory 100M, 1 rank: 56.9 MB fits" "$?" "0"
big 2 -o "$tmp/m2.png" 2>"$tmp/m2.err"
rc=$?
sed 's/^/# /' "$tmp/m2.err" | head -5
tap_ok "... 2 ranks: exit non-zero, no hang (rc $rc)" \
    test "$rc" -ne 0 -a "$rc" -ne 124
tap_is "... one located error, from rank 0" \
    "$(grep -c 'caustic_ball.pov:23:23: error: photons: .* 56.9 MB .* shared by the node.s MPI ranks' "$tmp/m2.err")" "1"
tap_ok "... and no image" test ! -e "$tmp/m2.png"

# Another rank fails. MPMD launches ('-n 1 A : -n 1 B') give rank 1
# arguments or limits of its own, as a node with less memory would.
# (a) rank 1's photon pass exceeds its memory: --node-memory 60M on rank
# 1 alone leaves it 30 MB (less its resident set) for the 56.9 MB pass 1
# map, while rank 0 (no limit but the machine's) builds pass 0. Rank 1
# never builds pass 0, so its located error is the pass 1 one, which
# only rank 1 could print; rank 0 prints it, naming the rank, once;
# exit 2 (a scene's photon settings, as on one rank), no image.
mpmd() { # mpmd 'RANK0 ARGS' 'RANK1 PREFIX' 'RANK1 ARGS'
    timeout 120 "$MPIRUN" --oversubscribe --allow-run-as-root \
        -n 1 "$IRIS" $1 : -n 1 $2 "$IRIS" $1 $3; }
ballargs="-q $ball +W32 +H24 --threads 1 Declare=Photons=2000000 --passes 4 -o $tmp/f1.png"
mpmd "$ballargs" "" "--node-memory 60M" 2>"$tmp/f1.err"
rc=$?
sed 's/^/# /' "$tmp/f1.err" | head -3
tap_is "rank 1 over its memory share: exit 2, no hang (124)" "$rc" "2"
tap_is "... one located error from rank 0, naming rank 1" \
    "$(grep -c 'caustic_ball.pov:23:23: error: photons: .* 56.9 MB .*--node-memory shared by the node.s MPI ranks.*(MPI rank 1)$' "$tmp/f1.err")" "1"
tap_ok "... and no image" test ! -e "$tmp/f1.png"
# (b) rank 1 dies of a signal: 'ulimit -t 1' ends it (SIGXCPU, then
# SIGKILL) after 1 s of CPU, well inside its share of 4000 passes of
# 24x24 (~0.007 s each, ~14 s of CPU for its half; 400 passes became
# too few once passes got faster). mpirun ends the job: non-zero exit, not a hang,
# and its report names rank 1 and the signal (nothing else can: rank 1
# is gone, and rank 0 waits at an agreement until mpirun ends it).
sargs="-q $scene +W24 +H24 --threads 1 --passes 4000 --seed 3 -o $tmp/f2.png"
printf '#!/bin/sh\nulimit -t 1\nexec "$@"\n' >"$tmp/cpu1"
chmod +x "$tmp/cpu1"
mpmd "$sargs" "$tmp/cpu1" "" >"$tmp/f2.out" 2>&1
rc=$?
grep -v '^ *$\|^---' "$tmp/f2.out" | sed 's/^/# /' | head -4
tap_ok "rank 1 killed by a signal: exit non-zero, no hang (rc $rc)" \
    test "$rc" -ne 0 -a "$rc" -ne 124
tap_ok "... mpirun names rank 1 and the signal" \
    grep -q 'rank 1 .*exited on signal' "$tmp/f2.out"
# (c) rank 0 cannot write the image: the directory does not exist. It is
# checked before the parse (a render of hours must not end so), once;
# rank 1, which writes nothing, does not check and goes on to its first
# agreement, where rank 0 will never come: rank 0, leaving alone, must
# end the job (MPI_Abort; MPI_Finalize would wait for rank 1 for ever).
timeout 120 "$MPIRUN" --oversubscribe --allow-run-as-root -n 2 "$IRIS" -q \
    "$scene" +W24 +H24 --threads 1 --passes 4 -o "$tmp/none/w.png" \
    2>"$tmp/f3.err"
rc=$?
tap_is "rank 0's image directory is missing: exit 1, no hang (124)" "$rc" "1"
tap_is "... said once, before the render" \
    "$(grep -c "^iris: $tmp/none/w.png: cannot write the image there: No such file or directory" "$tmp/f3.err")" "1"
[ "$tap_failed" -eq 0 ]
