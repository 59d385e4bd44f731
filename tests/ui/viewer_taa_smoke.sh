#!/usr/bin/env bash
# ui.viewer_taa_motion: the viewer with TAA on (`--set taa=1`), driven by real keys in a real window,
# with its frames in flight and the TAA histories under validation and synchronization validation.
# Moving the camera (D held) changes the picture; released, the picture settles (screenshots a
# fraction of a second apart within 1 % of the scene's pixels: the history accumulates; without it
# the jitter moves every edge, and this test fails); the `motion` debug view (F2 until it shows,
# counted from `ppr --help`'s list) is black where nothing moves and lit while the camera moves;
# back to the frame, F12 captures with taa=1; F3 switches the technique (a history reset) and the
# camera moves again; a resize recreates the swapchain and the histories; the viewer exits with
# code 0 and no validation error.
#
# usage: viewer_taa_smoke.sh PPR_BINARY WORK_DIR
set -uo pipefail


TEST=ui.viewer_taa_motion
# shellcheck source=ui_lib.sh
source "$(dirname "$0")/ui_lib.sh" "$@"

PPR_VIEWER_FRAMES=5000 "$PPR" view --size 640x360 --validation --set taa=1 --out "$WORK/out" >"$WORK/viewer.log" 2>&1 &
VIEWER_PID=$!
find_window

scene_region
lit() { convert "$1" -colorspace gray -threshold 4% -format '%[fx:mean]' info:; }  # share of non-black pixels
above() { awk "BEGIN{exit !($1 > $2)}"; }
PIXELS=$((SW * SH))

xdotool mousemove --sync $((WX + WW - 100)) $((WY + WH / 2))
xdotool windowfocus "$WID" 2>/dev/null
sleep 0.3

# hold KEY CHECK: holds KEY until CHECK succeeds (polled once a second), then releases it.
hold() {
    local key=$1; shift
    xdotool keydown "$key"
    for _ in $(seq 1 "$STEP_TIMEOUT"); do
        alive || { xdotool keyup "$key"; fail "viewer exited while $key was held"; }
        sleep 1
        if "$@"; then xdotool keyup "$key"; return 0; fi
    done
    xdotool keyup "$key"
    return 1
}
# settled: three screenshots, 0.37 s and 0.61 s apart, differ in under 1 % of the scene's pixels. Uneven
# gaps: with screenshots a second apart, a build whose TAA ignored its history passed (0 pixels
# differed; the viewer drew about one 16-frame jitter cycle a second).
settled() {
    shot a; sleep 0.37; shot b; sleep 0.61; shot c
    n=$(( $(differing "$WORK/a-scene.png" "$WORK/b-scene.png") + $(differing "$WORK/b-scene.png" "$WORK/c-scene.png") ))
    measured="$n differing pixels"
    [ "$n" -lt $((PIXELS / 100)) ]
}

# 1. A picture, and it settles with the camera still (the ball's bob stays under 1 %).
wait_for "a still picture settled" settled
note "settled on a still camera ($n of $PIXELS pixels differ between three shots)"
shot start

# 2. Strafing changes the picture; released, it settles again.
moved() { shot now; n=$(differing "$WORK/start-scene.png" "$WORK/now-scene.png"); [ "$n" -gt $((PIXELS / 5)) ]; }
hold d moved || fail "holding D did not move the camera (only $n pixels differ)"
note "strafing changed $n of $PIXELS pixels"
wait_for "the picture settled after the strafe" settled
note "settled after the strafe ($n pixels differ between three shots)"

# 3. The motion debug view: black where nothing moves, lit while the camera moves. F2 steps through the
# views in `--help`'s order.
views=$("$PPR" --help 2>&1 | sed -n 's/^ *debug=\([a-z|]*\) .*/\1/p' | tr '|' '\n')
steps=$(printf '%s\n' "$views" | grep -n -x motion | cut -d: -f1)
[ -n "$steps" ] || fail "ppr --help lists no debug view 'motion'"
for _ in $(seq 2 "$steps"); do xdotool key F2; done
dark() { shot motion; share=$(lit "$WORK/motion-scene.png"); measured="$share lit"; above 0.15 "$share"; }
wait_for "the motion view was dark on a still camera" dark
note "motion view, still camera: $share of the scene lit"
bright() { shot motion; share=$(lit "$WORK/motion-scene.png"); above "$share" 0.3; }
hold w bright || fail "the motion view stayed dark while W was held ($share lit)"
note "motion view, camera moving: $share of the scene lit"

# 4. Back to the frame (F2 wraps round the list), TAA again; F12 captures it.
for _ in $(seq "$steps" "$(printf '%s\n' "$views" | wc -l)"); do xdotool key F2; done
sleep 1
xdotool key F12
capture_has() { [ -s "$WORK/out/$1/report.json" ] && sleep 1 && grep -q "$2" "$WORK/out/$1/report.json"; }
wait_for "F12 wrote view-capture-1" capture_has view-capture-1 '"debug": "none"'
grep -q '"taa": "1"' "$WORK/out/view-capture-1/report.json" || fail "view-capture-1 was not taken with taa=1"
grep -q '"validation_errors": 0' "$WORK/out/view-capture-1/report.json" || fail "view-capture-1: validation_errors is not 0"
note "F12 captured the TAA frame (view-capture-1)"

# 5. F3: the next technique (its histories start again), moving.
xdotool key F3
shot start
hold a moved || fail "holding A after F3 did not move the camera (only $n pixels differ)"
xdotool key F12
wait_for "F12 wrote view-capture-2 with ssr-brute" capture_has view-capture-2 '"technique": "ssr-brute"'
note "F3 switched to ssr-brute and the camera moved"

# 6. Resize with TAA on: the new area is drawn.
xdotool windowsize "$WID" 800 450
drawn() {
    eval "$(xdotool getwindowgeometry --shell "$WID")"
    [ "$WIDTH" -eq 800 ] && [ "$HEIGHT" -eq 450 ] || return 1
    WW=$WIDTH WH=$HEIGHT
    xwd -root -silent | convert xwd:- -crop "160x450+$((WX + 640))+$WY" +repage "png:$WORK/strip.png" || return 1
    sd=$(convert "$WORK/strip.png" -format '%[fx:standard_deviation]' info:)
    above "$sd" 0.03
}
wait_for "the resized window was drawn" drawn
note "resized to 800x450, new area drawn"

# 7. Clean exit: exit code 0 = no validation errors.
close_viewer
note "PASS (viewer exit code 0, no validation errors)"
exit 0
