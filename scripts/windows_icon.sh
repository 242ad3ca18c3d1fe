#!/bin/sh
# Regenerates assets/mountains.ico, the icon build.rs puts into the Windows
# exe, and from it the Linux icons (scripts/linux_icons.sh): one of the
# program's own mountains (seed 42 at the built-in defaults, 256x256), whole
# at 256 and 48 pixels, the central peak at 32 and 16 (the whole scene is a
# smudge that small).
# Needs ImageMagick's convert (apt-get install -y imagemagick).
# Usage: sh scripts/windows_icon.sh   (builds the release binary first)
set -eu
cd "$(dirname "$0")/.."
# /usr/bin/convert first: a stand-in earlier on PATH may not write .ico.
convert=convert
[ -x /usr/bin/convert ] && convert=/usr/bin/convert
cargo build --release -q
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# The defaults, whatever the preferences file of whoever runs this says.
: >"$work/empty.toml"
target/release/mountains render --config "$work/empty.toml" --size 256x256 \
  --set seed=42 -o "$work/m256.png" >/dev/null
"$convert" "$work/m256.png" -resize 48x48 "$work/m48.png"
"$convert" "$work/m256.png" -crop 160x160+80+40 +repage -resize 32x32 "$work/m32.png"
"$convert" "$work/m256.png" -crop 160x160+80+40 +repage -resize 16x16 "$work/m16.png"
# TrueColorAlpha: every size 32-bit (16 px has few enough colours that it
# would get a 256-colour palette). Written beside the old icon, then
# renamed over it: never half an icon.
"$convert" "$work/m16.png" "$work/m32.png" "$work/m48.png" "$work/m256.png" -type TrueColorAlpha \
  "ico:assets/mountains.ico.tmp"
mv assets/mountains.ico.tmp assets/mountains.ico
ls -l assets/mountains.ico
# The Linux desktop icons are the same pictures.
sh scripts/linux_icons.sh
