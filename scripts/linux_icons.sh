#!/bin/sh
# Writes assets/hicolor/NxN/apps/mountains.png (16, 32, 48, 256), the icons the
# .deb installs for the desktop entries, from the pictures of
# assets/mountains.ico (scripts/windows_icon.sh makes that from a mountain).
# tests/platforms/packages.rs fails while they differ from the icon.
# Usage: sh scripts/linux_icons.sh
set -eu
cd "$(dirname "$0")/.."
cargo run --quiet --example hicolor_icons
