#!/bin/sh
# Measures the full-screen saver under Xvfb: start to first present, CPU
# while drawing and while holding, peak memory (VmHWM) at 1080p and 4K.
# Usage: scripts/measure_saver.sh [path/to/mountains]   (default: release build)
#        MODE=--root scripts/measure_saver.sh              (the xscreensaver way; default /s)
#        SEED=5 scripts/measure_saver.sh                   (one seed's slides; default random)
# Needs Xvfb. Quiet machine recommended; numbers are per-core percentages.
set -eu
BIN=${1:-target/release/mountains}
MODE=${MODE:-/s}
SEED_SET=${SEED:+--set seed=$SEED}
[ -x "$BIN" ] || { echo "build first: cargo build --release" >&2; exit 1; }
HZ=$(getconf CLK_TCK)
TMP=$(mktemp -d)
XPID=
trap 'kill $SPID $XPID 2>/dev/null || true; rm -rf "$TMP"' EXIT
SPID=

ticks() { # utime + stime of $1, in clock ticks
    # Fields after the ")" that ends the command name: utime is 12th, stime 13th.
    sed 's/.*) //' "/proc/$1/stat" | awk '{print $12 + $13}'
}

cpu_percent() { # pid seconds -> percent of one core over that time
    a=$(ticks "$1"); sleep "$2"; b=$(ticks "$1")
    awk -v a="$a" -v b="$b" -v s="$2" -v hz="$HZ" 'BEGIN { printf "%.2f", (b - a) / hz / s * 100 }'
}

run_at() { # width height draw pause
    Xvfb -noreset -nolisten tcp -displayfd 3 -screen 0 "${1}x${2}x24" 3>"$TMP/display" 2>/dev/null &
    XPID=$!
    while [ ! -s "$TMP/display" ]; do sleep 0.05; done
    export DISPLAY=":$(cat "$TMP/display")"
    HOME=$TMP XDG_CONFIG_HOME=$TMP/c XDG_DATA_HOME=$TMP/d MOUNTAINS_TRACE=1 \
        "$BIN" "$MODE" $SEED_SET --set "draw_seconds=$3" --set "pause_seconds=$4" 2>"$TMP/err" &
    SPID=$!
}

stop() {
    kill "$SPID" 2>/dev/null || true; wait "$SPID" 2>/dev/null || true
    kill "$XPID" 2>/dev/null || true; wait "$XPID" 2>/dev/null || true
    rm -f "$TMP/display"
}

echo "== $MODE at 1920x1080, drawn over 8 s, held 12 s"
run_at 1920 1080 8 12
sleep 0.5
echo "CPU while drawing (0.5-7.5 s): $(cpu_percent "$SPID" 7) % of a core"
sleep 1.5
echo "CPU while holding (9-19 s):    $(cpu_percent "$SPID" 10) % of a core"
echo "VmHWM: $(awk '/VmHWM/ {print $2, $3}' "/proc/$SPID/status")"
grep -h "first frame" "$TMP/err" || echo "(no trace line)"
stop

echo "== $MODE at 3840x2160, drawn over 2 s, held 3 s"
run_at 3840 2160 2 3
sleep 4
echo "VmHWM: $(awk '/VmHWM/ {print $2, $3}' "/proc/$SPID/status")"
grep -h "first frame" "$TMP/err" || echo "(no trace line)"
stop
