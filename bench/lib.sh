# What the side-by-side scripts share (sourced, not run): their common options, a JSON field of a
# bench line, and a median.
#   parse_bench_options "$@"  sets threads, rounds, frames, layouts (for --layouts) and inputs
#   default_to_bench_scenes   fills empty inputs with ../shared/bench/*.json
threads=$(nproc 2>/dev/null || echo 2)
rounds=3
frames=10
layouts=0
inputs=()
parse_bench_options() {
  while [ $# -gt 0 ]; do
    case "$1" in
      --threads) threads=$2; shift 2 ;;
      --rounds) rounds=$2; shift 2 ;;
      --frames) frames=$2; shift 2 ;;
      --layouts) layouts=1; shift ;;
      *) inputs+=("$1"); shift ;;
    esac
  done
}
# No inputs given: the shared benchmark scenes (../shared/bench/*.json).
default_to_bench_scenes() {
  if [ ${#inputs[@]} -eq 0 ]; then
    for s in ../shared/bench/*.json; do inputs+=("$s"); done
  fi
}
field() { sed -n "s/.*\"$1\": \([0-9.]*\).*/\1/p"; }
median() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print (NR%2 ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2)}'; }
