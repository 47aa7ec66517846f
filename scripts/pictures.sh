#!/usr/bin/env bash
# Draws every picture of the docs that a command draws (docs/images/sources.txt) again, with the
# built illum: after a change that moves pixels, so that each picture stays what its command draws.
#   scripts/pictures.sh [NAME.png ...]   (default: all of them)
set -euo pipefail
cd "$(dirname "$0")/.."
illum=build/apps/illum/illum
[ -x "$illum" ] || { echo "pictures: $illum is missing: build first (scripts/dev.sh run)" >&2; exit 2; }
while IFS= read -r line; do
  case "$line" in '#'*|'') continue ;; esac
  name=${line%%:*}
  args=${line#*: }
  case "$args" in illustration:*) continue ;; esac
  if [ $# -gt 0 ] && ! printf '%s\n' "$@" | grep -qx "$name"; then continue; fi
  echo "docs/images/$name: illum ${args//OUT/docs/images/$name}"
  # The arguments as a shell reads them (quotes and all), as tests/docs_test.cpp runs them.
  sh -c "\"$illum\" ${args//OUT/docs/images/$name} --quiet"
done < docs/images/sources.txt
