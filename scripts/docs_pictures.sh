#!/bin/sh
# Regenerates the pictures README.md shows (docs/*.png), one per mode, all of
# seed 1997 at 480x270, and the evening/morning/midday row.
# Usage: sh scripts/docs_pictures.sh   (builds the release binary first)
#
# A picture whose pixels did not change keeps its bytes: the encoder's output
# depends on how the program hands it rows (it changed with b2c3bb7's 64 Ki
# pixel batches), so re-encoding the same pixels gave files that differ in
# bytes only, and a re-run left pictures "modified" that were not. The pixels
# are compared with ImageMagick's `compare` when it is there; without it every
# picture is written anew.
set -eu
cd "$(dirname "$0")/.."
cargo build --release -q
m=target/release/mountains
# The defaults, whatever the preferences file of whoever runs this says.
empty=$(mktemp)
tmp=$(mktemp -d)
trap 'rm -rf "$empty" "$tmp"' EXIT
same_pixels() {
    command -v compare >/dev/null 2>&1 || return 1
    [ -f "$2" ] || return 1
    # `compare -metric AE` prints the number of differing pixels on stderr
    # and exits 1 when they differ, 2 on trouble.
    n=$(compare -metric AE "$1" "$2" null: 2>&1) || return 1
    [ "$n" = 0 ]
}
r() {
    out=$1
    shift
    # The temperate world: these show the keys, each against the same
    # coast (scripts/worlds_pictures.sh shows the worlds).
    "$m" render --config "$empty" --size 480x270 --set seed=1997 --set world=temperate "$@" -o "$tmp/$out.png" >/dev/null
    if same_pixels "$tmp/$out.png" "docs/$out.png"; then
        return 0
    fi
    mv "$tmp/$out.png" "docs/$out.png"
    echo "docs/$out.png: new pixels"
}
r natural
r morning --set sun=morning
r evening --set sun=evening
r sunset --set sun=sunset
r night --set sun=night
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
r brownian --set generator=brownian
r brownian-rough --set generator=brownian --set hurst=0.4
r lakes --set seed=30
r cliffs --set cliffs=0.6
r cloudy --set clouds=0.8
r mirror --set seed=8
r no-weather --set clouds=0 --set reflections=false
# Two 16:9 monitors under monitors = "span": one picture, a bezel put between
# its halves (seed 8's temperate coast: a peak across the seam).
"$m" render --config "$empty" --size 960x270 --set seed=8 --set world=temperate -o "$tmp/span-whole.png" >/dev/null
python3 scripts/span_picture.py "$tmp/span-whole.png" "$tmp/span.png"
if ! same_pixels "$tmp/span.png" docs/span.png; then
    mv "$tmp/span.png" docs/span.png
    echo "docs/span.png: new pixels"
fi
echo "docs/*.png regenerated"
