#!/usr/bin/env bash
# Whitted ray tracing: illum against POV-Ray 3.7 (Debian's povray) on the same triangle-mesh scene,
# whole process (parse, build, trace, write the PNG), side by side:
#   bench/compare_povray.sh [--threads N] [--rounds R] [--slices S] [--width W --height H] [--depth D]
# bench/povray/whitted_scene.py writes the scene for both: a checkerboard, a mirror sphere and a
# glass sphere of S slices (about S² triangles each), one light, the same camera, resolution and ray depth;
# POV-Ray without anti-aliasing, illum with one ray per pixel, both on N threads. The two are
# alternated R times; the table shows each median wall time and the ratio.
set -euo pipefail
cd "$(dirname "$0")/.."
illum=build/apps/illum/illum
threads=2 rounds=3 slices=256 width=1280 height=960 depth=5
while [ $# -gt 0 ]; do
  case $1 in
    --threads) threads=$2; shift 2 ;;
    --rounds) rounds=$2; shift 2 ;;
    --slices) slices=$2; shift 2 ;;
    --width) width=$2; shift 2 ;;
    --height) height=$2; shift 2 ;;
    --depth) depth=$2; shift 2 ;;
    *) echo "compare_povray: unknown argument $1" >&2; exit 2 ;;
  esac
done
command -v povray >/dev/null || { echo "compare_povray: needs POV-Ray (apt-get install povray)" >&2; exit 2; }
[ -x "$illum" ] || { echo "compare_povray: build illum first (scripts/dev.sh run)" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python3 bench/povray/whitted_scene.py "$work" --slices "$slices" --width "$width" --height "$height" --depth "$depth"
triangles=$(python3 -c "import json,sys; s=json.load(open(sys.argv[1])); print(sum(len(o['mesh']['indices'])//3 for o in s['objects']))" "$work/whitted_mesh.json")

median() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print (NR%2 ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2)}'; }
seconds() { local start=$1 end=$2; awk -v a="$start" -v b="$end" 'BEGIN {printf "%.3f", b - a}'; }
now() { date +%s.%N; }

ours=() theirs=()
for ((r = 0; r < rounds; ++r)); do
  t0=$(now)
  "$illum" render "$work/whitted_mesh.json" --threads "$threads" -o "$work/illum.png" -q
  t1=$(now)
  # File_Gamma=1.0: write linear values, as illum does (the scene's assumed_gamma is 1.0 too).
  povray "+I$work/whitted_mesh.pov" "+O$work/povray.png" "+W$width" "+H$height" "+WT$threads" -D -V -GA \
    File_Gamma=1.0 >/dev/null 2>&1
  t2=$(now)
  ours+=("$(seconds "$t0" "$t1")") theirs+=("$(seconds "$t1" "$t2")")
done
a=$(median "${ours[@]}") b=$(median "${theirs[@]}")
echo "Whitted scene: $triangles triangles, ${width}×${height}, depth $depth, $threads threads; median of $rounds alternated rounds (whole process)"
printf '| %-8s | %8s |\n' tool "wall s"
printf '|%s|%s|\n' ---------- ----------
printf '| %-8s | %8s |\n' illum "$a" POV-Ray "$b"
awk -v a="$a" -v b="$b" 'BEGIN {printf "illum / POV-Ray = %.2f\n", a / b}'
