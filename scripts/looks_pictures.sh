#!/bin/sh
# Regenerates docs/look-*.jpg (and docs/looks.jpg, all the looks side by
# side; see its end): each seed program's look (`mountains render
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

# docs/looks.jpg: every look side by side, seed 7 at 480x270, labelled.
tile() {
    out=$1
    label=$2
    shift 2
    "$m" render --config "$empty" --size 480x270 --set seed=7 "$@" -o "$tmp/$out.png" >/dev/null
    printf '%s\n' "$label" >"$tmp/$out.label"
}
tile 1 'look = "ours"'
tile 2 'look = "fractal-mountain-climbing"' --set look=fractal-mountain-climbing
tile 3 'look = "mountain-terrain"' --set look=mountain-terrain
tile 4 'look = "mountain-terrain", color = "purple"' --set look=mountain-terrain --set color=purple
tile 5 'look = "fl3"' --set look=fl3
tile 6 'look = "essay" (seed 7: turned 56.25 degrees)' --set look=essay
montage \
    -label "$(cat "$tmp/1.label")" "$tmp/1.png" -label "$(cat "$tmp/2.label")" "$tmp/2.png" \
    -label "$(cat "$tmp/3.label")" "$tmp/3.png" -label "$(cat "$tmp/4.label")" "$tmp/4.png" \
    -label "$(cat "$tmp/5.label")" "$tmp/5.png" -label "$(cat "$tmp/6.label")" "$tmp/6.png" \
    -tile 3x2 -geometry +4+4 -background '#202020' -fill white -pointsize 15 \
    -strip -quality 88 -sampling-factor 4:2:0 -define jpeg:optimize-coding=true \
    docs/looks.jpg
echo docs/looks.jpg
