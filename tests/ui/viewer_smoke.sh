#!/usr/bin/env bash
# ui.viewer_opens: `ppr view` opens a window on a private Xvfb display and draws the scene with the
# ImGui panel (at the default render scale, `auto`, which it says on a CPU device); F2 (cycle the
# `debug` setting) changes the picture; F12 writes a capture; the viewer exits cleanly with zero
# validation errors (it runs with --validation).
#
# usage: viewer_smoke.sh PPR_BINARY WORK_DIR
# Environment knobs: PPR_UI_FRAMES (frame limit, a safety net: the script closes the viewer with
# SIGTERM once the checks are done), PPR_UI_TIMEOUT (seconds to wait for each step, default 90).
set -uo pipefail

FRAMES=${PPR_UI_FRAMES:-3000}

TEST=ui.viewer_opens
# shellcheck source=ui_lib.sh
source "$(dirname "$0")/ui_lib.sh" "$@"

PPR_VIEWER_FRAMES=$FRAMES "$PPR" view --size 640x360 --validation --out "$WORK/out" >"$WORK/viewer.log" 2>&1 &
VIEWER_PID=$!

find_window
note "window $WID at $WX,$WY size ${WW}x${WH}: $(xdotool getwindowname "$WID")"
[ "$WW" -eq 640 ] && [ "$WH" -eq 360 ] || fail "window is ${WW}x${WH}, expected 640x360"

scene_region
stddev() { convert "$1" -format '%[fx:standard_deviation]' info:; }

# 1. The window shows a picture (not a blank/black swapchain image).
ok=""
for _ in $(seq 1 $((STEP_TIMEOUT))); do
    alive || fail "viewer exited before it drew a picture"
    shot first
    sd=$(stddev "$WORK/first-scene.png")
    if awk "BEGIN{exit !($sd > 0.03)}"; then ok=1; break; fi
    sleep 1
done
[ -n "$ok" ] || fail "the window stays blank (standard deviation $sd)"
note "picture drawn (scene standard deviation $sd, whole window $(stddev "$WORK/first.png"))"

# Frame-to-frame noise of a still camera (0 today; temporal techniques may add some): the F2 change
# must stand well above it. Differences are counted with a 2% fuzz (differing).
sleep 1
shot before
sleep 1
shot still
noise=$(differing "$WORK/before-scene.png" "$WORK/still-scene.png")
note "still-camera noise: $noise pixels"

# 2. F2 cycles the debug view (none → albedo): the scene region must change.
xdotool mousemove --sync $((WX + WW - 100)) $((WY + WH / 2))
xdotool windowfocus "$WID" 2>/dev/null
sleep 0.3
xdotool key F2
ok=""
for _ in $(seq 1 $((STEP_TIMEOUT))); do
    alive || fail "viewer exited while waiting for F2 to take effect"
    sleep 1
    shot after
    n=$(differing "$WORK/before-scene.png" "$WORK/after-scene.png")
    [ "$n" -gt $((SW * SH / 20)) ] && [ "$n" -gt $((noise * 4)) ] && { ok=1; break; }
done
[ -n "$ok" ] || fail "F2 did not change the picture (only $n pixels differ)"
note "F2 changed $n of $((SW * SH)) scene pixels"

# 3. F12 writes a capture (final.png + report.json) of the current view.
xdotool key F12
ok=""
for _ in $(seq 1 $((STEP_TIMEOUT))); do
    alive || fail "viewer exited while capturing"
    [ -s "$WORK/out/view-capture-1/report.json" ] && [ -s "$WORK/out/view-capture-1/final.png" ] && { ok=1; break; }
    sleep 1
done
[ -n "$ok" ] || fail "F12 wrote no $WORK/out/view-capture-1/{final.png,report.json}"
sleep 1  # report.json is written last; let it be complete
grep -q '"validation_errors": 0' "$WORK/out/view-capture-1/report.json" || fail "report.json: validation_errors is not 0"
grep -q '"final": "final.png"' "$WORK/out/view-capture-1/report.json" || fail "report.json does not name final.png"
grep -q '"debug": "albedo"' "$WORK/out/view-capture-1/report.json" || fail "report.json does not hold the F2 setting (debug=albedo)"
grep -q '"technique": "ppr"' "$WORK/out/view-capture-1/report.json" || fail "report.json: the viewer should start with --technique ppr"
note "F12 wrote $WORK/out/view-capture-1"

# 3b. F3 switches to the next technique (ppr → ssr-brute); the next capture records it.
xdotool key F3
sleep 1
xdotool key F12
ok=""
for _ in $(seq 1 $((STEP_TIMEOUT))); do
    alive || fail "viewer exited after F3"
    [ -s "$WORK/out/view-capture-2/report.json" ] && { sleep 1; grep -q '"technique": "ssr-brute"' "$WORK/out/view-capture-2/report.json" && { ok=1; break; }; }
    sleep 1
done
[ -n "$ok" ] || fail "F3 did not switch to the next technique (no view-capture-2 with technique ssr-brute)"
note "F3 switched to ssr-brute (view-capture-2)"

# 4. Resize: the swapchain is recreated and the bigger window shows a picture over its whole width.
xdotool windowsize "$WID" 800 450
ok=""
for _ in $(seq 1 $((STEP_TIMEOUT))); do
    alive || fail "viewer exited after the resize"
    sleep 1
    eval "$(xdotool getwindowgeometry --shell "$WID")"
    [ "$WIDTH" -eq 800 ] && [ "$HEIGHT" -eq 450 ] || continue
    WW=$WIDTH WH=$HEIGHT SW=$((WIDTH - 400)) SH=$HEIGHT
    shot resized
    # The strip that did not exist at 640x360 must be drawn too (not left black by an old swapchain).
    convert "$WORK/resized.png" -crop "160x450+640+0" +repage "png:$WORK/resized-strip.png"
    sd=$(stddev "$WORK/resized-strip.png")
    awk "BEGIN{exit !($sd > 0.03)}" && { ok=1; break; }
done
[ -n "$ok" ] || fail "after resizing to 800x450 the new area stays blank (standard deviation ${sd:-n/a})"
note "resized to 800x450, new area drawn (standard deviation $sd)"

# 5. Clean exit: SIGTERM closes the window like the close button; exit code 0 = no validation errors.
close_viewer
# The default render scale (`auto`): half the window's size on a CPU device, which the viewer says at
# start-up (read once it has exited: its output is buffered); a GPU renders at the window's own size and says nothing.
if grep -q '(cpu, Vulkan' "$WORK/viewer.log"; then
    grep -q "rendering at 0.50 of the window's size on a cpu device" "$WORK/viewer.log" ||
        fail "a CPU device's viewer did not say it renders at half the window's size (--render-scale auto)"
    note "render scale auto: 0.50 on the CPU device"
elif grep -q "rendering at .* of the window's size" "$WORK/viewer.log"; then
    fail "a GPU's viewer renders below the window's size by default"
fi
warnings=$(grep -c '^validation warning' "$WORK/viewer.log")
[ "$warnings" -eq 0 ] || note "note: $warnings validation warning(s) in $WORK/viewer.log"
note "PASS (viewer exit code 0, no validation errors)"
exit 0
