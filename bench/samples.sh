#!/usr/bin/env bash
# What multisampling costs: each scene or model (default: ../shared/bench/*.json) drawn by
# `illum bench` at 1, 4 and 8 samples per pixel, the three alternated R rounds of F frames; the
# table shows the median frame times, their ratios to one sample, and the peak memory at 1 and 8.
#   bench/samples.sh [--threads N] [--rounds R] [--frames F] [SCENE|MODEL ...]
set -euo pipefail
cd "$(dirname "$0")/.."
. bench/lib.sh
parse_bench_options "$@"
default_to_bench_scenes
illum=build/apps/illum/illum
[ -x "$illum" ] || { echo "samples: $illum is missing: build first (scripts/dev.sh run)" >&2; exit 2; }
echo "# $(lscpu | sed -n 's/^Model name: *//p'), $(nproc) cores; --threads $threads; median of $rounds alternated rounds of $frames frames"
printf '| %-28s | %8s | %8s | %8s | %6s | %6s | %9s | %9s |\n' input "1 ms" "4 ms" "8 ms" "4×/1×" "8×/1×" "MiB at 1" "MiB at 8"
printf '|%s|%s|%s|%s|%s|%s|%s|%s|\n' ------------------------------ ---------- ---------- ---------- -------- -------- ----------- -----------
for input in "${inputs[@]}"; do
  declare -A ms=() mib=()
  for ((r = 0; r < rounds; ++r)); do
    for s in 1 4 8; do
      out=$("$illum" bench "$input" --samples "$s" --frames "$frames" --threads "$threads" --environment none)
      ms[$s]+=" $(field ms_per_frame <<<"$out")"
      mib[$s]=$(field peak_mib <<<"$out")
    done
  done
  a=$(median ${ms[1]}) b=$(median ${ms[4]}) c=$(median ${ms[8]})
  printf '| %-28s | %8.2f | %8.2f | %8.2f | %6.2f | %6.2f | %9s | %9s |\n' "$(basename "$input")" "$a" "$b" "$c" \
    "$(awk -v x="$b" -v y="$a" 'BEGIN { print x / y }')" "$(awk -v x="$c" -v y="$a" 'BEGIN { print x / y }')" "${mib[1]}" "${mib[8]}"
  unset ms mib
done
