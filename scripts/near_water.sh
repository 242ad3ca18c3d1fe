#!/bin/sh
# Makes docs/near-water-2160p.jpg: 1:1 crops of 3840x2160 frames where the
# water near the viewer mirrors the land, each drawn by two builds, the one
# before the mirrored land stood for its width and the streaks' tilt faded
# on water seen wide (issue 33) beside the one after it.
#
# Usage: sh scripts/near_water.sh BEFORE_BINARY AFTER_BINARY
#   e.g. sh scripts/near_water.sh ../wt-base/target/release/mountains target/release/mountains
# Needs ImageMagick 6 (convert, montage).
set -eu
. "$(dirname "$0")/lib/two_builds.sh" "$@"

# seed, what the crop shows, then one 800x500 crop as X+Y of the 3840x2160 frame.
crops='23 near-water 1400+1660
8 near-lake 1300+1660
2 near-water 2700+1660'

echo "$crops" | crop_sheet docs/near-water-2160p.jpg \
    "1:1 crops of 3840x2160 frames, defaults; near water before (left) and after (right)
after: the mirrored land the mean across its width, no streak tilt where the water is near"
