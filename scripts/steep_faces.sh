#!/bin/sh
# Makes docs/steep-faces-2160p.jpg: 1:1 crops of steep faces in 4K frames
# drawn at the defaults by two builds, the one before the side views of the
# relief (4a418a6: the bumps laid over the ground's plan, faded out on
# steep faces, which showed the grid's light blended down each face) over
# the one after them (a steep face takes its bumps from a side view: rock
# down the face as across it). Seed 705 is a tropical island's near wall,
# 101 a desert's mesa faces with their strata, 13 a winter's rock ridge.
#
# Usage: sh scripts/steep_faces.sh BEFORE_BINARY AFTER_BINARY
#   e.g. sh scripts/steep_faces.sh ../wt-base/target/release/mountains target/release/mountains
# Needs ImageMagick 6 (convert, montage).
set -eu
. "$(dirname "$0")/lib/two_builds.sh" "$@"

# seed, what the crop shows, then one 800x500 crop as X+Y of the 3840x2160 frame.
crops='705 face 1500+700
101 face 2300+750
13 face 1700+1500'

echo "$crops" | crop_sheet docs/steep-faces-2160p.jpg \
    "1:1 crops of 3840x2160 frames, defaults
before (left): the grid's light down each face; after (right): rock from the side views"
