#!/usr/bin/env bash
# The path tracer against an independent one: Blender's Cycles (Debian's blender) renders the same
# Cornell box, side by side, and the two linear pictures are compared:
#   bench/compare_cycles.sh [--samples N] [--threads N] [SCENE.json]
# Prints both times, the mean relative error and the RMS error of illum against Cycles, and writes
# the README's pictures docs/images/cornell_cycles.png (Cycles) and docs/images/cornell_difference.png
# (the 8×8-pixel blocks' |illum − Cycles| × 16, one pixel a block) at their 256 samples only; other
# sample counts write them beside the run's output instead (./cornell_cycles.png, ./cornell_difference.png).
set -euo pipefail
caller=$PWD
cd "$(dirname "$0")/.."
illum=build/apps/illum/illum
samples=256 threads=2 scene=examples/cornell_box.json
while [ $# -gt 0 ]; do
  case $1 in
    --samples) samples=$2; shift 2 ;;
    --threads) threads=$2; shift 2 ;;
    *) scene=$(cd "$caller" && realpath "$1"); shift ;;
  esac
done
pictures=$caller
[ "$samples" = 256 ] && pictures=docs/images
command -v blender >/dev/null || { echo "compare_cycles: needs Blender (apt-get install blender)" >&2; exit 2; }
[ -x "$illum" ] || { echo "compare_cycles: build illum first (scripts/dev.sh run)" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
now() { date +%s.%N; }
t0=$(now)
"$illum" render "$scene" --samples "$samples" --threads "$threads" -o "$work/illum.exr" -q
t1=$(now)
blender -b --factory-startup -P bench/cycles/render_scene.py -- "$scene" "$work/cycles.exr" "$samples" "$threads" \
  > "$work/blender.log" 2>&1 || { tail -n 20 "$work/blender.log"; exit 1; }
t2=$(now)
blender -b --factory-startup -P bench/cycles/compare.py -- "$work/cycles.exr" "$work/illum.exr" \
  "$pictures/cornell_difference.png" 2>/dev/null | grep illum-compare | sed 's/^illum-compare: //'
# Cycles' picture as illum writes its own: linear values, no view transform or display encoding.
blender -b --factory-startup --python-expr "import bpy; s = bpy.context.scene; \
s.view_settings.view_transform = 'Standard'; s.display_settings.display_device = 'None'; \
s.render.image_settings.file_format = 'PNG'; \
bpy.data.images.load('$work/cycles.exr').save_render('$(realpath "$pictures")/cornell_cycles.png', scene=s)" >/dev/null 2>&1
awk -v a="$t0" -v b="$t1" -v c="$t2" -v s="$samples" -v n="$threads" \
  'BEGIN {printf "%d samples per pixel, %d threads: illum %.1f s, Cycles %.1f s (whole process)\n", s, n, b - a, c - b}'
