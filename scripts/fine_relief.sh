#!/bin/sh
# Makes docs/fine-relief-2160p.jpg: 1:1 crops of 4K frames drawn at the
# defaults by two builds, the one before the relief below the grid (issue
# 33: near land blended across cells of many pixels, soft blobs) beside the
# one after it (each pixel lit from the finer terrain). Seed 30 is an
# autumn coast in the sun: a foreground slope, a steep face and a mirrored
# shore; seed 1 an alpine valley's forest.
#
# Usage: sh scripts/fine_relief.sh BEFORE_BINARY AFTER_BINARY
#   e.g. sh scripts/fine_relief.sh ../wt-base/target/release/mountains target/release/mountains
# Needs ImageMagick 6 (convert, montage).
set -eu
. "$(dirname "$0")/lib/two_builds.sh" "$@"

# seed, what the crop shows, then one 800x500 crop as X+Y of the 3840x2160 frame.
crops='30 foreground-slope 200+1500
30 steep-face 2500+800
30 mirrored-shore 2900+1450
1 valley-forest 1300+1500'

echo "$crops" | crop_sheet docs/fine-relief-2160p.jpg \
    "1:1 crops of 3840x2160 frames, defaults
before (left): the grid's light blended; after (right): the relief below the grid"
