#!/bin/sh
# SPDX-License-Identifier: MIT
# tests/cli/misuse.sh: the command line misused (issue 7): every option
# with a missing, negative, huge or non-numeric value, files that cannot
# be read or written, the output naming a directory, options that
# contradict each other, output files that would overwrite the scene.
# Each case must end with the exit status it names (2: bad usage, 1: I/O)
# and a message naming what is wrong, never a crash, never a file written
# where it was not asked for. The cases come from the session-8 sweep;
# those marked 'was:' did something else before (a hidden 'DIR/.png', the
# scene replaced by JSON, a checkpoint silently not written, an error
# only after the render).
. "$top_srcdir/tests/tap.sh"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cp "$top_srcdir/tests/cli/scenes/minimal.pov" "$tmp/s.pov"
cp "$tmp/s.pov" "$tmp/s.orig"
mkdir "$tmp/dir"
cd "$tmp" || exit 1
"$IRIS" -q +W16 +H16 s.pov -o big.png 2>/dev/null

# case STATUS PATTERN ARGS...: runs iris +W8 +H8 ARGS (under 20 s of CPU);
# the exit status must be STATUS and stderr must match PATTERN (grep -E).
case_() {
    want=$1 pat=$2; shift 2
    ( ulimit -t 20; exec "$IRIS" -q +W8 +H8 "$@" ) >out.txt 2>&1 </dev/null
    rc=$?
    st=0
    [ "$rc" = "$want" ] || st=1
    grep -Eq -- "$pat" out.txt || st=1
    tap_result $st "$* -> exit $want, '$pat' (got $rc)"
    [ $st = 0 ] || head -n 3 out.txt | sed 's/^/#   /'
}

# numbers: missing, negative, zero, huge, not a number, not finite
case_ 2 "width must be 1..65536" +W0 s.pov -o a.png
case_ 2 "unknown option '\+W-1'" +W-1 s.pov -o a.png
case_ 2 "width must be 1..65536" +W99999999999999999999 s.pov -o a.png
case_ 2 "height must be 1..65536" --height=1e3 s.pov -o a.png
case_ 2 "width must be 1..65536" s.pov --width
case_ 2 "threads must be 1..1024" --threads=0 s.pov -o a.png
case_ 2 "thread count 1..1024" +WT s.pov -o a.png
case_ 2 "seed must be a non-negative integer" --seed=-1 s.pov -o a.png
case_ 2 "seed must be a non-negative integer" --seed=99999999999999999999999 s.pov -o a.png
case_ 2 "passes must be a positive integer" --passes=0 s.pov -o a.png
case_ 2 "passes must be a positive integer" --passes=abc s.pov -o a.png
case_ 2 "expected a time in seconds" --time-limit=nan s.pov -o a.png
case_ 2 "expected a time in seconds" --time-limit=-1 s.pov -o a.png
case_ 2 "expected a size in bytes" --node-memory=8X s.pov -o a.png
case_ 2 "expected a size in bytes" --node-memory=1e30 s.pov -o a.png
case_ 2 "expected 2..10000 wavelengths" --spectral-samples=1 s.pov -o a.png
case_ 2 "a positive number of iterations" --max-loop-iterations=-1 s.pov -o a.png
case_ 2 "antialiasing threshold 0..3" +A-1 s.pov -o a.png
case_ 2 "antialiasing method must be" +AM9 s.pov -o a.png
case_ 2 "antialiasing gamma" +AGinf s.pov -o a.png
case_ 2 "antialiasing depth must be 1..9" +R0 s.pov -o a.png
case_ 2 "jitter amount" +J1e300 s.pov -o a.png
case_ 2 "quality must be 0..11" +Q12 s.pov -o a.png
case_ 2 "clock value" +K1e40 s.pov -o a.png
case_ 2 "PNG bit depth must be 8 or 16" +FN7 s.pov -o a.png
case_ 2 "row or column number" +SRx s.pov -o a.png
case_ 2 "row or column number" +ERinf s.pov -o a.png
# the render window (was: +SR100 +H8 rendered the last row, exit 0)
case_ 2 "\+SR100: the image has 8 rows" +SR100 s.pov -o a.png
case_ 2 "\+SC9: the image has 8 columns" +SC9 s.pov -o a.png
case_ 2 "\+SR6 \+ER5: the start row is below" +SR6 +ER5 s.pov -o a.png

