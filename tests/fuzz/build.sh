#!/bin/sh
# SPDX-License-Identifier: MIT
# tests/fuzz/build.sh: builds the libFuzzer target of povparse with clang,
# AddressSanitizer and UBSan, and optionally runs it.
#
# usage: tests/fuzz/build.sh BUILD_DIR [SECONDS]
#   BUILD_DIR  a configured build tree (for config.h)
#   SECONDS    if given, fuzz that long from the golden test cases as seed
#              corpus (a crash leaves crash-* files in the current directory)
set -e
top=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:?usage: build.sh BUILD_DIR [SECONDS]}
out="$build/tests/fuzz"
mkdir -p "$out"
CC=${CC:-clang}
# src/fn evaluates pattern and pigment functions with src/material, which
# the parser calls when a scene evaluates such a function while parsing.
srcs="$top/tests/fuzz/fuzz_parse.c $top/povparse/*.c $top/src/util/arena.c \
 $top/src/util/mem.c $top/src/math/transform.c $top/src/scene/scene.c \
 $top/src/fn/*.c $top/src/material/*.c $top/src/image/image.c \
 $top/src/image/image_io.c $top/src/image/png.c"
$CC -g -O1 -std=c11 -D_GNU_SOURCE -fsanitize=fuzzer,address,undefined \
    -fno-sanitize-recover=undefined \
    -I"$build" -I"$top/include" -I"$top/src" -I"$top" \
    -DIRIS_PKGLIBDIR='"/nonexistent"' \
    $srcs -lpng -ldl -lm -o "$out/fuzz_parse"
echo "built $out/fuzz_parse"
if [ -n "$2" ]; then
    corpus="$out/corpus"
    mkdir -p "$corpus"
    cp "$top"/tests/parse/cases/*.pov "$corpus"/ 2>/dev/null || true
    "$out/fuzz_parse" -max_total_time="$2" -timeout=10 -rss_limit_mb=1024 \
        -max_len=4096 "$corpus"
fi
