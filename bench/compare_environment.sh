#!/usr/bin/env bash
# Three glTF models under one outdoor sky (bench/environment/sky_hdr.py), as illum's rasterizer
# lights them by image-based lighting, as its path tracer lights them, as Blender's Cycles path
# traces them (Blender's own glTF importer, illum's camera and display: bench/cycles/render_model.py)
# and as f3d's --hdri does (f3d through llvmpipe under Xvfb): a sheet of 3 × 4 pictures, the
# README's illustration docs/images/environment_models.png. The rig is off (--light-intensity 0):
# the sky alone lights. Prints each renderer's time per model.
# Usage: bench/compare_environment.sh [OUT.png] [CYCLES_SAMPLES]
#   (needs Blender, f3d, xvfb-run and ImageMagick)
set -euo pipefail
out=$(realpath -m "${1:-environment_models.png}")
cd "$(dirname "$0")/.."
here=bench
illum=build/apps/illum/illum
cycles_samples=${2:-256}
for tool in blender f3d xvfb-run convert; do
  command -v "$tool" >/dev/null || { echo "compare_environment: needs Blender, f3d, xvfb-run and ImageMagick (apt-get install blender f3d xvfb imagemagick)" >&2; exit 2; }
done
models=/usr/share/assimp/models/glTF2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python3 "$here/environment/sky_hdr.py" "$work/sky.hdr" 512
now() { date +%s.%N; }
rows=()
for model in "$models/2CylinderEngine-glTF-Binary/2CylinderEngine.glb" "$models/BoxTextured-glTF/BoxTextured.gltf" \
             "$models/ClearCoat-glTF/ClearCoatTest.gltf"; do
  name=$(basename "$model")
  t0=$(now)
  "$illum" render "$model" --environment "$work/sky.hdr" --light-intensity 0 --resolution 360,270 -o "$work/$name.raster.png" >/dev/null
  t1=$(now)
  "$illum" render "$model" --environment "$work/sky.hdr" --light-intensity 0 --renderer path --samples 64 \
           --resolution 360,270 -o "$work/$name.path.png" --save-scene "$work/$name.path.json" >/dev/null
  t2=$(now)
  blender -b --factory-startup -P "$here/cycles/render_model.py" -- "$work/$name.path.json" "$model" "$work/sky.hdr" \
          "$work/$name.cycles.png" "$cycles_samples" 2 > "$work/blender.log" 2>&1 || { tail -n 20 "$work/blender.log"; exit 1; }
  t3=$(now)
  xvfb-run -a f3d --hdri "$work/sky.hdr" --resolution 360,270 --output "$work/$name.f3d.png" "$model" >/dev/null 2>&1
  t4=$(now)
  awk -v n="$name" -v a="$t0" -v b="$t1" -v c="$t2" -v d="$t3" -v e="$t4" -v s="$cycles_samples" 'BEGIN {
    printf "%s: illum raster %.2f s, illum path (64 samples, denoised) %.2f s, Cycles (%d samples) %.2f s, f3d %.2f s\n",
           n, b - a, c - b, s, d - c, e - d }'
  convert "$work/$name.raster.png" "$work/$name.path.png" "$work/$name.cycles.png" "$work/$name.f3d.png" +append "$work/$name.row.png"
  rows+=("$work/$name.row.png")
done
convert "${rows[@]}" -append "$out"
echo "$out: rows 2CylinderEngine, BoxTextured, ClearCoatTest; columns illum raster, illum path, Cycles, f3d --hdri"
