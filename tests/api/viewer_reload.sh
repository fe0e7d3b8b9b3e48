#!/usr/bin/env bash
# fxkit-view reloading in its window, as an effect author edits: a broken save is reported
# (file:line:col) while the window keeps drawing the last good version, and the fix reloads.
# Usage: viewer_reload.sh XVFB_RUN FXKIT_VIEW EFFECT WORK_DIR
set -euo pipefail
xvfb=$1 view=$2 effect=$3 work=$4
mkdir -p "$work"
file=$work/reload.fx
log=$work/viewer.log
cp "$effect" "$file"
"$xvfb" -a "$view" "$file" --frames 1000000 --size 160x120 --validate >"$log" 2>&1 &
pid=$!
# xvfb-run's children (the viewer and Xvfb) end with the test
trap 'pkill -P $pid 2>/dev/null; wait $pid 2>/dev/null || true' EXIT

# waits (10 s at most) for a line matching $1 while the viewer runs
wait_for() {
  for _ in $(seq 1 100); do
    grep -q -- "$1" "$log" && return 0
    kill -0 $pid 2>/dev/null || { echo "fxkit-view exited early:"; cat "$log"; exit 1; }
    sleep 0.1
  done
  echo "no '$1' within 10 s:"; cat "$log"; exit 1
}
sleep 1  # loaded and drawing
echo "technique broken { pass p0 { VertexShader = compile vs_2_0 Nowhere(); } }" >>"$file"
wait_for "^failed $file"
wait_for "$file:[0-9]*:[0-9]*: error"
cp "$effect" "$file"
wait_for "^reloaded $file"
kill -0 $pid  # still drawing
if grep -qi "validation" "$log"; then echo "validation messages:"; cat "$log"; exit 1; fi
cat "$log"
echo "viewer reload: ok"
