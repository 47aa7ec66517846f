#!/usr/bin/env bash
# The thumbnailer as GNOME runs it (bubblewrap: read-only /usr, minimal /dev, no network, no
# display, the input alone in the sandbox's /tmp) over every model file of Debian's
# assimp-testmodels: how many are drawn and refused, the slowest, the largest memory, and the
# 2CylinderEngine.glb's whole-process time at 256².
#   bench/thumbnails.sh [SIZE]   (default 256)
set -euo pipefail
cd "$(dirname "$0")/.."
size=${1:-256}
illum=$PWD/build/apps/illum/illum
[ -x "$illum" ] || { echo "thumbnails: $illum is missing: build first (scripts/dev.sh run)" >&2; exit 2; }
command -v bwrap >/dev/null || { echo "thumbnails: bwrap is missing (apt-get install bubblewrap)" >&2; exit 2; }
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
run() {  # run FILE: "seconds kilobytes exit"
  local ext=".${1##*.}" inside
  inside=/tmp/gnome-desktop-file-to-thumbnail$ext
  bwrap --ro-bind /usr /usr --symlink usr/lib /lib --symlink usr/lib64 /lib64 --symlink usr/bin /bin \
    --proc /proc --dev /dev --chdir / --unshare-all --die-with-parent --clearenv --bind "$out" /tmp \
    --ro-bind "$1" "$inside" --ro-bind "$(dirname "$illum")" /opt/illum \
    /usr/bin/time -f "%e %M" -o /tmp/time /opt/illum/illum thumbnail "$inside" /tmp/thumb.png "$size" >/dev/null 2>&1 &&
    status=0 || status=$?
  echo "$(cat "$out/time" 2>/dev/null | tail -1) $status"
}
drawn=0 refused=0 slowest=0 slowestName= largest=0 largestName=
while IFS= read -r -d '' f; do
  case "${f,,}" in *.png|*.jpg|*.jpeg|*.tga|*.bmp|*.dds|*.txt|*.md|*.bin|*.mtl|*.xml|*.gif|*.tif|*.pcx|*.psd) continue ;; esac
  read -r seconds kb status <<<"$(run "$f")"
  [ "$status" = 0 ] && drawn=$((drawn + 1)) || refused=$((refused + 1))
  if awk -v a="$seconds" -v b="$slowest" 'BEGIN { exit !(a > b) }'; then slowest=$seconds slowestName=$f; fi
  if [ "${kb:-0}" -gt "$largest" ]; then largest=$kb largestName=$f; fi
done < <(find /usr/share/assimp/models -type f -print0 | sort -z)
engine=/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb
times=()
for _ in 1 2 3 4 5; do read -r seconds _ _ <<<"$(run "$engine")"; times+=("$seconds"); done
echo "# $(lscpu | sed -n 's/^Model name: *//p'), $(nproc) cores; thumbnails of ${size}² inside bubblewrap"
echo "drawn $drawn, refused $refused; slowest $slowest s ($slowestName); largest $((largest / 1024)) MiB ($largestName)"
echo "2CylinderEngine.glb: $(printf '%s\n' "${times[@]}" | sort -g | sed -n 3p) s (median of 5, whole process)"
