#!/usr/bin/env bash
# The path tracer against an independent one: Blender's Cycles (Debian's blender) renders the same
# scene, side by side, and the two linear pictures are compared:
#   bench/compare_cycles.sh [--samples N] [--threads N] [SCENE.json | builtin]
# SCENE.json defaults to the Cornell box. `builtin` is the built-in scene path traced, without its
# labels (its GL lights, Blinn-Phong materials and mirrors as bench/cycles/render_scene.py builds
# them; its shapes, the teapot among them, as illum tessellates them: bench/scene_meshes.cpp).
# Prints both times, the mean relative error and the RMS error of illum against Cycles, and writes
# the README's pictures docs/images/NAME_cycles.png (Cycles) and docs/images/NAME_difference.png
# (the 8×8-pixel blocks' |illum − Cycles| × 16, one pixel a block), and for `builtin`
# docs/images/builtin_path_illum.png (illum's, as Cycles' is written: linear values, no display
# encoding), NAME the scene's (cornell_box: cornell), at their 256 samples only; other sample
# counts write them beside the run's output instead (./NAME_cycles.png, ...).
set -euo pipefail
caller=$PWD
cd "$(dirname "$0")/.."
illum=build/apps/illum/illum
meshes_tool=build/bench/illum_scene_meshes
samples=256 threads=2 scene=examples/cornell_box.json
while [ $# -gt 0 ]; do
  case $1 in
    --samples) samples=$2; shift 2 ;;
    --threads) threads=$2; shift 2 ;;
    builtin) scene=builtin; shift ;;
    *) scene=$(cd "$caller" && realpath "$1"); shift ;;
  esac
done
pictures=$caller
[ "$samples" = 256 ] && pictures=docs/images
command -v blender >/dev/null || { echo "compare_cycles: needs Blender (apt-get install blender)" >&2; exit 2; }
[ -x "$illum" ] || { echo "compare_cycles: build illum first (scripts/dev.sh run)" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
meshes=()
if [ "$scene" = builtin ]; then
  [ -x "$meshes_tool" ] || { echo "compare_cycles: build $meshes_tool first (cmake --build build)" >&2; exit 2; }
  name=builtin
  # The built-in scene as the path tracer draws it, saved as a scene file, its labels left out
  # (Cycles draws no text).
  "$illum" render --renderer path --resolution 480,270 --save-scene "$work/builtin_labels.json" -o "$work/unused.png" -q
  python3 -c "import json, sys; s = json.load(open(sys.argv[1])); s.pop('labels', None); json.dump(s, open(sys.argv[2], 'w'))" \
    "$work/builtin_labels.json" "$work/builtin.json"
  scene=$work/builtin.json
  "$meshes_tool" "$scene" "$work/meshes.json"
  meshes=("$work/meshes.json")
else
  name=$(basename "$scene" .json)
  [ "$name" = cornell_box ] && name=cornell
fi
now() { date +%s.%N; }
t0=$(now)
"$illum" render "$scene" --samples "$samples" --threads "$threads" -o "$work/illum.exr" -q
t1=$(now)
blender -b --factory-startup -P bench/cycles/render_scene.py -- "$scene" "$work/cycles.exr" "$samples" "$threads" \
  "${meshes[@]}" > "$work/blender.log" 2>&1 || { tail -n 20 "$work/blender.log"; exit 1; }
t2=$(now)
blender -b --factory-startup -P bench/cycles/compare.py -- "$work/cycles.exr" "$work/illum.exr" \
  "$pictures/${name}_difference.png" 2>/dev/null | grep illum-compare | sed 's/^illum-compare: //'
# The pictures as illum writes its own linear ones: no view transform or display encoding.
as_png() {
  blender -b --factory-startup --python-expr "import bpy; s = bpy.context.scene; \
s.view_settings.view_transform = 'Standard'; s.display_settings.display_device = 'None'; \
s.render.dither_intensity = 0; s.render.image_settings.file_format = 'PNG'; \
bpy.data.images.load('$1').save_render('$(realpath "$pictures")/$2', scene=s)" >/dev/null 2>&1
}
as_png "$work/cycles.exr" "${name}_cycles.png"
[ "$name" = builtin ] && as_png "$work/illum.exr" "builtin_path_illum.png"
awk -v a="$t0" -v b="$t1" -v c="$t2" -v s="$samples" -v n="$threads" \
  'BEGIN {printf "%d samples per pixel, %d threads: illum %.1f s, Cycles %.1f s (whole process)\n", s, n, b - a, c - b}'
