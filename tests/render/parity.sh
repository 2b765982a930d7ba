#!/bin/sh
# SPDX-License-Identifier: MIT
#
# parity.sh: the POV-Ray parity suite (TAP). Every scene in scenes/ is
# rendered at 80x60 with antialiasing (+A0.3, POV-Ray's method 1 and
# jitter) by iris and by POV-Ray, and the two PNGs must agree to a PSNR
# of at least 35 dB on the sRGB values (psnr.c). A scene may lower its bar
# with a line '// parity-min-psnr: N reason', or mark a known failure of
# another part with '// parity-todo: reason' (reported as TAP TODO).
# A line '// parity-options: SWITCHES' gives both renderers more POV-Ray
# switches after the defaults (e.g. '+UA' or '+AM2 +R4 -J'); with +UA
# the alpha channel is compared too (psnr --rgba).
#
# Every scene here is one iris renders: a scene error (exit status 2)
# fails like any other exit status, so a parser regression cannot hide
# as a skip. Without POV-Ray every scene is skipped.
#
# Environment: IRIS, POVRAY, top_srcdir, top_builddir (set by make check).

srcdir=${top_srcdir:-.}/tests/render
psnr=${top_builddir:-.}/tests/render/psnr
size="+W80 +H60"
aa="+A0.3"

scenes=$(ls "$srcdir"/scenes/*.pov 2>/dev/null | sort)
n=$(printf '%s\n' "$scenes" | grep -c .)
echo "1..$n"

work=$(mktemp -d /tmp/iris-parity.XXXXXX) || exit 1
trap 'rm -rf "$work"' EXIT INT TERM

have_pov=yes
if [ -z "$POVRAY" ] || ! command -v "$POVRAY" >/dev/null 2>&1; then
    have_pov=no
fi

i=0
for scene in $scenes; do
    i=$((i + 1))
    name=$(basename "$scene" .pov)
    if [ "$have_pov" = no ]; then
        echo "ok $i - $name # SKIP POV-Ray is not installed"
        continue
    fi
    min=$(sed -n 's|^// parity-min-psnr: *\([0-9.]*\).*|\1|p' "$scene" | head -n 1)
    min=${min:-35}
    todo=$(sed -n 's|^// parity-todo: *\(.*\)|\1|p' "$scene" | head -n 1)
    directive=""
    [ -n "$todo" ] && directive=" # TODO $todo"
    opts=$(sed -n 's|^// parity-options: *\(.*\)|\1|p' "$scene" | head -n 1)
    mode=""
    case " $(printf '%s' "$opts" | tr 'a-z' 'A-Z') " in
    *" +UA "*) mode=--rgba ;;
    esac

    # shellcheck disable=SC2086 (opts: several switches)
    "$IRIS" "+I$scene" "+O$work/$name.iris.png" "+L$srcdir/scenes" $size $aa \
        $opts -q --threads=2 \
        > "$work/$name.iris.log" 2>&1
    rc=$?
    if [ $rc -ne 0 ]; then
        echo "not ok $i - $name: iris exited with status $rc$directive"
        sed 's/^/# /' "$work/$name.iris.log" | head -n 5
        continue
    fi
    (cd "$work" && "$POVRAY" "+I$scene" "+O$work/$name.pov.png" \
        "+L$srcdir/scenes" $size $aa $opts \
        -D -V +FN > "$work/$name.pov.log" 2>&1)
    if [ ! -s "$work/$name.pov.png" ]; then
        echo "ok $i - $name # SKIP POV-Ray did not render it"
        continue
    fi
    res=$("$psnr" $mode "$work/$name.iris.png" "$work/$name.pov.png" 2>&1)
    db=${res%% *}
    if [ "$db" = inf ] || awk -v a="$db" -v b="$min" \
        'BEGIN { exit !(a + 0 >= b + 0 && a != "") }'; then
        echo "ok $i - $name: PSNR $db dB (>= $min)$directive"
    else
        echo "not ok $i - $name: PSNR $db dB, want >= $min ($res)$directive"
    fi
done
