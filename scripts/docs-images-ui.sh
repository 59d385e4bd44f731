#!/usr/bin/env bash
# The README's viewer and editor pictures (scripts/docs-images.sh calls this): `ppr view` at 1280x720
# on the puddles camera in a private Xvfb display (the UI tests' tests/ui/ui_lib.sh), screenshot →
# WORK_DIR/viewer.png; then the Reflectors window opened and the large puddle selected by a click on
# it → WORK_DIR/editor.png. Nothing is saved. The panel shows frame times and the animation's clock, so
# these two pictures differ on every run.
#   scripts/docs-images-ui.sh PPR_BINARY WORK_DIR
set -uo pipefail
TEST=docs-images-ui
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# shellcheck source=../tests/ui/ui_lib.sh
source "$root/tests/ui/ui_lib.sh" "$@"

# A copy of the scene's reflector file, opened by a relative name so that the editor's title shows
# no machine's path.
ppr_abs="$(cd "$(dirname "$PPR")" && pwd)/$(basename "$PPR")"
cp "$(dirname "$ppr_abs")/../content/default/default.reflectors.json" "$WORK/" || fail "no default reflector file next to $PPR"
(cd "$WORK" && exec "$ppr_abs" view --size 1280x720 --render-scale 1 --camera puddles --reflectors default.reflectors.json --out out) >"$WORK/viewer.log" 2>&1 &
VIEWER_PID=$!
find_window
[ "$WW" -eq 1280 ] && [ "$WH" -eq 720 ] || fail "window is ${WW}x${WH}, expected 1280x720"
xdotool mousemove --sync $((WX + 640)) $((WY + 700))  # out of the panels' way
scene_region
drawn() { shot viewer && awk "BEGIN{exit !($(convert "$WORK/viewer-scene.png" -format '%[fx:standard_deviation]' info:) > 0.03)}"; }
wait_for "a picture in the window" drawn
sleep 8  # the panel's frame times settle
shot viewer
note "viewer.png"

# ImGui 1.86 reads the mouse at each frame's start: a click is held for longer than a frame takes on
# a loaded machine, and each step is clicked again only if the picture, seconds later, lacks it.
click_held() { xdotool mousemove --sync "$1" "$2" mousedown 1; sleep 1.5; xdotool mouseup 1; sleep 4; }
# The Reflectors window (top right) open: its dark panel covers the floor at (1200, 480).
expanded() { shot editor && awk "BEGIN{exit !($(convert "$WORK/editor.png" -format '%[fx:p{1200,480}.intensity]' info:) < 0.15)}"; }
open_reflectors() { expanded || { click_held $((WX + 921)) $((WY + 17)); expanded; }; }
wait_for "the Reflectors window open" open_reflectors
selected() {  # the selection outline (editor_ui.cpp's yellow) is on screen
    shot editor && [ "$(convert "$WORK/editor.png" -fill black +opaque 'rgb(255,200,40)' -fill white -opaque 'rgb(255,200,40)' -format '%[fx:mean*w*h]' info:)" != 0 ]
}
select_puddle() { selected || { click_held $((WX + 560)) $((WY + 520)); selected; }; }  # a click on the large puddle
wait_for "the puddle selected" select_puddle
xdotool mousemove --sync $((WX + 640)) $((WY + 700))
sleep 4
shot editor
note "editor.png"
close_viewer
