#!/bin/sh
# Runs the Windows build's screensaver paths (/s, /p <HWND>) under Wine on a
# private Xvfb: cross-builds mountains.exe fresh, then runs tests/platforms/wine.rs
# and tests/platforms/windows_resources.rs (the exe's name, version and icon), failing
# (not skipping) if Wine, mingw or the exe is missing.
# Needs: apt-get install -y wine64 gcc-mingw-w64-x86-64 xvfb xserver-xephyr, and
#        rustup target add x86_64-pc-windows-gnu
set -eu
cd "$(dirname "$0")/.."
cargo build --release --target x86_64-pc-windows-gnu
MOUNTAINS_REQUIRE_WINE=1 MOUNTAINS_REQUIRE_DISPLAY=1 cargo test --test platforms -- --include-ignored wine:: wine_power:: wine_span:: "$@"
MOUNTAINS_REQUIRE_WINE=1 cargo test --test platforms -- --include-ignored windows_resources:: "$@"
