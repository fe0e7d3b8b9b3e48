#!/usr/bin/env bash
# fxkit-view reloading in its window, as an effect author edits: a broken save is reported
# (file:line:col) while the window keeps drawing the last good version, and the fix reloads.
# Every step waits for what the viewer writes (a screenshot, a line), never for a fixed time;
# a step gives up after 60 s times FXKIT_TEST_SLOWDOWN (10 in sanitizer builds).
# Usage: viewer_reload.sh XVFB_RUN FXKIT_VIEW EFFECT WORK_DIR
set -euo pipefail
xvfb=$1 view=$2 effect=$3 work=$4
patience=$((60 * ${FXKIT_TEST_SLOWDOWN:-1}))
mkdir -p "$work"
file=$work/reload.fx
log=$work/viewer.log
loaded=$work/loaded.png
script=$work/reload.script
cp "$effect" "$file"
rm -f "$loaded"
# Loaded and drawing once the first screenshot is written; then it draws on, reloading.
printf 'frames 2\nscreenshot %s\nframes 1000000\n' "$loaded" >"$script"
"$xvfb" -a "$view" "$file" --script "$script" --size 160x120 --validate >"$log" 2>&1 &
pid=$!
# xvfb-run's children (the viewer and Xvfb) end with the test
trap 'pkill -P $pid 2>/dev/null; wait $pid 2>/dev/null || true' EXIT

# waits until `$1` succeeds while the viewer runs
wait_until() {
  local give_up=$((SECONDS + patience))
  while ((SECONDS < give_up)); do
    eval "$1" && return 0
    kill -0 $pid 2>/dev/null || { echo "fxkit-view exited early:"; cat "$log"; exit 1; }
    sleep 0.1
  done
  echo "not within ${patience} s: $1"; cat "$log"; exit 1
}
wait_for() { wait_until "grep -q -- '$1' '$log'"; }
wait_until "[ -s '$loaded' ]"
echo "technique broken { pass p0 { VertexShader = compile vs_2_0 Nowhere(); } }" >>"$file"
wait_for "^failed $file"
wait_for "$file:[0-9]*:[0-9]*: error"
cp "$effect" "$file"
wait_for "^reloaded $file"
kill -0 $pid  # still drawing
if grep -qi "validation" "$log"; then echo "validation messages:"; cat "$log"; exit 1; fi
cat "$log"
echo "viewer reload: ok"
