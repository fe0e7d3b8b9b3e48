#!/usr/bin/env bash
# The viewer's window shows what `fxkit render` writes headlessly: the same effect, mesh,
# size and framing give the same pixels. Both draw through the same shaders, pipelines and
# stand-ins; only the backgrounds differ (png_compare.py compares the pixels either drew).
# Tolerance: p99 2 and max 8 levels, coverage within 1% (a swapchain in another 8-bit format
# rounds differently; lavapipe gives 0).
# Usage: viewer_matches_render.sh XVFB_RUN FXKIT_VIEW FXKIT EFFECT WORK_DIR
set -euo pipefail
# Under the sanitizer build: GLFW's X11 and Vulkan libraries, loaded with dlopen and closed at
# exit, leave allocations LeakSanitizer cannot attribute (frames in an unknown module, so no
# suppression can name them) and it aborts the viewer; leak checking stays on for the rest.
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"
xvfb=$1 view=$2 fxkit=$3 effect=$4 work=$5
mkdir -p "$work"
"$xvfb" -a "$view" "$effect" --size 256x256 --frames 3 --validate --screenshot "$work/window.png"
"$fxkit" render "$effect" --size 256x256 --validation --out "$work/headless.png"
python3 "$(dirname "$0")/png_compare.py" "$work/window.png" "$work/headless.png"
