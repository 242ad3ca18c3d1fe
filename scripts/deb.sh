#!/bin/sh
# Makes the Debian/Ubuntu package: target/dist/mountains_<version>_<arch>.deb
# with the stripped binary, xscreensaver's hack (a link in its hack folder)
# and settings XML, the man page, the desktop entries and icons, and the
# copyright. Depends: the C libraries the binary links (dpkg-shlibdeps) and
# the X11 and Wayland libraries it opens at run time (the table in
# src/platform/libcheck.rs, the one place that lists them).
#
# Usage: sh scripts/deb.sh [--binary PATH] [--out DIR]
#   --binary  package this binary (stripped on the way) instead of building
#             the release one (`cargo build --release --locked`)
#   --out     write the .deb into DIR instead of target/dist
# Needs dpkg-deb, dpkg-shlibdeps (dpkg-dev), strip (binutils), gzip.
# Install: sudo apt install ./target/dist/mountains_*.deb
set -eu
cd "$(dirname "$0")/.."

binary=
out=${CARGO_TARGET_DIR:-target}/dist
while [ $# -gt 0 ]; do
  case $1 in
    --binary) binary=${2:?--binary needs a path}; shift 2 ;;
    --out) out=${2:?--out needs a folder}; shift 2 ;;
    *) echo "deb.sh: unknown argument '$1' (usage: sh scripts/deb.sh [--binary PATH] [--out DIR])" >&2; exit 2 ;;
  esac
done
for tool in dpkg-deb dpkg-shlibdeps strip gzip; do
  command -v $tool >/dev/null || {
    echo "deb.sh: $tool is missing (apt-get install dpkg-dev binutils gzip)" >&2
    exit 1
  }
done
if [ -z "$binary" ]; then
  cargo build --release --locked
  binary=${CARGO_TARGET_DIR:-target}/release/mountains
fi
[ -x "$binary" ] || { echo "deb.sh: $binary is not an executable file" >&2; exit 1; }

version=$(sed -n 's/^version = "\(.*\)"$/\1/p' Cargo.toml | head -n 1)
arch=$(dpkg --print-architecture)
# The run-time libraries' packages, from the table the program itself uses
# to name a missing one ("libX11.so.6", "libx11-6").
table=$(grep -rl '^pub const X11_LIBRARIES' src)
# A pair in a list ends its line with "),", one standing alone with ");".
dlopened=$(sed -n 's/.*("lib[^"]*", "\([a-z0-9.+-]*\)")[,;]$/\1/p' $table | sort -u | paste -sd, - | sed 's/,/, /g')
[ -n "$dlopened" ] || { echo "deb.sh: no library table found in src/ (X11_LIBRARIES)" >&2; exit 1; }

mkdir -p "$out"
out=$(cd "$out" && pwd)
# Built beside the output and renamed into place: never half a package.
work=$(mktemp -d "$out/.deb.XXXXXX")
trap 'rm -rf "$work"' EXIT
umask 022
# dpkg-shlibdeps wants the Debian source layout: debian/control, and the
# files under debian/<package>/.
mkdir -p "$work/debian"
printf 'Source: mountains\n\nPackage: mountains\nArchitecture: any\n' >"$work/debian/control"
root=$work/debian/mountains

install -d "$root/usr/bin" "$root/usr/libexec/xscreensaver" \
  "$root/usr/share/xscreensaver/config" "$root/usr/share/man/man6" \
  "$root/usr/share/applications" "$root/usr/share/doc/mountains" "$root/DEBIAN"
strip -o "$root/usr/bin/mountains" "$binary"
chmod 755 "$root/usr/bin/mountains"
# xscreensaver runs hacks from its own folder first (Debian: /usr/libexec/xscreensaver).
ln -s ../../bin/mountains "$root/usr/libexec/xscreensaver/mountains"
install -m 644 contrib/mountains.xml "$root/usr/share/xscreensaver/config/mountains.xml"
gzip -9n <contrib/mountains.6 >"$root/usr/share/man/man6/mountains.6.gz"
install -m 644 contrib/mountains.desktop contrib/mountains-settings.desktop "$root/usr/share/applications/"
for dir in assets/hicolor/*/apps; do
  px=${dir#assets/hicolor/}
  install -D -m 644 "$dir/mountains.png" "$root/usr/share/icons/hicolor/${px%/apps}/apps/mountains.png"
done

{
  echo "Format: https://www.debian.org/doc/packaging-manuals/copyright-format/1.0/"
  echo "Upstream-Name: mountains"
  echo
  echo "Files: *"
  echo "Copyright: $(sed -n 's/^Copyright (c) //p' LICENSE)"
  echo "License: MIT"
  # The licence text, indented, an empty line as " .".
  sed -n '/^Permission/,$p' LICENSE | sed 's/^$/./; s/^/ /'
} >"$root/usr/share/doc/mountains/copyright"

# Its stderr only when it fails: it warns that a binary "should already be
# installed in its package's directory", which this one is.
shlibs=$(cd "$work" && dpkg-shlibdeps -O -e debian/mountains/usr/bin/mountains 2>"$work/shlibdeps.err" |
  sed -n 's/^shlibs:Depends=//p')
[ -n "$shlibs" ] || { cat "$work/shlibdeps.err" >&2; echo "deb.sh: dpkg-shlibdeps found no libraries" >&2; exit 1; }
# Installed-Size as dpkg-gencontrol counts it, the same on any filesystem
# (du counts blocks, which differ): a file or link its size in KiB rounded
# up, anything else (a folder) 1 KiB.
size=$(find "$root" -path "$root/DEBIAN" -prune -o -printf '%y %s\n' |
  awk '{ kib += ($1 == "f" || $1 == "l") ? int(($2 + 1023) / 1024) : 1 } END { print kib }')
description=$(sed -n 's/^description = "\(.*\)"$/\1/p' Cargo.toml | head -n 1)
cat >"$root/DEBIAN/control" <<EOF
Package: mountains
Version: $version
Architecture: $arch
Maintainer: ${DEBFULLNAME:-mountains authors} <${DEBEMAIL:-mountains@localhost}>
Installed-Size: $size
Depends: $shlibs, $dlopened
Suggests: xscreensaver
Section: x11
Priority: optional
Description: $description
 Makes a mountain by recursive subdivision and draws it strip by strip as
 shaded triangles, then the next one, like a slide show: a window
 (mountains --window), full screen (mountains /s, also under Wayland idle
 daemons), or an xscreensaver hack (add "mountains --root" to the programs
 list in ~/.xscreensaver). Keeps the modes of Mountain Terrain 3.0 and
 xmountains: colour filters, Sonar, water by depth, saved data sets.
EOF
(cd "$root" && find usr -type f | LC_ALL=C sort | xargs md5sum) >"$root/DEBIAN/md5sums"
chmod 644 "$root/DEBIAN/control" "$root/DEBIAN/md5sums"

# The same sources give the same package: every time is the last commit's.
SOURCE_DATE_EPOCH=${SOURCE_DATE_EPOCH:-$(git log -1 --format=%ct 2>/dev/null || date +%s)}
export SOURCE_DATE_EPOCH
find "$root" -exec touch -h -d "@$SOURCE_DATE_EPOCH" {} +
deb=mountains_${version}_${arch}.deb
dpkg-deb --root-owner-group -Zxz --build "$root" "$work/$deb" >/dev/null
mv "$work/$deb" "$out/$deb"
echo "$out/$deb"
