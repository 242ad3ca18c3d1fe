# Sourced by the scripts that draw crops with two builds (one_to_one.sh,
# mirror_outline.sh): checks their two arguments, sets $before and $after
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
