#!/usr/bin/env bash
# Three glTF models under one outdoor sky (bench/environment/sky_hdr.py), as illum's rasterizer
# lights them by image-based lighting, as its path tracer lights them, and as f3d's --hdri does
# (f3d through llvmpipe under Xvfb): a sheet of 3 × 3 pictures, the README's illustration
# docs/images/environment_models.png. The rig is off (--light-intensity 0): the sky alone lights.
# Usage: bench/compare_environment.sh [OUT.png]   (needs f3d, xvfb-run and ImageMagick)
set -euo pipefail
out=$(realpath -m "${1:-environment_models.png}")
cd "$(dirname "$0")/.."
here=bench
illum=build/apps/illum/illum
for tool in f3d xvfb-run convert; do
  command -v "$tool" >/dev/null || { echo "compare_environment: needs f3d, xvfb-run and ImageMagick (apt-get install f3d xvfb imagemagick)" >&2; exit 2; }
done
models=/usr/share/assimp/models/glTF2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python3 "$here/environment/sky_hdr.py" "$work/sky.hdr" 512
rows=()
for model in "$models/2CylinderEngine-glTF-Binary/2CylinderEngine.glb" "$models/BoxTextured-glTF/BoxTextured.gltf" \
             "$models/ClearCoat-glTF/ClearCoatTest.gltf"; do
  name=$(basename "$model")
  "$illum" render "$model" --environment "$work/sky.hdr" --light-intensity 0 --resolution 360,270 -o "$work/$name.raster.png" >/dev/null
  "$illum" render "$model" --environment "$work/sky.hdr" --light-intensity 0 --renderer path --samples 64 \
           --resolution 360,270 -o "$work/$name.path.png" >/dev/null
  xvfb-run -a f3d --hdri "$work/sky.hdr" --resolution 360,270 --output "$work/$name.f3d.png" "$model" >/dev/null 2>&1
  convert "$work/$name.raster.png" "$work/$name.path.png" "$work/$name.f3d.png" +append "$work/$name.row.png"
  rows+=("$work/$name.row.png")
done
convert "${rows[@]}" -append "$out"
echo "$out: rows 2CylinderEngine, BoxTextured, ClearCoatTest; columns illum raster, illum path, f3d --hdri"
