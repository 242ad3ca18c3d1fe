#!/bin/sh
# The worlds' pictures README.md shows: a contact sheet of 24 consecutive
# varied slides (the default preferences, seeds 1-24) and a row of four
# slides for each world (seeds 1-4 with `world` named), all at 320x180, put
# side by side with ImageMagick's `montage`.
# Usage: sh scripts/worlds_pictures.sh [--big DIR]
#   --big DIR  also each world at 1920x1080 (seed 2) and 1:1 crops of it at
#              3840x2160, into DIR, to look at (not committed)
set -eu
cd "$(dirname "$0")/.."
command -v montage >/dev/null || { echo "needs ImageMagick's montage (apt-get install imagemagick)"; exit 1; }
cargo build --release -q
m="${CARGO_TARGET_DIR:-target}/release/mountains"
empty=$(mktemp)
tmp=$(mktemp -d)
trap 'rm -rf "$empty" "$tmp"' EXIT
worlds="temperate alpine winter autumn desert tropical"
for seed in $(seq 1 24); do
    "$m" render --config "$empty" --size 320x180 --set seed="$seed" -o "$tmp/varied-$seed.png" >/dev/null
done
montage $(for s in $(seq 1 24); do echo "$tmp/varied-$s.png"; done) \
    -tile 6x4 -geometry 320x180+2+2 -background '#202020' -quality 88 docs/worlds-varied.jpg
for w in $worlds; do
    for seed in 1 2 3 4; do
        "$m" render --config "$empty" --size 320x180 --set seed="$seed" --set world="$w" \
            -o "$tmp/$w-$seed.png" >/dev/null
    done
    montage "$tmp/$w-1.png" "$tmp/$w-2.png" "$tmp/$w-3.png" "$tmp/$w-4.png" \
        -tile 4x1 -geometry 320x180+2+2 -background '#202020' -quality 88 "docs/world-$w.jpg"
done
echo "docs/worlds-varied.jpg and docs/world-*.jpg written"
if [ "${1:-}" = "--big" ] && [ -n "${2:-}" ]; then
    mkdir -p "$2"
    for w in $worlds; do
        "$m" render --config "$empty" --size 1920x1080 --set seed=2 --set world="$w" -o "$2/$w-1080p.png" >/dev/null
        "$m" render --config "$empty" --size 3840x2160 --set seed=2 --set world="$w" -o "$tmp/$w-4k.png" >/dev/null
        convert "$tmp/$w-4k.png" -crop 960x540+1440+1000 +repage "$2/$w-4k-crop.png"
    done
    echo "$2: each world at 1080p and a 1:1 crop of it at 4K"
fi
