#!/usr/bin/env bash
# Fuzz illum for a fixed budget:
#   fuzz/run.sh [SECONDS]   each target for SECONDS (default 60), from a random seed: for hunting
#   fuzz/run.sh --ci        each target for a fixed number of runs from a fixed seed: the same
#                           inputs on every run, about 45 s each on two cores (what CI runs)
# Builds the libFuzzer targets with clang, ASan and UBSan (build-fuzz/), replays the regression
# inputs of tests/regressions/, then fuzzes the scene parser and the model import from seed
# corpora (the examples and test scenes; small files of Debian's assimp-testmodels). A crash
# leaves its input as fuzz/artifacts/crash-*: add it to tests/regressions/ with the fix.
set -euo pipefail
cd "$(dirname "$0")/.."
budget=(-max_total_time="${1:-60}")
label="${1:-60} s"
if [ "${1:-}" = "--ci" ]; then
  budget=(-seed=1)
  label="a fixed seed"
fi
jobs=$(nproc 2>/dev/null || echo 2)

cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  -DILLUM_FUZZ=ON -DILLUM_MESA_PARITY=OFF >/dev/null
cmake --build build-fuzz -j "$jobs" --target illum_scene_fuzzer illum_model_fuzzer illum_environment_fuzzer \
  illum_output_template_fuzzer

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/scene" "$work/model" "$work/hdr" "$work/template" fuzz/artifacts

# Seeds: every scene file of the repository; for models, the extension index as the first byte.
find examples tests/scenes tests/regressions -name '*.json' -exec cp {} "$work/scene/" \;
extensions=(ply off stl obj gltf glb ac nff dae 3ds ase md5mesh cob x smd fbx)
seed() {  # seed FILE: prepend the byte that selects FILE's extension
  local ext=${1##*.} i
  ext=${ext,,}
  for i in "${!extensions[@]}"; do
    if [ "${extensions[$i]}" = "$ext" ]; then
      { printf "\\$(printf '%03o' "$i")"; cat "$1"; } > "$work/model/$(basename "$1")"
      return
    fi
  done
}
for f in tests/regressions/*; do if [ -f "$f" ]; then seed "$f"; fi; done
# Output templates: the documented ones, over inputs named alone, through a link and from a folder.
printf '{dir}/{name}\n\np.obj\nq.obj\n' > "$work/template/1"
printf '{dir}/{stem}.png\nthumbs\n../p.obj\nmodels/a/m.obj\nmodels/c/m.obj\n' > "$work/template/2"
printf '{n}.png\nout\nlink.obj\np.obj\n' > "$work/template/3"
printf '{stem}_{frame:04}.png\n/abs\n/tmp/../p.obj\n' > "$work/template/4"
# Environment maps: the regressions, and a whole 8×2 run-length encoded map and a flat 4×2 one.
cp tests/regressions/*.hdr "$work/hdr/"
{ printf '#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 8\n'
  for row in 1 2; do printf '\002\002\000\010'; for c in 1 2 3 4; do printf '\210\200'; done; done; } > "$work/hdr/rle.hdr"
{ printf '#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 4\n'; head -c 32 /dev/zero | tr '\0' '\200'; } > "$work/hdr/flat.hdr"
if [ -d /usr/share/assimp/models ]; then
  while IFS= read -r f; do seed "$f"; done < <(find /usr/share/assimp/models -type f -size -16k | sort)
fi

export ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export LSAN_OPTIONS=suppressions=$PWD/tests/lsan.supp
run() {  # run TARGET CORPUS RUNS: RUNS applies with --ci
  local runs=()
  [ "${budget[0]}" = "-seed=1" ] && runs=(-runs="$3")
  echo "illum: fuzzing $1 ($label${runs:+, $3 runs})"
  if ! "build-fuzz/fuzz/illum_$1" "${budget[@]}" "${runs[@]}" -timeout=20 -rss_limit_mb=2048 -max_len=65536 \
      -artifact_prefix="$PWD/fuzz/artifacts/" -print_final_stats=1 "$2" > "$work/$1.log" 2>&1; then
    grep -v '^#' "$work/$1.log" | tail -n 60
    echo "illum: $1 found a crash: fuzz/artifacts/ holds the input" >&2
    return 1
  fi
  tail -n 6 "$work/$1.log"
}
run scene_fuzzer "$work/scene" 150000
run model_fuzzer "$work/model" 2000
run environment_fuzzer "$work/hdr" 200000
run output_template_fuzzer "$work/template" 100000
echo "fuzz: 4 passed, 0 failed"
