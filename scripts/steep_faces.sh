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

# seed, then one 800x500 crop as X+Y of the 3840x2160 frame.
crops='28 1500+1450
15 2600+600
8 1600+600'

echo "$crops" | while read -r seed at; do
    for who in before after; do
        if [ "$who" = before ]; then bin=$before; else bin=$after; fi
        frame="$tmp/$who-$seed.png"
        "$bin" render --config "$tmp/empty.toml" --size 3840x2160 --set "seed=$seed" -o "$frame" >/dev/null
        convert "$frame" -crop "800x500+${at}" +repage -set label "seed $seed at $at: $who" \
            "$tmp/tile-$seed-$who.png"
    done
    echo "$tmp/tile-$seed-before.png $tmp/tile-$seed-after.png" >>"$tmp/tiles"
done
# Before on the left, after on the right, one seed a row. JPEG with full
# resolution colour (4:4:4), as one_to_one.sh: the streaks are a pixel or
# two of colour.
# shellcheck disable=SC2046 # one argument per tile file
montage $(cat "$tmp/tiles") -tile 2x -geometry +3+3 -pointsize 20 -background white \
    -title "1:1 crops of 3840x2160 frames, defaults\nbefore (left): curtains; after (right): strata" \
    "$tmp/sheet.png"
out=docs/steep-faces-2160p.jpg
convert "$tmp/sheet.png" -strip -sampling-factor 4:4:4 -quality 88 "$out"
echo "$out: $(wc -c <"$out") bytes"
