#!/bin/sh
# SPDX-License-Identifier: MIT
# tests/fuzz/build.sh: builds the libFuzzer targets (issue 7) with clang,
# AddressSanitizer and UBSan: fuzz_parse (scanner and parser),
# fuzz_plan (parse -> render plan, no pixels) and fuzz_render (parse ->
# a 4x3 render whose pixels must be finite), and optionally runs them.
# regress.sh (make check-fuzz) replays and fuzzes the first two only: a
# render input takes 10-100 times longer, and on a loaded machine the
# render of a seed like many_objects.pov (140000 spheres, 2 s of CPU
# under ASan) passed libFuzzer's 10 s limit; campaigns run fuzz_render
# with -timeout=30 (session 6: 25 minutes, no crash).
#
# usage: tests/fuzz/build.sh BUILD_DIR [SECONDS]
#   BUILD_DIR  a configured build tree (for config.h and the library flags)
#   SECONDS    if given, fuzz each target that long from a seed corpus of
#              scenes/ and the test cases (crash-* files land in the
#              current directory)
#
# The library sources are compiled once into an archive, so a target links
# only the objects it reaches (the plan pulls in the tracer, which needs
# Embree's symbols but never calls them here).
set -e
top=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:?usage: build.sh BUILD_DIR [SECONDS]}
build=$(cd "$build" && pwd)
out="$build/tests/fuzz"
obj="$out/obj"
mkdir -p "$obj"
CC=${CC:-clang}
jobs=${FUZZ_JOBS:-$(nproc 2>/dev/null || echo 2)}
# library flags as configure found them (MPI, FreeType, PNG paths)
mkvar() { sed -n "s/^$1 = //p" "$build/Makefile" | head -n 1; }
cflags="-g -O1 -std=c11 -D_GNU_SOURCE -fsanitize=fuzzer-no-link,address,undefined \
 -fno-sanitize-recover=undefined -Wno-constant-logical-operand -I$build -I$top/include -I$top/src -I$top \
 $(mkvar FREETYPE_CFLAGS) $(mkvar PNG_CFLAGS) $(mkvar MPI_CFLAGS) \
 -DIRIS_PKGLIBDIR=\"/nonexistent\""
libs="$(mkvar EMBREE_LIBS) $(mkvar FREETYPE_LIBS) $(mkvar PNG_LIBS) \
 $(mkvar MPI_LIBS) -pthread -ldl -lm"
# everything but the programs (cli, compare) and the C++ OpenImageIO module
srcs=$(cd "$top" && ls povparse/*.c src/*/*.c | grep -v -e '^src/cli/' \
       -e '^src/compare/')
# compile what changed since its object was built, 'jobs' at a time
printf '%s\n' $srcs | CFLAGS_FUZZ="$cflags" TOP="$top" OBJ="$obj" CC="$CC" \
    xargs -P "$jobs" -I{} sh -c '
        o="$OBJ/$(echo {} | tr / _ | sed "s/\.c\$/.o/")"
        if [ ! -f "$o" ] || [ "$TOP/{}" -nt "$o" ] || \
           [ -n "$(find "$TOP/povparse" "$TOP/src" "$TOP/include" \
                   -name "*.h" -newer "$o" 2>/dev/null | head -n 1)" ]; then
            $CC $CFLAGS_FUZZ -c "$TOP/{}" -o "$o" 2>"$o.err" || {
                cat "$o.err"; rm -f "$o"
                echo "build.sh: {} does not compile with $CC; left out" \
                     "(the link fails if a target needs it)"; }
            cat "$o.err"; rm -f "$o.err"
        fi'
rm -f "$out/libfuzzcore.a"
# objects of sources removed since the last build must not linger
for o in "$obj"/*.o; do
    [ -e "$o" ] || continue
    n=$(basename "$o" .o)
    printf '%s\n' $srcs | tr / _ | grep -qx "$n.c" || rm -f "$o"
done
ar rcs "$out/libfuzzcore.a" "$obj"/*.o
for t in fuzz_parse fuzz_plan fuzz_render; do
    # shellcheck disable=SC2086
    $CC $cflags -fsanitize=fuzzer "$top/tests/fuzz/$t.c" "$out/libfuzzcore.a" \
        $libs -o "$out/$t"
    echo "built $out/$t"
done
# A libFuzzer dictionary of the SDL's words (session 7): every reserved
# word of povparse/tokens.def, the directives with their '#', and the
# punctuation that opens blocks and vectors. Mutations then splice whole
# keywords in, where byte flips almost never make one.
{
    sed -n 's/^\(TOK\|ALIAS\)([A-Z_0-9]*, *\("[^"]*"\)).*/\2/p' \
        "$top/povparse/tokens.def"
    for w in declare local undef macro end while for if ifdef ifndef else \
             elseif switch case range break include version debug warning \
             error fopen fclose read write default; do
        echo "\"#$w\""
    done
    printf '"%s"\n' '{' '}' '<' '>' ',' ';' '(' ')' '[' ']' '//' '/*' '*/'
} >"$out/sdl.dict"
echo "wrote $out/sdl.dict ($(wc -l <"$out/sdl.dict") entries)"
if [ -n "$2" ]; then
    corpus="$out/seed"
    mkdir -p "$corpus"
    sh "$top/tests/fuzz/seed.sh" "$corpus"
    for t in fuzz_parse fuzz_plan fuzz_render; do
        mkdir -p "$out/corpus-$t"
        "$out/$t" -max_total_time="$2" -timeout=10 -rss_limit_mb=2048 \
            -max_len=8192 -dict="$out/sdl.dict" "$out/corpus-$t" "$corpus"
    done
fi
