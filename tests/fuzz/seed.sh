#!/bin/sh
# SPDX-License-Identifier: MIT
# tests/fuzz/seed.sh DIR: copies the seed corpus (issue 7) into DIR: the
# example scenes, the parser's golden cases, the bad-input cases and the
# checked-in regression corpus. Inputs over 64 KiB are left out: libFuzzer
# mutates short inputs faster, and no grammar rule needs a long one.
set -e
top=$(cd "$(dirname "$0")/../.." && pwd)
dir=${1:?usage: seed.sh DIR}
mkdir -p "$dir"
find "$top/scenes" "$top/tests/parse/cases" "$top/tests/badinput/cases" \
     "$top/tests/stability/scenes" "$top/tests/fuzz/corpus" \
     -type f \( -name '*.pov' -o -name '*.inc' -o -path '*/fuzz/corpus/*' \) \
     -size -64k 2>/dev/null |
while read -r f; do
    # one flat name per file, unique by its path
    n=$(echo "${f#"$top"/}" | tr '/' '_')
    cp "$f" "$dir/$n"
done
