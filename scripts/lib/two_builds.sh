# Sourced by the scripts that draw crops with two builds (one_to_one.sh,
# mirror_outline.sh, steep_faces.sh, fine_relief.sh): checks their two arguments, sets $before and $after
# to the builds' absolute paths (the scripts work from the repository's
# top folder), checks for ImageMagick's montage, moves to the top folder,
# and makes $tmp (removed on exit) with an empty preferences file in it,
# $tmp/empty.toml: the defaults, whatever the preferences file of whoever
# runs the script says.
# Usage: . "$(dirname "$0")/lib/two_builds.sh" "$@"
if [ $# -ne 2 ]; then
    echo "usage: sh $0 BEFORE_BINARY AFTER_BINARY" >&2
    exit 2
fi
before=$1
after=$2
for b in "$before" "$after"; do
    [ -f "$b" ] && [ -x "$b" ] || { echo "error: $b is not an executable" >&2; exit 2; }
done
before=$(cd "$(dirname "$before")" && pwd)/$(basename "$before")
after=$(cd "$(dirname "$after")" && pwd)/$(basename "$after")
command -v montage >/dev/null 2>&1 || { echo "error: montage (ImageMagick) is needed" >&2; exit 2; }
cd "$(dirname "$0")/.."
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
: >"$tmp/empty.toml"

# crop_sheet OUT TITLE: reads lines "SEED WHAT X+Y" on its input; draws each
# seed at 3840x2160 at the defaults with both builds (once a seed), crops
# 800x500 at X+Y from each, and writes OUT: before on the left, after on the
# right, a crop a row, titled TITLE. JPEG with full-resolution colour (4:4:4),
# as one_to_one.sh: what the crops show is a pixel or two of colour.
crop_sheet() {
    out=$1
    title=$2
    : >"$tmp/tiles"
    while read -r seed what at; do
        for who in before after; do
            if [ "$who" = before ]; then bin=$before; else bin=$after; fi
            frame="$tmp/$who-$seed.png"
            [ -f "$frame" ] ||
                "$bin" render --config "$tmp/empty.toml" --size 3840x2160 --set "seed=$seed" -o "$frame" >/dev/null
            convert "$frame" -crop "800x500+${at}" +repage -set label "seed $seed, $what at $at: $who" \
                "$tmp/tile-$seed-$what-$who.png"
        done
        echo "$tmp/tile-$seed-$what-before.png $tmp/tile-$seed-$what-after.png" >>"$tmp/tiles"
    done
    # shellcheck disable=SC2046 # one argument per tile file
    montage $(cat "$tmp/tiles") -tile 2x -geometry +3+3 -pointsize 20 -background white \
        -title "$title" "$tmp/sheet.png"
    convert "$tmp/sheet.png" -strip -sampling-factor 4:4:4 -quality 88 "$out"
    echo "$out: $(wc -c <"$out") bytes"
}
