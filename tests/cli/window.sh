#!/bin/sh
# SPDX-License-Identifier: MIT
# tests/cli/window.sh: the render window +SR +ER +SC +EC, as numbers and
# as fractions of the image (+SR0.5), the way POV-Ray 3.7 reads them
# (View::StartRender in source/backend/scene/view.cpp):
#   start v in [0, 1): first pixel (int)(size * v), counted from 0
#   end   v in [0, 1]: last pixel  (int)(size * v) - 1
#   any other v:       pixel (int)v, counted from 1 (+SR2.7 is row 2)
# with v a float (POVMSFloat): 10 * 0.7f = 6.9999998, so +SR0.7 of 10
# rows starts at row 7 (1-based), where double arithmetic gives 8.
# Each case renders minimal.pov (no pixel of it is black: plane 0.35,
# sphere red) at 10x10 and reads which rows and columns are not black:
# they must be the window the rule above gives (written out by hand
# below, 1-based first-last) and, when POV-Ray is installed, the rows
# and columns POV-Ray renders with the same switches (pixels outside
# the window are black in both).
. "$top_srcdir/tests/tap.sh"
imgtool="$top_builddir/tests/cli/imgtool"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cp "$top_srcdir/tests/cli/scenes/minimal.pov" "$tmp/s.pov"
cd "$tmp" || exit 1
have_povray=no
if [ -n "$POVRAY" ] && command -v "$POVRAY" >/dev/null 2>&1; then
    have_povray=yes
fi

# span IMAGE: "R1-R2 C1-C2", the 1-based first and last rows and columns
# that hold a pixel other than black ("none" when all are black)
span() {
    for y in 0 1 2 3 4 5 6 7 8 9; do
        for x in 0 1 2 3 4 5 6 7 8 9; do
            echo "$x $y $("$imgtool" pixel "$1" $x $y)"
        done
    done | awk '$3 + $4 + $5 > 0 {
            if (!n++ || $2 < r1) r1 = $2; if ($2 > r2) r2 = $2
            if (n == 1 || $1 < c1) c1 = $1; if ($1 > c2) c2 = $1 }
        END { if (n) printf "%d-%d %d-%d\n", r1 + 1, r2 + 1, c1 + 1, c2 + 1
              else print "none" }'
}

# win "SWITCHES" "ROWS COLS": iris's window, and POV-Ray's when installed
win() {
    args=$1 want=$2
    rm -f i.png p.png
    # shellcheck disable=SC2086 # the switches are split on purpose
    ( ulimit -t 30; exec "$IRIS" -q +W10 +H10 $args s.pov -o i.png ) \
        >log.txt 2>&1 </dev/null
    got=$(span i.png 2>&1)
    tap_is "iris +W10 +H10 $args renders rows, columns $want" "$got" "$want"
    if [ $have_povray = yes ]; then
        # shellcheck disable=SC2086
        "$POVRAY" +W10 +H10 $args -D -V -GA +FN +Is.pov +Op.png \
            >pov.txt 2>&1 </dev/null
        if [ -s p.png ]; then
            tap_is "... the same as POV-Ray's" "$(span p.png 2>&1)" "$got"
        else
            tap_result 0 "... POV-Ray # SKIP POV-Ray did not render"
        fi
    else
        tap_result 0 "... POV-Ray # SKIP no POV-Ray (\$POVRAY)"
    fi
}

tap_plan 25
win "" "1-10 1-10"
# whole numbers: rows 3 to 5
win "+SR3 +ER5" "3-5 1-10"
# fractions: (int)(10 * 0.5) = 5 from 0 is row 6; (int)(10 * 0.75) = 7
win "+SR0.5" "6-10 1-10"
win "+SR0.5 +ER0.75" "6-7 1-10"
win "+SC0.25 +EC0.55" "1-10 3-5"
# an end of 1 (or 1.0) is the whole image, a start of 0 the first row
win "+ER1" "1-10 1-10"
win "+SR0 +EC1.0" "1-10 1-10"
# float rounding: 10 * 0.7f = 6.9999998: start row 7, end column 6
win "+SR0.7 +EC0.7" "7-10 1-6"
# a number above 1 is truncated: 2.7 is row 2, 3.9 row 3
win "+SR2.7 +ER3.9" "2-3 1-10"
# the last row alone, as a fraction
win "+SR0.95 +ER1" "10-10 1-10"
# switch order does not matter: +H after the fraction
rm -f i.png
"$IRIS" -q +SR0.5 +W10 +H10 +ER0.75 s.pov -o i.png >log.txt 2>&1
tap_is "+SR0.5 before +W10 +H10 is resolved against the final size" \
    "$(span i.png 2>&1)" "6-7 1-10"

# what POV-Ray refuses, iris refuses with the switch named (exit 2):
# +ER0.05 ends before the first row, +ER11 past the image
# ("Invalid end column or row"), +SR0.5 +ER0.3 ends above its start
# (POV-Ray renders an empty image; the message gives the rows the
# fractions resolved to), and a negative value
refuse() {
    want=$1 pat=$2; shift 2
    ( ulimit -t 20; exec "$IRIS" -q +W10 +H10 "$@" s.pov -o r.png ) \
        >out.txt 2>&1 </dev/null
    rc=$?
    st=0
    [ "$rc" = "$want" ] || st=1
    grep -Eq -- "$pat" out.txt || st=1
    tap_result $st "$* -> exit $want, '$pat' (got $rc)"
    [ $st = 0 ] || head -n 3 out.txt | sed 's/^/#   /'
}
refuse 2 "\+ER0.05: the window ends before the first row" +ER0.05
refuse 2 "\+EC11: the image has 10 columns" +EC11
refuse 2 "\+SR6 \+ER3: the start row is below the end row" +SR0.5 +ER0.3
refuse 2 "expected a row or column number, or a fraction" +SR-0.5
[ $tap_failed -eq 0 ]
