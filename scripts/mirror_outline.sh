#!/bin/sh
# Makes docs/mirror-outline-2160p.jpg: 1:1 crops of 3840x2160 frames where
# the land's outline is mirrored in the water, each drawn by two builds, the
# one before the smooth mirrored outline (issue 33) over the one after it.
#
# Usage: sh scripts/mirror_outline.sh BEFORE_BINARY AFTER_BINARY
# Needs ImageMagick 6 (convert, montage).
set -eu
. "$(dirname "$0")/lib/two_builds.sh" "$@"

# seed, extra setting (- for none), an 800x400 box's X+Y at 3840x2160.
scenes='30 - 900+1700
30 sun=sunset 1900+1600
8 - 900+1760'

echo "$scenes" | while read -r seed extra at; do
    for who in before after; do
        if [ "$who" = before ]; then bin=$before; else bin=$after; fi
        frame="$tmp/$who-$seed-$extra.png"
        if [ "$extra" = - ]; then
            "$bin" render --config "$tmp/empty.toml" --size 3840x2160 --seed "$seed" -o "$frame" >/dev/null
        else
            "$bin" render --config "$tmp/empty.toml" --size 3840x2160 --seed "$seed" --set "$extra" -o "$frame" >/dev/null
        fi
        light=$extra
        [ "$light" = - ] && light="defaults"
        convert "$frame" -crop "800x400+${at%+*}+${at#*+}" +repage \
            -set label "seed $seed ($light), 3840x2160 at $at: $who" "$tmp/tile-$seed-$extra-$who.png"
        echo "$tmp/tile-$seed-$extra-$who.png" >>"$tmp/tiles"
    done
done
# Each scene a column, before above after.
# shellcheck disable=SC2046 # one argument per tile file
montage $(sed -n '1~2p' "$tmp/tiles") $(sed -n '2~2p' "$tmp/tiles") \
    -tile 3x2 -geometry +4+4 -pointsize 18 -background '#202020' -fill white \
    "$tmp/strip.png"
convert "$tmp/strip.png" -sampling-factor 4:4:4 -quality 88 docs/mirror-outline-2160p.jpg
echo "docs/mirror-outline-2160p.jpg"