# scenes that cannot be read
case_ 2 "cannot read the scene" nothere.pov -o a.png
case_ 2 "dir: cannot read the scene: it is a directory" dir -o a.png
case_ 2 "/dev/null: cannot read the scene: not a regular file" /dev/null -o a.png
case_ 2 "more than one scene" s.pov s.pov -o a.png
case_ 2 "standard input is not supported" - -o a.png
case_ 2 "no scene given" -o a.png

# the output (was: '-o dir/' wrote the hidden file dir/.png, '-o dir'
# wrote dir.png, '-o .' wrote '..png', -o '' wrote '.png')
case_ 2 "dir/: is a directory" s.pov -o dir/
case_ 2 "dir: is a directory" s.pov +Odir
case_ 2 "\.: is a directory" s.pov -o .
case_ 2 "-o needs a file name" s.pov -o ''
case_ 2 "--output= needs a file name" s.pov --output=
case_ 1 "cannot write the image there" s.pov -o nothere/a.png
case_ 1 "cannot write this format" s.pov -o a.xyz
case_ 2 "refusing to overwrite the scene" s.pov -o s.pov
tap_is "no stray images were written" \
    "$(ls -A . dir | grep -c '\.png$')" "1"  # big.png alone

# files written at the end: checked before the render (was: --stats=s.pov
# replaced the scene with JSON; a missing directory failed after the
# render, and a failed checkpoint write lost the image)
case_ 2 "--stats=s.pov: refusing to write over the scene file" s.pov --stats=s.pov -o a.png
case_ 2 "--checkpoint=s.pov: refusing to write over the scene file" s.pov --passes=2 --checkpoint=s.pov -o a.png
case_ 2 "--stats=a.png: refusing to write over the image" s.pov --stats=a.png -o a.png
case_ 2 "--checkpoint=c: refusing to write over --stats" s.pov --passes=2 --stats=c --checkpoint=c -o a.png
case_ 2 "--stats=nothere/s.json: cannot write there" s.pov --stats=nothere/s.json -o a.png
case_ 2 "--stats=dir: cannot write there: Is a directory" s.pov --stats=dir -o a.png
case_ 2 "--checkpoint=nothere/c: cannot write there" s.pov --passes=2 --checkpoint=nothere/c -o a.png
cmp -s s.pov s.orig
tap_is "the scene file is intact" "$?" "0"
tap_is "no file was written by a refused run" "$(ls -A . dir | grep -c -e '^a\.png$' -e '^c$' -e 'json$')" "0"

# progressive files
case_ 2 "only a progressive render writes a checkpoint" s.pov --checkpoint=c.ckpt -o a.png
case_ 2 "--resume=nothere: No such file" s.pov --resume=nothere -o a.png
case_ 1 "not an iris checkpoint" s.pov --resume=s.pov -o a.png
case_ 2 "cannot read the reference" s.pov --passes=2 --reference=nothere.png -o a.png
case_ 2 "the reference is 16x16, the image 8x8" s.pov --passes=2 --reference=big.png -o a.png
case_ 2 "--error-log needs --reference" s.pov --passes=2 --error-log=e.csv -o a.png

# declarations and unknown options
case_ 2 "expected Declare=Name=Value" s.pov Declare=X -o a.png
case_ 2 "Declare=X>:1:[0-9]+: error: undeclared identifier 'abc'" s.pov Declare=X=abc -o a.png
case_ 2 "'sphere' is a reserved word" s.pov Declare=sphere=3 -o a.png
case_ 2 "unknown option '--bogus'" s.pov --bogus
case_ 2 "unknown option '\+Z'" s.pov +Z

# an image beyond memory is said before anything is allocated (under a
# 4 GB address-space limit, whatever the machine has)
( ulimit -v 4000000; ulimit -t 20
  exec "$IRIS" -q +W65536 +H65536 s.pov -o a.png ) >out.txt 2>&1
rc=$?
grep -q "the image needs 68.7 GB" out.txt
tap_is "+W65536 +H65536 under ulimit -v 4 GB: exit 1 before allocating" \
    "$rc:$?" "1:0"

echo "1..$tap_n"
