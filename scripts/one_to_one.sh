#!/bin/sh
# Makes docs/one-to-one-1080p.jpg and docs/one-to-one-2160p.jpg: crops of
# frames at 1:1 (no scaling), a foreground slope, a far ridge, a piece of
# skyline and a piece of coast of three seeds, each drawn by two builds, the
# one before smooth shading (issue 18) over the one after it.
#
# Usage: sh scripts/one_to_one.sh BEFORE_BINARY AFTER_BINARY
#   e.g. sh scripts/one_to_one.sh ../wt-base/target/release/mountains target/release/mountains
# Needs ImageMagick 6 (convert, montage).
#
# Seeds 1997 and 42 drew another time of day before "one seed, one scene"
# (1997 was midday, 42 evening); so that the crops compare the drawing and
# not the light, both builds draw them under the sun the new build gives them
# (1997 evening, 42 midday), fixed with --set sun=. Seed 8 is midday in both
# builds at 1080p and is drawn with the defaults; at 4K the old build gave it
# another light (the fault "one seed, one scene" mends), which the strip shows. The 4K crops cover the same part of
# the scene as the 1080p ones: coordinates and sizes doubled.
set -eu
. "$(dirname "$0")/lib/two_builds.sh" "$@"

# seed, extra settings, then four crops as X+Y of a 320x200 box at 1920x1080:
# foreground slope, far ridge, skyline, coast.
scenes='1997 sun=evening 180+430 600+280 300+130 1150+700
42 sun=midday 400+750 1150+180 780+130 1340+690
8 - 1600+690 1500+350 800+130 220+740'
parts='foreground-slope far-ridge skyline coast'

# strip SIZE SCALE QUALITY OUT NOTE: one row of four crops per build and seed.
# JPEG with full-resolution colour (4:4:4): halved chroma would smear the very
# edges the crops are for. The 4K strip at quality 86 stays under 1.5 MB
# (38.0 dB against its PNG; 90 would be 1.76 MB, 39.6 dB).
strip() {
    size=$1
    k=$2
    quality=$3
    out=$4
    note=$5
    echo "$scenes" | while read -r seed extra slope ridge sky coast; do
        for who in before after; do
            if [ "$who" = before ]; then bin=$before; else bin=$after; fi
            frame="$tmp/$who-$seed-$size.png"
            if [ "$extra" = - ]; then
                "$bin" render --config "$tmp/empty.toml" --size "$size" --set "seed=$seed" -o "$frame" >/dev/null
            else
                "$bin" render --config "$tmp/empty.toml" --size "$size" --set "seed=$seed" --set "$extra" -o "$frame" >/dev/null
            fi
            set -- $parts
            for at in "$slope" "$ridge" "$sky" "$coast"; do
                x=$((${at%+*} * k))
                y=$((${at#*+} * k))
                w=$((320 * k))
                h=$((200 * k))
                light=$extra
                [ "$light" = - ] && light="defaults"
                label="seed $seed ($light), $1 at $x,$y: $who"
                convert "$frame" -crop "${w}x${h}+${x}+${y}" +repage -set label "$label" \
                    "$tmp/tile-$seed-$who-$1.png"
                echo "$tmp/tile-$seed-$who-$1.png" >>"$tmp/tiles-$size"
                shift
            done
        done
    done
    # shellcheck disable=SC2046 # one argument per tile file
    montage $(cat "$tmp/tiles-$size") -tile 4x -geometry +3+3 -pointsize $((11 * k)) \
        -background white -title "1:1 crops of ${size} frames: before (e1354d1, flat faces), after (smooth shading; skyline, crests and coast anti-aliased; lakes)\n${note}" \
        "$tmp/strip.png"
    convert "$tmp/strip.png" -strip -sampling-factor 4:4:4 -quality "$quality" "$out"
    echo "$out: $(wc -c <"$out") bytes"
}
strip 1920x1080 1 90 docs/one-to-one-1080p.jpg \
    "seeds 1997 and 42 under a fixed sun in both (before, they drew other times of day); seed 8 at its defaults"
strip 3840x2160 2 86 docs/one-to-one-2160p.jpg \
    "seeds 1997 and 42 under a fixed sun in both; seed 8 at its defaults: before, its light at 4K was not its 1080p one"
