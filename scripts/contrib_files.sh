#!/bin/sh
# Writes contrib/mountains.xml and contrib/mountains.6 from the key table
# (tests/platforms/contrib_files.rs fails while they differ from what the program prints).
set -eu
cd "$(dirname "$0")/.."
cargo build --quiet
target/debug/mountains --xscreensaver-xml > contrib/mountains.xml.tmp
mv contrib/mountains.xml.tmp contrib/mountains.xml
target/debug/mountains --man-page > contrib/mountains.6.tmp
mv contrib/mountains.6.tmp contrib/mountains.6
echo "contrib/mountains.xml and contrib/mountains.6 written"
