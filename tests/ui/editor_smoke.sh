#!/usr/bin/env bash
# ui.editor_snap_move_save: the reflector editor driven by real input in a real window. Ctrl+click on
# the floor snaps a new reflector onto it, dragging its centre handle moves it, Ctrl+S saves; the saved
# file holds it at the new place, and a headless `ppr capture` with it shows reflector pixels and a
# PPR reflection there and nowhere else; Ctrl+Z undoes the move; a viewer killed right after Ctrl+S
# leaves a valid file.
#
# usage: editor_smoke.sh PPR_BINARY WORK_DIR
# PPR_UI_VIEW_ARGS: more viewer options, default --render-scale 1 (the window's own resolution, which
# `auto` would halve on lavapipe); ui.editor_render_scale passes --render-scale 0.5: the click must
# pick the render pixel under the cursor, not the window pixel.
set -uo pipefail

TEST=${PPR_UI_TEST_NAME:-ui.editor_snap_move_save}
read -r -a VIEW_ARGS <<<"${PPR_UI_VIEW_ARGS:---render-scale 1}"
# shellcheck source=ui_lib.sh
source "$(dirname "$0")/ui_lib.sh" "$@"

SCENE_DIR=$(dirname "$PPR")/../content/default
FILE="$WORK/edited.reflectors.json"
cp "$SCENE_DIR/default.reflectors.json" "$FILE" || fail "no default reflector file in $SCENE_DIR"
count() { python3 -c "import json,sys; print(len(json.load(open(sys.argv[1]))['reflectors']))" "$1"; }
centre() { python3 -c "import json,sys; r=[r for r in json.load(open(sys.argv[1]))['reflectors'] if r['name']=='puddle_1']; print(' '.join('%.3f' % c for c in r[0]['center']) if r else 'none')" "$1"; }
before=$(count "$FILE")

start_viewer() {
    "$PPR" view --size 640x360 --camera puddles --reflectors "$FILE" --validation --out "$WORK/out" "${VIEW_ARGS[@]}" >"$WORK/viewer.log" 2>&1 &
    VIEWER_PID=$!
    find_window
    xdotool windowfocus "$WID" 2>/dev/null
    sleep 3  # a few frames drawn
}
shot_window() { xwd -root -silent | convert xwd:- -crop "${WW}x${WH}+${WX}+${WY}" +repage "png:$WORK/view.png"; }
selected() {  # the selection outline (yellow) is on screen
    shot_window || return 1
    [ "$(convert "$WORK/view.png" -fill black +opaque 'rgb(255,200,40)' -fill white -opaque 'rgb(255,200,40)' -format '%[fx:mean*w*h]' info:)" != 0 ]
}
handle_at() {  # handle_at X Y COLOUR: a handle of COLOUR lies within 6 px of window pixel (X, Y)
    shot_window || return 1
    [ "$(convert "$WORK/view.png" -crop "13x13+$(($1 - 6))+$(($2 - 6))" +repage -fill black +opaque "$3" -fill white -opaque "$3" -format '%[fx:mean*w*h]' info:)" != 0 ]
}
WHITE='rgb(255,255,255)' ORANGE='rgb(255,110,0)'  # a handle, the handle being dragged (editor_ui.cpp)
saved_with() { [ "$(centre "$FILE")" != none ] && [ "$(centre "$FILE")" != "$1" ]; }

start_viewer
# The floor just below the red ball (puddles camera, 640x360): a patch there reflects the ball.
PX=$((WX + 440)) PY=$((WY + 212))
xdotool mousemove --sync "$PX" "$PY"
sleep 1
# Every step waits for what the viewer shows, not for a time: on a loaded machine one frame can take
# seconds, and ImGui 1.86 sees only the input state at each frame's start.
xdotool keydown ctrl
sleep 0.5
xdotool click 1
wait_for "the snapped reflector in the view" selected
xdotool keyup ctrl
xdotool key ctrl+s
wait_for "the snapped reflector in the saved file" saved_with none
snapped=$(centre "$FILE")
[ "$(count "$FILE")" -eq $((before + 1)) ] || fail "the saved file should hold one more reflector"
note "snapped puddle_1 at $snapped"

