#!/bin/sh
# Makes docs/sky-water-1080p.jpg: five slides at 1920x1080 (a midday, an
# evening, a sunset, a cloudy one and a calm lake), each without the sky's weather and
# the water's mirror (clouds = 0, reflections = false: the sky and the water
# as they were before issue 19) beside the defaults; then a 1:1 crop of
# each slide's water under its shore, the same two ways.
#
# Usage: sh scripts/sky_water.sh   (builds the release binary first)
# Needs ImageMagick 6 (convert, montage).
set -eu
command -v montage >/dev/null 2>&1 || { echo "error: montage (ImageMagick) is needed" >&2; exit 2; }
cd "$(dirname "$0")/.."
cargo build --release -q
m=target/release/mountains
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# The defaults, whatever the preferences file of whoever runs this says.
: >"$tmp/empty.toml"

# seed, what the slide shows, a 480x270 box of water under a shore (X+Y at
# 1920x1080) for the 1:1 crop, and the time of day ("-": the seed's own).
slides='8 midday 560+560 -
13 evening 900+640 -
2 sunset 560+380 sunset
10 cloudy 700+560 -
30 lake 480+200 -'

n=0
echo "$slides" | while read -r seed what crop sun; do
    n=$((n + 1))
    for way in before after; do
        set --
        [ "$sun" != - ] && set -- --set sun="$sun"
        [ "$way" = before ] && set -- "$@" --set clouds=0 --set reflections=false
        "$m" render --config "$tmp/empty.toml" --size 1920x1080 --seed "$seed" "$@" \
            -o "$tmp/$n-$way.png" >/dev/null
        convert "$tmp/$n-$way.png" -resize 640x360 "$tmp/$n-$way-small.png"
        convert "$tmp/$n-$way.png" -crop "480x270+$crop" +repage "$tmp/$n-$way-crop.png"
    done
    label="seed $seed, $what"
    montage -label "$label: clouds = 0, reflections = false" "$tmp/$n-before-small.png" \
        -label "$label: the defaults" "$tmp/$n-after-small.png" \
        -label "1:1, before" "$tmp/$n-before-crop.png" \
        -label "1:1, after" "$tmp/$n-after-crop.png" \
        -tile 4x1 -geometry +4+4 -background '#202020' -fill white -pointsize 15 \
        "$tmp/row-$n.png"
done
convert "$tmp"/row-1.png "$tmp"/row-2.png "$tmp"/row-3.png "$tmp"/row-4.png "$tmp"/row-5.png -append \
    -sampling-factor 4:4:4 -quality 88 docs/sky-water-1080p.jpg
echo "docs/sky-water-1080p.jpg written"
