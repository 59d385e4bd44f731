# Shared by the UI tests: a private Xvfb display, the viewer's window, screenshots. A test sets TEST
# (its name in messages) and sources this with its own arguments, PPR_BINARY WORK_DIR, which become
# PPR and WORK; STEP_TIMEOUT is PPR_UI_TIMEOUT (seconds to wait for each step, default 90).
PPR=${1:?usage: $(basename "$0") PPR_BINARY WORK_DIR}
WORK=${2:?usage: $(basename "$0") PPR_BINARY WORK_DIR}
STEP_TIMEOUT=${PPR_UI_TIMEOUT:-90}

fail() { echo "$TEST: FAIL: $*" >&2; [ -f "$WORK/viewer.log" ] && sed 's/^/  viewer: /' "$WORK/viewer.log" >&2; exit 1; }
note() { echo "$TEST: $*"; }

for tool in Xvfb xdotool xwd convert compare; do
    command -v "$tool" >/dev/null 2>&1 || { echo "$TEST: FAIL: '$tool' not installed (scripts/install-deps.sh installs it)"; exit 1; }
done
[ -x "$PPR" ] || fail "no executable at $PPR"

rm -rf "$WORK"
mkdir -p "$WORK/out"

XVFB_PID=""
VIEWER_PID=""
cleanup() {
    if [ -n "$VIEWER_PID" ] && kill -0 "$VIEWER_PID" 2>/dev/null; then
        kill "$VIEWER_PID" 2>/dev/null
        sleep 1
        kill -9 "$VIEWER_PID" 2>/dev/null
    fi
    if [ -n "$XVFB_PID" ]; then
        kill "$XVFB_PID" 2>/dev/null
        wait "$XVFB_PID" 2>/dev/null
    fi
}
trap cleanup EXIT

# A private X server on the first free display number from 90 up (a number another test grabbed
# in the meantime makes Xvfb exit at once: then try the next one).
DISP=""
for n in $(seq 90 160); do
    [ -e "/tmp/.X$n-lock" ] || [ -e "/tmp/.X11-unix/X$n" ] && continue
    Xvfb ":$n" -screen 0 1280x800x24 -nolisten tcp >"$WORK/xvfb.log" 2>&1 &
    XVFB_PID=$!
    up=""
    for _ in $(seq 1 200); do  # ready = it answers a client, not merely has its socket
        kill -0 "$XVFB_PID" 2>/dev/null || break
        DISPLAY=":$n" xdotool getdisplaygeometry >/dev/null 2>&1 && { up=1; break; }
        sleep 0.1
    done
    if [ -n "$up" ]; then DISP=$n; break; fi
    kill "$XVFB_PID" 2>/dev/null
    wait "$XVFB_PID" 2>/dev/null
    XVFB_PID=""
done
[ -n "$DISP" ] || fail "could not start Xvfb on any display :90..:160 ($(tail -1 "$WORK/xvfb.log" 2>/dev/null))"
export DISPLAY=":$DISP"
unset WAYLAND_DISPLAY
# Xvfb has no GPU driver behind it: lavapipe can present to it, a discrete GPU's driver usually cannot.
export PPR_DEVICE=${PPR_DEVICE:-cpu}
note "Xvfb on $DISPLAY"

alive() { kill -0 "$VIEWER_PID" 2>/dev/null; }

# wait_for DESCRIPTION COMMAND...: polls COMMAND every half second until it succeeds, for at most
# STEP_TIMEOUT seconds (the checks' own time included), while the viewer lives. A check may leave its
# last figure in `measured` for the failure message.
measured=""
wait_for() {
    local what=$1 deadline=$((SECONDS + STEP_TIMEOUT)); shift
    while [ "$SECONDS" -lt "$deadline" ]; do
        alive || fail "viewer exited while waiting for $what"
        "$@" && return 0
        sleep 0.5
    done
    fail "timed out waiting for $what${measured:+ (last measured: $measured)}"
}

# find_window: waits for the viewer's window → WID, WX WY WW WH.
find_window() {
    WID=""
    for _ in $(seq 1 $((STEP_TIMEOUT * 2))); do
        alive || fail "viewer exited before its window appeared"
        WID=$(xdotool search --onlyvisible --name '^ppr' 2>/dev/null | head -1)
        [ -n "$WID" ] && break
        sleep 0.5
    done
    [ -n "$WID" ] || fail "no window named 'ppr…' after ${STEP_TIMEOUT}s"
    eval "$(xdotool getwindowgeometry --shell "$WID")"
    WX=$X WY=$Y WW=$WIDTH WH=$HEIGHT
}

# The scene region right of the ImGui panel (the panel's numbers change every frame; a still scene
# does not): SX SY SW SH, from the window's geometry.
scene_region() { SX=$((WX + 400)) SY=$WY SW=$((WW - 400)) SH=$WH; }
# shot NAME → $WORK/NAME.png (whole window) and $WORK/NAME-scene.png (scene_region).
shot() {
    xwd -root -silent | convert xwd:- -crop "${WW}x${WH}+${WX}+${WY}" +repage "png:$WORK/$1.png" || fail "screenshot failed"
    convert "$WORK/$1.png" -crop "${SW}x${SH}+$((SX - WX))+$((SY - WY))" +repage "png:$WORK/$1-scene.png"
}
# Pixels that differ between two images by more than a 2 % fuzz.
differing() { compare -metric AE -fuzz 2% "$1" "$2" null: 2>&1 | awk '{print int($1)}'; }

# close_viewer: SIGTERM closes the window like the close button; exit code 0 = no validation errors,
# and none in the log.
close_viewer() {
    kill -TERM "$VIEWER_PID"
    local rc="" pid=$VIEWER_PID
    for _ in $(seq 1 $((STEP_TIMEOUT * 2))); do
        if ! alive; then wait "$VIEWER_PID"; rc=$?; break; fi
        sleep 0.5
    done
    VIEWER_PID=""
    [ -n "$rc" ] || { kill -9 "$pid" 2>/dev/null; fail "viewer did not exit within ${STEP_TIMEOUT}s of SIGTERM"; }
    [ "$rc" -eq 0 ] || fail "viewer exit code $rc (1 = validation errors)"
    grep -q '^validation error' "$WORK/viewer.log" && fail "validation errors in the log"
    return 0
}
