#!/bin/sh
# SPDX-License-Identifier: MIT
# tests/parse/run.sh: the golden tests of povparse. Each cases/NAME.pov is
# parsed by tests/parse/parsedump and its output (diagnostics with caret
# lines, then the scene dump) must equal cases/NAME.expect byte for byte.
# The include test parses every standard include file of POV-Ray.
#
# To accept new output after a deliberate change:
#   UPDATE=1 top_srcdir=... top_builddir=... sh tests/parse/run.sh
. "$top_srcdir/tests/tap.sh"

dump="$top_builddir/tests/parse/parsedump"
cases="$top_srcdir/tests/parse/cases"
[ -x "$dump" ] || tap_skip_all "parsedump not built"

set -- "$cases"/*.pov
incdir=$(sed -n 's/^#define POVRAY_INCLUDE_DIR "\(.*\)"/\1/p' \
    "$top_builddir/config.h" 2>/dev/null)
n_inc=0
[ -n "$incdir" ] && [ -d "$incdir" ] && n_inc=$(ls "$incdir"/*.inc | wc -l)
tap_plan $(($# + n_inc))

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for f in "$@"; do
    name=$(basename "$f" .pov)
    # Options for parsedump may be given on a '// options:' line.
    opts=$(sed -n 's|^// options: ||p' "$f" | head -n 1)
    # Run from the cases directory so that paths in messages are short.
    (cd "$cases" && "$dump" $opts "$name.pov") >"$tmp/out" 2>&1
    if [ -n "$UPDATE" ]; then
        cp "$tmp/out" "$cases/$name.expect"
    fi
    if cmp -s "$tmp/out" "$cases/$name.expect"; then
        tap_result 0 "$name"
    else
        tap_result 1 "$name"
        diff "$cases/$name.expect" "$tmp/out" | head -n 20 | sed 's/^/# /'
    fi
done

# Every standard include file parses when #included by a scene. Some of
# them use colors.inc and shapes.inc without including them (POV-Ray 3.7
# rejects them alone too), so the scene includes those two first.
if [ "$n_inc" -gt 0 ]; then
    for inc in "$incdir"/*.inc; do
        b=$(basename "$inc")
        printf '#version 3.7;\n#include "colors.inc"\n#include "shapes.inc"\n#include "%s"\n' \
            "$b" >"$tmp/inc.pov"
        tap_ok "include $b" "$dump" -q -w "$tmp/inc.pov"
    done
fi
exit 0
