#!/bin/sh
# Makes docs/steep-faces-2160p.jpg: 1:1 crops of steep faces in 4K frames
# drawn at the defaults by two builds, the one before the rock strata
# (issue 33: curtains one grid column wide down every cliff) over the one
# after them (strata across the faces, each column's slope taken with its
# neighbours'). Seeds 28 and 15 are deserts whose cliffs are the terraces'
# faces; seed 8 is a snowy peak whose strata dip and fold.
#
# Usage: sh scripts/steep_faces.sh BEFORE_BINARY AFTER_BINARY
#   e.g. sh scripts/steep_faces.sh ../wt-base/target/release/mountains target/release/mountains
# Needs ImageMagick 6 (convert, montage).
set -eu
. "$(dirname "$0")/lib/two_builds.sh" "$@"

# seed, what the crop shows, then one 800x500 crop as X+Y of the 3840x2160 frame.
crops='28 face 1500+1450
15 face 2600+600
8 face 1600+600'

echo "$crops" | crop_sheet docs/steep-faces-2160p.jpg \
    "1:1 crops of 3840x2160 frames, defaults
before (left): curtains; after (right): strata"
