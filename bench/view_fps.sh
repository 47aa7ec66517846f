#!/usr/bin/env bash
# Frames per second of `illum view` while a drag orbits the view, as issue 32 measures it: the
# viewer on a virtual X server (Xvfb), a left drag across the picture for a few seconds (xdotool),
# and the viewer's own count (-v): frames shown, the rate while they came one after another (the
# wait before the drag not counted), the mean time to draw one and to present it.
#
#   bench/view_fps.sh [--seconds S] [VIEW ARGS...]      e.g.
#   bench/view_fps.sh --resolution 1280,720 --samples 4
#   bench/view_fps.sh /usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb --resolution 1280,720 --samples 4
set -euo pipefail
cd "$(dirname "$0")/.."
illum=${ILLUM:-build/apps/illum/illum}
seconds=5
if [ "${1:-}" = "--seconds" ]; then seconds=$2; shift 2; fi
work=$(mktemp -d)
trap 'kill $xvfb 2>/dev/null || true; rm -rf "$work"' EXIT
exec 3>"$work/display"
Xvfb -displayfd 3 -screen 0 2560x1440x24 -nolisten tcp &
xvfb=$!
for _ in $(seq 50); do [ -s "$work/display" ] && break; sleep 0.1; done
export DISPLAY=":$(cat "$work/display")"
"$illum" view -v "$@" 2>"$work/err" &
viewer=$!
window=""
for _ in $(seq 300); do
  window=$(xdotool search --onlyvisible --name '^illum view' 2>/dev/null | head -1 || true)
  [ -n "$window" ] && break
  sleep 0.1
done
[ -n "$window" ] || { echo "no window: $(cat "$work/err")" >&2; exit 1; }
sleep 2  # the first frame
# A drag back and forth across the middle of the picture, a step every ${STEP_MS:-5} ms asked (a
# mouse reports 125 times a second or more; xdotool's own time comes on top of the sleep).
step_ms=${STEP_MS:-5}
steps=$((seconds * 1000 / step_ms))
args=(mousemove --window "$window" 200 300 mousedown 1)
for i in $(seq "$steps"); do
  x=$((200 + (i % 400 < 200 ? i % 200 : 200 - i % 200) * 2))
  args+=(sleep "0.$(printf %03d "$step_ms")" mousemove --window "$window" "$x" 300)
done
xdotool "${args[@]}" mouseup 1
sleep 1
# (The viewer may be gone before the key is let go: BadWindow then is not a failure.)
xdotool key --window "$window" Escape 2>/dev/null || true
wait $viewer
grep "${GREP:-frames shown}" "$work/err" | sed 's/^illum view: //'