# Drag its centre handle (at the click point) 24 px right and 6 px down: it moves along the floor.
HX=$((PX - WX)) HY=$((PY - WY))  # the handle in window pixels
wait_for "the centre handle under the cursor" handle_at "$HX" "$HY" "$WHITE"
xdotool mousemove --sync "$PX" "$PY" mousedown 1
wait_for "the centre handle grabbed" handle_at "$HX" "$HY" "$ORANGE"
for step in 1 2 3 4 5 6; do xdotool mousemove --sync $((PX + 4 * step)) $((PY + step)); sleep 0.2; done
wait_for "the grabbed handle at the drag's end" handle_at $((HX + 24)) $((HY + 6)) "$ORANGE"
xdotool mouseup 1
wait_for "the handle released" handle_at $((HX + 24)) $((HY + 6)) "$WHITE"
xdotool key ctrl+s
wait_for "the moved reflector in the saved file" saved_with "$snapped"
moved=$(centre "$FILE")
note "moved to $moved"
python3 - "$snapped" "$moved" <<'PY' || fail "the move should stay on the floor (y = 0) and go somewhere"
import sys
a = [float(v) for v in sys.argv[1].split()]; b = [float(v) for v in sys.argv[2].split()]
assert abs(b[1]) < 0.02 and abs(a[1]) < 0.02, (a, b)
assert ((a[0] - b[0]) ** 2 + (a[2] - b[2]) ** 2) ** 0.5 > 0.05, (a, b)
PY
cp "$FILE" "$WORK/moved.reflectors.json"

# Undo restores the snapped position.
xdotool key ctrl+z
sleep 2
xdotool key ctrl+s
wait_for "the undone move in the saved file" bash -c "[ \"\$(python3 -c \"import json; r=[r for r in json.load(open('$FILE'))['reflectors'] if r['name']=='puddle_1']; print(' '.join('%.3f' % c for c in r[0]['center']))\")\" = '$snapped' ]"
note "Ctrl+Z restored $snapped"

# A viewer killed right after Ctrl+S leaves a valid file (temp file + rename).
xdotool key ctrl+y
xdotool key ctrl+s
kill -9 "$VIEWER_PID"
wait "$VIEWER_PID" 2>/dev/null
VIEWER_PID=""
python3 -c "import json,sys; json.load(open(sys.argv[1]))" "$FILE" || fail "the reflector file is not valid JSON after the kill"
note "killed during save: $FILE is intact ($(count "$FILE") reflectors)"

# Headless, the reflector is where it was moved to: with debug=reflectors (reflector pixels tinted),
# the captures with and without it differ around the drag's end point, and only there. And PPR
# reflects there: the normal captures differ in the same place.
shoot() {  # shoot FILE NAME [--set ...]: a 320x180 capture of the puddles camera → $WORK/NAME/final.png
    local file=$1 name=$2; shift 2
    "$PPR" capture --camera puddles --size 320x180 --frames 1 --reflectors "$file" --validation --out "$WORK/$name" "$@" >"$WORK/$name.log" 2>&1 ||
        fail "capture with $file failed: $(tail -1 "$WORK/$name.log")"
}
differ() { compare -metric AE "$1" "$2" null: 2>&1 | awk '{print int($1)}'; }
box() { convert "$1" -crop "$BOX" +repage "$2"; }
BOX=120x70+172+74  # around the drag's end (464, 218) at 640x360 → (232, 109) at 320x180
shoot "$SCENE_DIR/default.reflectors.json" ids-before --set debug=reflectors
shoot "$WORK/moved.reflectors.json" ids-after --set debug=reflectors
shoot "$SCENE_DIR/default.reflectors.json" before
shoot "$WORK/moved.reflectors.json" after
for kind in ids ""; do
    a="$WORK/${kind:+$kind-}before/final.png" b="$WORK/${kind:+$kind-}after/final.png"
    total=$(differ "$a" "$b")
    box "$a" "$WORK/box-a.png"; box "$b" "$WORK/box-b.png"
    inside=$(differ "$WORK/box-a.png" "$WORK/box-b.png")
    note "${kind:-final}: $inside of $total differing pixels lie around the moved reflector"
    [ "$inside" -gt 30 ] && [ $((inside * 10)) -ge $((total * 9)) ] || fail "the authored reflector does not show at its new place in a headless capture"
done
grep -q '^validation error' "$WORK/viewer.log" && fail "validation errors in the log"
note "PASS"
exit 0
