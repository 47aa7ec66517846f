#!/usr/bin/env bash
# How illum's and llvmpipe's frame times grow with triangles, resolution and threads, as a chart:
#   bench/scaling.sh [OUT.png]      (default docs/images/scaling.png; needs gnuplot: gnuplot-nox)
# The scene is ../shared/bench/spheres_48k_8lights_phong.json (twelve spheres, eight lights,
# per-pixel shading) with its sphere tessellation scaled from 10k to 3.8M triangles at 1080p;
# then that scene at 48k triangles from 720p to 4K; then 1 and 2 threads. Each point is the median
# of 5 frames, illum and llvmpipe alternated. Build first: scripts/dev.sh run.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-docs/images/scaling.png}
base=../shared/bench/spheres_48k_8lights_phong.json
illum=build/apps/illum/illum
peer=build/bench/illum_llvmpipe_bench
threads=$(nproc 2>/dev/null || echo 2)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
field() { sed -n "s/.*\"$1\": \([0-9.]*\).*/\1/p"; }
ours() { "$illum" bench "$@" --frames 5 | field ms_per_frame; }
theirs() { local t=$1; shift; LP_NUM_THREADS=$t "$peer" "$@" --frames 5 | field ms_per_frame; }

echo "# triangles illum_ms llvmpipe_ms" > "$work/triangles.dat"
for s in 20 40 80 160 320 400; do
  scene="$work/spheres_$s.json"
  sed -e "s/\"slices\": 64/\"slices\": $s/" -e "s/\"stacks\": 32/\"stacks\": $((s + 1))/" "$base" > "$scene"
  tris=$((12 * 2 * s * s))
  echo "$tris $(ours "$scene" --threads "$threads") $(theirs "$threads" "$scene")" | tee -a "$work/triangles.dat"
done
echo "# megapixels illum_ms llvmpipe_ms" > "$work/resolution.dat"
for wh in 1280x720 1920x1080 2560x1440 3840x2160; do
  w=${wh%x*} h=${wh#*x}
  echo "$(awk -v w="$w" -v h="$h" 'BEGIN { print w * h / 1e6 }') $(ours "$base" --width "$w" --height "$h" --threads "$threads") $(theirs "$threads" "$base" --width "$w" --height "$h")" | tee -a "$work/resolution.dat"
done
echo "# threads illum_ms llvmpipe_ms" > "$work/threads.dat"
for t in 1 2; do
  echo "$t $(ours "$base" --threads "$t") $(theirs "$t" "$base")" | tee -a "$work/threads.dat"
done

gnuplot <<GNUPLOT
set terminal pngcairo size 1500,460 font "DejaVu Sans,11"
set output "$out"
set multiplot layout 1,3 title "illum and llvmpipe, frame time (ms, median of 5) — $(lscpu | sed -n 's/^Model name: *//p'), $(nproc) cores"
set key top left
set grid
set style data linespoints
set xlabel "triangles (1080p, $threads threads)"; set ylabel "ms"; set logscale xy
plot "$work/triangles.dat" using 1:2 title "illum" lw 2, "" using 1:3 title "llvmpipe" lw 2
unset logscale
set xlabel "megapixels (48k triangles, $threads threads)"
plot "$work/resolution.dat" using 1:2 title "illum" lw 2, "" using 1:3 title "llvmpipe" lw 2
set xlabel "threads (48k triangles, 1080p)"; set xtics 1
plot "$work/threads.dat" using 1:2 title "illum" lw 2, "" using 1:3 title "llvmpipe" lw 2
unset multiplot
GNUPLOT
echo "bench/scaling.sh: wrote $out"
