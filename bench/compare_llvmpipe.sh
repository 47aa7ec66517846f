#!/usr/bin/env bash
# illum against Mesa's llvmpipe on the same CPU, side by side in one run:
#   bench/compare_llvmpipe.sh [--threads N] [--rounds R] [--frames F] [SCENE.json ...]
# Each scene (default: ../shared/bench/*.json) is rendered by `illum bench` and by llvmpipe
# (bench/llvmpipe_bench.cpp: fixed function for flat/Gouraud Blinn-Phong, GLSL otherwise, with
# LP_NUM_THREADS equal to illum's --threads), the two alternated R times; each prints the median
# frame time of F frames, and the table shows the median over the rounds and the ratio
# illum / llvmpipe (below 1: illum is faster). Build first: scripts/dev.sh run (or cmake --build build).
set -euo pipefail
cd "$(dirname "$0")/.."
threads=$(nproc 2>/dev/null || echo 2)
rounds=3
frames=10
scenes=()
while [ $# -gt 0 ]; do
  case "$1" in
    --threads) threads=$2; shift 2 ;;
    --rounds) rounds=$2; shift 2 ;;
    --frames) frames=$2; shift 2 ;;
    *) scenes+=("$1"); shift ;;
  esac
done
if [ ${#scenes[@]} -eq 0 ]; then
  for s in ../shared/bench/*.json; do scenes+=("$s"); done
fi
illum=build/apps/illum/illum
peer=build/bench/illum_llvmpipe_bench
for b in "$illum" "$peer"; do
  [ -x "$b" ] || { echo "compare_llvmpipe: $b is missing: build first (scripts/dev.sh run)" >&2; exit 2; }
done

field() { sed -n "s/.*\"$1\": \([0-9.]*\).*/\1/p"; }
median() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print (NR%2 ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2)}'; }

echo "# $(lscpu | sed -n 's/^Model name: *//p'), $(nproc) cores; illum --threads $threads, LP_NUM_THREADS=$threads;" \
     "median of $rounds alternated rounds of $frames frames"
printf '| %-34s | %12s | %12s | %14s |\n' scene "illum ms" "llvmpipe ms" "illum/llvmpipe"
printf '|%s|%s|%s|%s|\n' "------------------------------------" "--------------" "--------------" "----------------"
for scene in "${scenes[@]}"; do
  ours=() theirs=()
  for ((r = 0; r < rounds; ++r)); do
    ours+=("$("$illum" bench "$scene" --frames "$frames" --threads "$threads" | field ms_per_frame)")
    theirs+=("$(LP_NUM_THREADS=$threads "$peer" "$scene" --frames "$frames" | field ms_per_frame)")
  done
  a=$(median "${ours[@]}") b=$(median "${theirs[@]}")
  printf '| %-34s | %12.1f | %12.1f | %14.2f |\n' "$(basename "$scene" .json)" "$a" "$b" "$(awk -v a="$a" -v b="$b" 'BEGIN { print a / b }')"
done
