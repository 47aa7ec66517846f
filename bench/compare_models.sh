#!/usr/bin/env bash
# illum against Mesa's llvmpipe on model previews, side by side in one run:
#   bench/compare_models.sh [--threads N] [--rounds R] [--frames F] [MODEL ...]
# Each model (default: the set below, from Debian's assimp-testmodels) is previewed at 1000×600 as
# `illum bench MODEL` draws it (framed, the light rig, the file's materials and textures, sRGB) at
# 1, 4 and 8 samples per pixel, and by llvmpipe drawing the same scene (illum's own scene-building
# code) with an equivalent per-pixel GLSL program at 1 and 4 samples (a multisampled framebuffer
# object: 4 is the most llvmpipe takes), with LP_NUM_THREADS equal to illum's --threads; the two
# alternate, R rounds of F frames each, and the table shows medians: milliseconds per frame, the
# ratios illum/llvmpipe (below 1: illum is faster), illum's cost of 4 and 8 samples against 1, and
# illum's 1-sample frame with --geometry-only (same triangles, no materials or textures).
# Build first: scripts/dev.sh run (or cmake --build build).
set -euo pipefail
cd "$(dirname "$0")/.."
. bench/lib.sh
parse_bench_options "$@"
models=("${inputs[@]}")
M=/usr/share/assimp/models
if [ ${#models[@]} -eq 0 ]; then
  models=(
    "$M/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb"        # textured glTF
    "$M/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb" # PBR glTF, 121k triangles
    "$M/Collada/duck.dae"                                      # textured Collada
    "$M/OBJ/spider.obj"                                        # OBJ + MTL, textured
    "$M/STL/Spider_binary.stl"                                 # STL
    "$M/PLY/Wuson.ply"                                         # PLY
    "$M/Collada/kwxport_test_vcolors.dae"                      # vertex colours
    "$M/glTF2/ClearCoat-glTF/ClearCoatTest.gltf"               # translucent labels, normal maps
  )
fi
illum=build/apps/illum/illum
peer=build/bench/illum_llvmpipe_bench
for b in "$illum" "$peer"; do
  [ -x "$b" ] || { echo "compare_models: $b is missing: build first (scripts/dev.sh run)" >&2; exit 2; }
done

ratio() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.3f", a / b }'; }

echo "# $(lscpu | sed -n 's/^Model name: *//p'), $(nproc) cores; illum --threads $threads, LP_NUM_THREADS=$threads;" \
     "1000×600, median of $rounds alternated rounds of $frames frames; ms per frame"
printf '| %-24s | %9s | %8s | %8s | %8s | %8s | %8s | %8s | %8s | %7s | %7s | %9s | %9s |\n' \
  model triangles "illum 1" "llvm 1" "ratio 1" "illum 4" "llvm 4" "ratio 4" "illum 8" "4×/1×" "8×/1×" "geometry" "1×/geom"
printf '|%s|%s|%s|%s|%s|%s|%s|%s|%s|%s|%s|%s|%s|\n' -------------------------- ----------- ---------- ---------- \
  ---------- ---------- ---------- ---------- ---------- --------- --------- ----------- -----------
for model in "${models[@]}"; do
  declare -A ours=() theirs=()
  geometry=()
  triangles=
  for ((r = 0; r < rounds; ++r)); do
    for s in 1 4 8; do
      out=$("$illum" bench "$model" --samples "$s" --frames "$frames" --threads "$threads" --environment none)
      ours[$s]+=" $(field ms_per_frame <<<"$out")"
      triangles=$(field triangles <<<"$out")
      if [ "$s" != 8 ]; then
        theirs[$s]+=" $(LP_NUM_THREADS=$threads "$peer" "$model" --samples "$s" --frames "$frames" | field ms_per_frame)"
      fi
    done
    geometry+=("$("$illum" bench "$model" --samples 1 --geometry-only --frames "$frames" --threads "$threads" --environment none | field ms_per_frame)")
  done
  i1=$(median ${ours[1]}) i4=$(median ${ours[4]}) i8=$(median ${ours[8]})
  l1=$(median ${theirs[1]}) l4=$(median ${theirs[4]}) g=$(median "${geometry[@]}")
  printf '| %-24s | %9s | %8.2f | %8.2f | %8s | %8.2f | %8.2f | %8s | %8.2f | %7s | %7s | %9.2f | %9s |\n' \
    "$(basename "$model")" "$triangles" "$i1" "$l1" "$(ratio "$i1" "$l1")" "$i4" "$l4" "$(ratio "$i4" "$l4")" "$i8" \
    "$(ratio "$i4" "$i1")" "$(ratio "$i8" "$i1")" "$g" "$(ratio "$i1" "$g")"
  unset ours theirs
done
