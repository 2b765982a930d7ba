#!/bin/sh
# SPDX-License-Identifier: MIT
# tests/largerun/photon_file.sh: photons { save_file } and { load_file }
# (issue 8; src/photon/photon_file.c). A map saved and loaded back is the
# same map record for record, so the image must be identical: imgdiff's
# largest difference of the linear float pixels is exactly 0, no
# tolerance. The load run asks for 1 photon: were it shooting instead of
# loading, its image would differ (checked too, so the comparison can
# fail). A truncated, damaged, foreign, other-version or missing file is
# an error at the load_file keyword (photon_file.pov line 16, column 20)
# with exit status 1, never a crash or an image.
. "$top_srcdir/tests/tap.sh"
tap_plan 13
scene="$top_srcdir/tests/largerun/photon_file.pov"
imgdiff="$top_builddir/tests/progressive/imgdiff"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
r() { "$IRIS" -q "$scene" +W32 +H32 --threads 2 --seed 5 "$@"; }

r Declare=Mode=1 -o saved.exr --stats saved.json
tap_ok "save_file writes the photon file" test -s ball.photons
cp ball.photons good.photons
r Declare=Mode=2 Declare=Photons=1 -o loaded.exr --stats loaded.json
d=$("$imgdiff" saved.exr loaded.exr)
tap_is "load_file renders the saved render's image bit for bit" "$d" "0"
tap_is "... and reports the saved photon count" \
    "$(grep -o '"photons_stored": [0-9]*' loaded.json)" \
    "$(grep -o '"photons_stored": [0-9]*' saved.json)"
r Declare=Photons=1 -o shot1.exr
d=$("$imgdiff" saved.exr shot1.exr)
tap_ok "... while shooting 1 photon gives another image (difference $d)" \
    awk -v d="$d" 'BEGIN { exit !(d + 0 > 0.01) }'
r Declare=Mode=2 --passes 3 -o prog.exr
tap_ok "progressive passes after a loaded pass 0 run" test -s prog.exr

# bad_load NAME: the load must fail at the keyword with exit status 1,
# with WHAT in the message, and write no image
bad_load() { name=$1 what=$2
    rm -f bad.exr
    r Declare=Mode=2 -o bad.exr 2>err.txt
    rc=$?
    echo "# rc $rc: $(cat err.txt)"
    tap_ok "$name: located error, exit 1" sh -c "test $rc = 1 &&
        grep -q 'photon_file.pov:16:20: error: .*$what' err.txt &&
        test ! -e bad.exr"
}
head -c 20000 good.photons >ball.photons
bad_load "truncated file" "truncated"
head -c 50 good.photons >ball.photons
bad_load "truncated header" "truncated header"
cp "$scene" ball.photons
bad_load "foreign file" "not an iris photon file"
cp good.photons ball.photons
printf '\125' | dd of=ball.photons bs=1 seek=1000 conv=notrunc 2>/dev/null
bad_load "a damaged photon record" "damaged"
cp good.photons ball.photons
printf '\007' | dd of=ball.photons bs=1 seek=8 conv=notrunc 2>/dev/null
bad_load "another format version" "another version"
cp good.photons ball.photons
printf '\001\002\003\004' | dd of=ball.photons bs=1 seek=12 conv=notrunc \
    2>/dev/null
bad_load "the other byte order" "another byte order"
rm -f ball.photons
bad_load "a missing file" "cannot read the photon file"

# save_file and load_file together: POV-Ray refuses them; a scene error
printf '#version 3.7;\nglobal_settings { photons { count 10\n  save_file "a" load_file "b" } }\n' >both.pov
"$IRIS" -q both.pov +W8 +H8 -o both.png 2>err.txt
rc=$?
tap_ok "save_file with load_file: scene error (exit 2) at load_file" \
    sh -c "test $rc = 2 && grep -q 'both.pov:3:17' err.txt"
[ "$tap_failed" -eq 0 ]
