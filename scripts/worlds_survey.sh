#!/bin/sh
# The worlds' figures (BENCHMARKS.md): over 120 consecutive seeds with the
# default preferences, how many slides are mostly green below the horizon,
# have water across the bottom third or snow in the lower two thirds, how
# alike each slide is to its nearest other (16x9 Lab thumbnails), and how
# often the lakes show; then the same for the temperate world alone (the
# slide show before the worlds). The classifier is described in
# examples/worlds_survey.rs.
# Usage: sh scripts/worlds_survey.sh [--seeds A-B] [--size WxH]
set -eu
cd "$(dirname "$0")/.."
cargo build --release -q --example worlds_survey
s="${CARGO_TARGET_DIR:-target}/release/examples/worlds_survey"
echo "== the default preferences (world = \"varied\")"
"$s" --seeds 1-120 --size 320x180 "$@" | sed -n '/^slides:/,$p'
echo "== world = \"temperate\" (the slides before the worlds)"
"$s" --seeds 1-120 --size 320x180 --set world=temperate "$@" | sed -n '/^slides:/,$p'
