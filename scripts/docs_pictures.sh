#!/bin/sh
# Regenerates the pictures README.md shows (docs/*.png), one per mode, all of
# seed 1997 at 480x270, and the evening/morning/midday row.
# Usage: sh scripts/docs_pictures.sh   (builds the release binary first)
set -eu
cd "$(dirname "$0")/.."
cargo build --release -q
m=target/release/mountains
# The defaults, whatever the preferences file of whoever runs this says.
empty=$(mktemp)
trap 'rm -f "$empty"' EXIT
r() { out=$1; shift; "$m" render --config "$empty" --size 480x270 --set seed=1997 "$@" -o "docs/$out.png" >/dev/null; }
r natural
r morning --set sun=morning
r evening --set sun=evening
r oblique --set view=oblique
r perspective --set view=perspective
r triangle --set generator=triangle --set profile=massif
r sonar --set color=sonar
r sonar-low-detail --set color=sonar --set low_detail=true
r outline --set color=outline
r mono --set color=mono
r ridges --set color=ridges
r purple --set color=purple
r flat-water-no-shadows --set relative_depth=false --set shadows=false
echo "docs/*.png regenerated"
