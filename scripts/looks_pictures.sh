#!/bin/sh
# Regenerates docs/look-*.jpg: each seed program's look (`mountains render
# --set look=...`, left) beside the picture its own document's rules make
# (examples/listing_pictures, right), seed 7, 640x480 each (the essay's
# 640x384: its 1000x600 canvas; FL3's reference is drawn at 1280x960 and
# shown halved). docs/classics.md shows them.
# Usage: sh scripts/looks_pictures.sh   (builds the release binaries first)
#
# Byte-reproducible: both renderers are deterministic, ImageMagick is told
# to write no dates or profiles (-strip, fixed quality and sampling).
set -eu
cd "$(dirname "$0")/.."
cargo build --release -q --bin mountains --example listing_pictures
m=target/release/mountains
tmp=$(mktemp -d)
empty=$(mktemp)
trap 'rm -rf "$tmp" "$empty"' EXIT
target/release/examples/listing_pictures -o "$tmp/ref" --seed 7 >/dev/null
for look in fractal-mountain-climbing mountain-terrain fl3 essay; do
    size=640x480
    [ "$look" = essay ] && size=640x384
    "$m" render --config "$empty" --size "$size" --set seed=7 --set look="$look" \
        -o "$tmp/ours-$look.png" >/dev/null
    montage "$tmp/ours-$look.png" "$tmp/ref/$look.png" -tile 2x1 \
        -geometry "$size+4+4" -background '#808080' -filter Triangle \
        -strip -quality 88 -sampling-factor 4:2:0 -define jpeg:optimize-coding=true \
        "docs/look-$look.jpg"
    echo "docs/look-$look.jpg"
done
