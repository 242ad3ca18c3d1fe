#!/bin/sh
# Makes the Windows download: target/dist/mountains-<version>-windows-x86_64.zip
# with the stripped screensaver (mountains.scr), README-windows.txt (install,
# settings, uninstall) and LICENSE.txt, both with Windows line ends.
#
# Usage: sh scripts/windows_zip.sh [--exe PATH] [--out DIR]
#   --exe  pack this mountains.exe instead of building the release one
#          (`cargo build --release --locked --target x86_64-pc-windows-gnu`)
#   --out  write the zip into DIR instead of target/dist
# Needs x86_64-w64-mingw32-strip (binutils-mingw-w64-x86-64, with
# gcc-mingw-w64-x86-64) and zip.
set -eu
cd "$(dirname "$0")/.."

exe=
out=${CARGO_TARGET_DIR:-target}/dist
while [ $# -gt 0 ]; do
  case $1 in
    --exe) exe=${2:?--exe needs a path}; shift 2 ;;
    --out) out=${2:?--out needs a folder}; shift 2 ;;
    *) echo "windows_zip.sh: unknown argument '$1' (usage: sh scripts/windows_zip.sh [--exe PATH] [--out DIR])" >&2; exit 2 ;;
  esac
done
for tool in x86_64-w64-mingw32-strip zip; do
  command -v $tool >/dev/null || {
    echo "windows_zip.sh: $tool is missing (apt-get install gcc-mingw-w64-x86-64 zip)" >&2
    exit 1
  }
done
if [ -z "$exe" ]; then
  cargo build --release --locked --target x86_64-pc-windows-gnu
  exe=${CARGO_TARGET_DIR:-target}/x86_64-pc-windows-gnu/release/mountains.exe
fi
[ -f "$exe" ] || { echo "windows_zip.sh: $exe is not a file" >&2; exit 1; }

version=$(sed -n 's/^version = "\(.*\)"$/\1/p' Cargo.toml | head -n 1)
mkdir -p "$out"
out=$(cd "$out" && pwd)
# Built beside the output and renamed into place: never half a zip.
work=$(mktemp -d "$out/.zip.XXXXXX")
trap 'rm -rf "$work"' EXIT
umask 022
# The same sources give the same zip: every time is the last commit's (strip
# stamps the PE header with SOURCE_DATE_EPOCH when it is set, else with now).
SOURCE_DATE_EPOCH=${SOURCE_DATE_EPOCH:-$(git log -1 --format=%ct 2>/dev/null || date +%s)}
export SOURCE_DATE_EPOCH
x86_64-w64-mingw32-strip -o "$work/mountains.scr" "$exe"
sed "s/@VERSION@/$version/; s/\$/\r/" contrib/README-windows.txt >"$work/README-windows.txt"
sed 's/$/\r/' LICENSE >"$work/LICENSE.txt"
touch -d "@$SOURCE_DATE_EPOCH" "$work/mountains.scr" "$work/README-windows.txt" "$work/LICENSE.txt"
zip=mountains-$version-windows-x86_64.zip
(cd "$work" && zip -q -X -9 "$zip" mountains.scr README-windows.txt LICENSE.txt)
mv "$work/$zip" "$out/$zip"
echo "$out/$zip"
