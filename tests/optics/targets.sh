#!/bin/sh
# SPDX-License-Identifier: MIT
# tests/optics/targets.sh: photon targets found where POV-Ray 3.7 finds
# them (src/photon/targets.c; docs/optics.md check 29). Each case of
# scenes/targets.pov is rendered by the iris command with --stats, and
# the photons it emits and stores are compared with what POV-Ray 3.7.0.10
# reports for the same scene ('povray +V': "Number of photons shot",
# "Surface photons stored"), recorded below.
#
# Emitted: POV-Ray counts its rings over each target's bounding sphere
# and the photons of each ring by the same rule as iris (the same dtheta,
# the same phi steps a ring), so the counts agree exactly: 0.5% leaves
# room for nothing but rounding (the last ring alone is 2-5% of a
# target's photons; the union's sphere instead of its children's is 84%
# more for case 2). Stored: the mirrors reflect every photon, but
# POV-Ray starts each ring at a random phi, so its count moves by a
# photon or two between runs (2097 or 2098 for case 2): 1.5%, against
# 31% more for case 3 when a photon aimed at the ring that first meets
# the ball inside it is kept (the per-child version withdrawn in session
# 10), 3.5% fewer with the union's one sphere, all of them for a
# target iris did not find, and 6.8 times POV-Ray's count for case 13
# when a photon through the pass_through plate that misses the target is
# stored on the floor beyond (as iris did before session 12).
#
# Cases 14-16 ask for 'count 20000' with a blob as the target: the
# spacing comes from the target's bounding sphere, POV-Ray's box of a
# blob is the box around its components' bounding spheres
# (src/photon/povbox.c), and with iris's tighter box the spacing was
# finer and iris stored 1.5-3 times POV-Ray's photons (4294, 5738, 2200).
# POV-Ray also shoots its rings over that wider sphere, whose outer rings
# miss the blob; iris's stop at its own sphere, which holds the whole
# object, so only the stored photons are compared ('-': no emitted count).
# Case 17 (a target subtracted from a box, a mirror bowl) got no photons
# before session 12's second round: iris had no box for an object under
# a difference's inverse (src/accel/accel.c, accel_object_bounds).
. "$top_srcdir/tests/tap.sh"
scene="$top_srcdir/tests/optics/scenes/targets.pov"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# case, POV-Ray's photons shot and stored, what the case shows
cases='1 5942 1028 a_target_in_a_plain_union_with_a_table
2 11884 2097 a_flagged_union_split_into_its_two_balls
3 72956 6020 a_flagged_union_of_a_ring_around_a_ball_(overlapping_spheres)
4 21856 1943 a_flagged_merge:_one_target
5 21856 1943 a_flagged_union_with_split_union_off:_one_target
6 21856 1943 a_flagged_clipped_union:_one_target
7 5942 1001 a_target_in_a_difference_that_is_not_one
8 5942 1001 a_target_in_an_intersection_that_is_not_one
9 0 0 a_target_in_a_light_group_without_global_lights:_no_photons
10 5942 1028 a_target_in_a_light_group_with_global_lights_on
11 11884 2097 a_child_with_its_own_target_0.5:_the_union_spacing_wins
12 11884 2097 a_child_with_reflection_off:_the_union_flag_wins
13 5942 1027 a_target_under_a_pass_through_plate:_what_misses_it_not_stored
14 - 2857 count_20000,_a_blob_of_one_cylinder:_the_POV-Ray_blob_box
15 - 2068 count_20000,_the_glass_of_lights/glassthing.pov:_a_blob_in_a_merge_cut_by_a_plane
16 - 746 count_20000,_a_turned_blob_of_a_squashed_sphere_and_a_slanted_cylinder
17 5942 1706 a_target_subtracted_in_a_difference_that_is_not_one'
tap_plan "$(printf '%s\n' "$cases" | grep -c .)"
stat_of() { tr ',' '\n' <"$1" | awk -F: -v k="\"$2\"" '$1 ~ k { gsub(/[ }]/, "", $2); print $2 }'; }
# counts_ok EMITTED STORED POV_SHOT POV_STORED: within 0.5% and 1.5%
# (POV_SHOT '-': the emitted count is not compared)
counts_ok() { awk -v e="$1" -v s="$2" -v E="$3" -v S="$4" 'BEGIN {
    de = e - E; if (de < 0) de = -de; ds = s - S; if (ds < 0) ds = -ds
    exit !(e != "" && s != "" && (E == "-" || de <= 0.005 * E) &&
           ds <= 0.015 * S) }'; }
while read -r c shot stored what; do
    "$IRIS" -q "$scene" Declare=CASE="$c" +W8 +H6 -o "$tmp/t$c.exr" \
        --stats="$tmp/t$c.json" >"$tmp/log" 2>&1 || sed 's/^/# /' "$tmp/log"
    e=$(stat_of "$tmp/t$c.json" photons_emitted)
    s=$(stat_of "$tmp/t$c.json" photons_stored)
    tap_ok "case $c, $(echo "$what" | tr _ ' '): $e photons emitted, $s stored (POV-Ray 3.7: $shot, $stored)" \
        counts_ok "$e" "$s" "$shot" "$stored"
done <<EOF_CASES
$cases
EOF_CASES
exit $((tap_failed > 0))
