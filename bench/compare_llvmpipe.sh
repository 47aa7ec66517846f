#!/usr/bin/env bash
# illum against Mesa's llvmpipe on the same CPU, side by side in one run:
#   bench/compare_llvmpipe.sh [--threads N] [--rounds R] [--frames F] [--layouts] [SCENE.json ...]
# Each scene (default: ../shared/bench/*.json) is rendered by `illum bench` and by llvmpipe
# (bench/llvmpipe_bench.cpp: fixed function for flat/Gouraud Blinn-Phong, GLSL otherwise, with
# LP_NUM_THREADS equal to illum's --threads), the two alternated R times; each prints the median
# frame time of F frames, and the table shows the median over the rounds and the ratio
# illum / llvmpipe (below 1: illum is faster). With --layouts every scene is also run at 720p and
# at 4K, and as four times as many spheres of half the radius and a quarter of the triangles each
# (the same triangle count, smaller objects; written with python3). Build first: scripts/dev.sh
# run (or cmake --build build).
set -euo pipefail
cd "$(dirname "$0")/.."
. bench/lib.sh
parse_bench_options "$@"
default_to_bench_scenes
scenes=("${inputs[@]}")
illum=build/apps/illum/illum
peer=build/bench/illum_llvmpipe_bench
for b in "$illum" "$peer"; do
  [ -x "$b" ] || { echo "compare_llvmpipe: $b is missing: build first (scripts/dev.sh run)" >&2; exit 2; }
done


echo "# $(lscpu | sed -n 's/^Model name: *//p'), $(nproc) cores; illum --threads $threads, LP_NUM_THREADS=$threads;" \
     "median of $rounds alternated rounds of $frames frames"
printf '| %-34s | %12s | %12s | %14s |\n' scene "illum ms" "llvmpipe ms" "illum/llvmpipe"
printf '|%s|%s|%s|%s|\n' "------------------------------------" "--------------" "--------------" "----------------"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# One row: label, scene, then extra arguments for both renderers (a resolution).
row() {
  local label=$1 scene=$2
  shift 2
  local ours=() theirs=()
  for ((r = 0; r < rounds; ++r)); do
    ours+=("$("$illum" bench "$scene" "$@" --frames "$frames" --threads "$threads" | field ms_per_frame)")
    theirs+=("$(LP_NUM_THREADS=$threads "$peer" "$scene" "$@" --frames "$frames" | field ms_per_frame)")
  done
  local a b
  a=$(median "${ours[@]}") b=$(median "${theirs[@]}")
  printf '| %-34s | %12.2f | %12.2f | %14.3f |\n' "$label" "$a" "$b" "$(awk -v a="$a" -v b="$b" 'BEGIN { print a / b }')"
}

# Four spheres of half the radius, a quarter of the triangles each, in place of every sphere.
smaller_objects() {
  python3 - "$1" "$2" <<'PY'
import json, sys
scene = json.load(open(sys.argv[1]))
objects = []
for o in scene["objects"]:
    mesh = o["mesh"]
    for dx, dy in ((-1, -1), (1, -1), (-1, 1), (1, 1)):
        small = json.loads(json.dumps(o))
        small["mesh"]["radius"] = mesh["radius"] / 2
        small["mesh"]["slices"] = max(3, mesh["slices"] // 2)
        small["mesh"]["stacks"] = max(2, mesh["stacks"] // 2)
        t = small.get("transform", [{"translate": [0, 0, 0]}])[0]["translate"]
        r = mesh["radius"] / 2
        small["transform"] = [{"translate": [t[0] + dx * r, t[1] + dy * r, t[2]]}]
        objects.append(small)
scene["objects"] = objects
json.dump(scene, open(sys.argv[2], "w"))
PY
}

for scene in "${scenes[@]}"; do
  name=$(basename "$scene" .json)
  row "$name" "$scene"
  if [ "$layouts" = 1 ]; then
    row "$name @720p" "$scene" --width 1280 --height 720
    row "$name @4K" "$scene" --width 3840 --height 2160
    smaller_objects "$scene" "$work/$name.small.json"
    row "$name ×4 smaller" "$work/$name.small.json"
  fi
done
