#!/usr/bin/env bash
# The path tracer's denoiser, measured: each input path traced at 16, 64 and 128 samples per
# pixel without the denoiser and at 16 and 64 with it, each picture's relative MSE against a
# 4096-sample reference of the same input (illum_relmse: mean of (x − r)²/(r² + 0.01) over the
# linear RGB values), and the whole command's time writing the picture as a PNG (the error is read from
# the same picture drawn again into an EXR, whose float layers take longer to write). References are kept in build/denoise-ref/
# (delete them after changing the path tracer).
# With --seeds K, each input's 16 denoised and 128 raw samples are drawn again with seeds 1..K
# (illum render --seed) and their error split into bias² and variance (illum_relmse --seeds): a
# raw picture's is all variance; a filter trades some of it for bias.
# --size native draws each input at the size its command draws by default (a scene file's own,
# the built-in scene's 960×540, a model's 1000×600); by default every input is 320×240.
#   bench/denoise.sh [--size W,H|native] [--reference N] [--seeds K] [INPUT ...]
# Inputs default to the Cornell box, the built-in scene and a glTF model (2CylinderEngine.glb).
set -euo pipefail
cd "$(dirname "$0")/.."
size=320,240
reference=4096
seeds=0
inputs=()
while [ $# -gt 0 ]; do
  case "$1" in
    --size) size=$2; shift 2 ;;
    --reference) reference=$2; shift 2 ;;
    --seeds) seeds=$2; shift 2 ;;
    *) inputs+=("$1"); shift ;;
  esac
done
[ ${#inputs[@]} -gt 0 ] || inputs=(examples/cornell_box.json builtin /usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb)
illum=build/apps/illum/illum
relmse=build/bench/illum_relmse
for b in "$illum" "$relmse"; do
  [ -x "$b" ] || { echo "denoise: $b is missing: build first (scripts/dev.sh run)" >&2; exit 2; }
done
out=build/denoise-ref
mkdir -p "$out"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# render NAME.EXT INPUT SAMPLES OPTIONS...: the picture as work/NAME.EXT; prints the seconds it took.
render() {
  local name=$1 input=$2 samples=$3
  shift 3
  local args=(render)
  [ "$input" = builtin ] || args+=("$input")
  args+=(--renderer path --samples "$samples" "$@" -o "$work/$name")
  [ "$size" = native ] || args+=(--resolution "$size")
  local start end
  start=$(date +%s.%N)
  "$illum" "${args[@]}" >/dev/null
  end=$(date +%s.%N)
  awk -v a="$start" -v b="$end" 'BEGIN { printf "%.2f", b - a }'
}
echo "# $(lscpu | sed -n 's/^Model name: *//p'), $(nproc) cores; size $size; relative MSE against $reference samples per pixel; seconds for the whole command (PNG)"
printf '| %-22s | %-16s | %-16s | %-16s | %-16s | %-16s |\n' input "16" "16 denoised" "64" "64 denoised" "128"
printf '|%s|%s|%s|%s|%s|%s|\n' ------------------------ ------------------ ------------------ ------------------ ------------------ ------------------
for input in "${inputs[@]}"; do
  key=$(basename "$input" | tr -c 'A-Za-z0-9.\n' _)_${size/,/x}_$reference
  ref="$out/$key.exr"
  if [ ! -f "$ref" ]; then
    render ref.exr "$input" "$reference" --no-denoise >/dev/null
    mv "$work/ref.exr" "$ref"
  fi
  row=()
  for run in "16 --no-denoise" "16 --denoise" "64 --no-denoise" "64 --denoise" "128 --no-denoise"; do
    set -- $run
    seconds=$(render pic.png "$input" "$1" "$2")
    render pic.exr "$input" "$1" "$2" >/dev/null
    row+=("$(printf '%.4f in %ss' "$("$relmse" "$work/pic.exr" "$ref")" "$seconds")")
  done
  printf '| %-22s | %-16s | %-16s | %-16s | %-16s | %-16s |\n' "$(basename "$input")" "${row[@]}"
done
[ "$seeds" -gt 1 ] || exit 0
echo
echo "# relative MSE over seeds 1..$seeds: error = bias² + variance"
printf '| %-22s | %-36s | %-36s |\n' input "16 denoised" "128"
printf '|%s|%s|%s|\n' ------------------------ -------------------------------------- --------------------------------------
for input in "${inputs[@]}"; do
  key=$(basename "$input" | tr -c 'A-Za-z0-9.\n' _)_${size/,/x}_$reference
  row=()
  for run in "16 --denoise" "128 --no-denoise"; do
    set -- $run
    pictures=()
    for seed in $(seq 1 "$seeds"); do
      render "s$seed.exr" "$input" "$1" "$2" --seed "$seed" >/dev/null
      pictures+=("$work/s$seed.exr")
    done
    row+=("$("$relmse" --seeds "$out/$key.exr" "${pictures[@]}" | awk '{printf "%.5f = %.5f + %.5f", $2, $4, $6}')")
  done
  printf '| %-22s | %-36s | %-36s |\n' "$(basename "$input")" "${row[@]}"
done
