#!/usr/bin/env bash
# Loading and rendering big meshes: illum against f3d (Debian's, under xvfb-run), whole process,
# side by side: bench/compare_f3d.sh [MODEL ...]
# Without arguments it writes two test meshes to a scratch folder: a 2-million-triangle binary PLY
# (an indexed sphere without normals) and a 100 MB binary STL (the same sphere as a triangle soup).
# Prints wall time, CPU time and peak memory of each, rendering at 1000×600. illum draws one sample
# per pixel here (--samples 1), as f3d does by default; its previews take 8 (multisampling) unless told.
set -euo pipefail
cd "$(dirname "$0")/.."
illum=build/apps/illum/illum
command -v f3d >/dev/null && command -v xvfb-run >/dev/null ||
  { echo "compare_f3d: needs f3d and xvfb-run (apt-get install f3d xvfb)" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
models=("$@")
if [ ${#models[@]} -eq 0 ]; then
  python3 - "$work" <<'PY'
import math, struct, sys
n = m = 1000
d = sys.argv[1]
p = lambda i, j: (math.sin(math.pi*i/n)*math.cos(2*math.pi*j/m), math.sin(math.pi*i/n)*math.sin(2*math.pi*j/m), math.cos(math.pi*i/n))
with open(d + "/sphere_2m.ply", "wb") as f:
    f.write(b"ply\nformat binary_little_endian 1.0\nelement vertex %d\nproperty float x\nproperty float y\nproperty float z\n"
            b"element face %d\nproperty list uchar int vertex_indices\nend_header\n" % ((n+1)*(m+1), 2*n*m))
    f.write(b"".join(struct.pack("<3f", *p(i, j)) for i in range(n+1) for j in range(m+1)))
    f.write(b"".join(struct.pack("<B3i", 3, i*(m+1)+j, (i+1)*(m+1)+j, i*(m+1)+j+1) +
                     struct.pack("<B3i", 3, i*(m+1)+j+1, (i+1)*(m+1)+j, (i+1)*(m+1)+j+1) for i in range(n) for j in range(m)))
with open(d + "/sphere_2m.stl", "wb") as f:
    f.write(bytes(80) + struct.pack("<I", 2*n*m))
    for i in range(n):
        f.write(b"".join(struct.pack("<12fH", 0, 0, 0, *p(i, j), *p(i+1, j), *p(i, j+1), 0) +
                         struct.pack("<12fH", 0, 0, 0, *p(i, j+1), *p(i+1, j), *p(i+1, j+1), 0) for j in range(m)))
PY
  models=("$work/sphere_2m.ply" "$work/sphere_2m.stl")
fi
printf '| %-16s | %-6s | %8s | %8s | %10s |\n' model tool "wall s" "CPU s" "peak MB"
printf '|%s|%s|%s|%s|%s|\n' ------------------ -------- ---------- ---------- ------------
for model in "${models[@]}"; do
  for tool in illum f3d; do
    if [ "$tool" = illum ]; then
      /usr/bin/time -f '%e %U %S %M' -o "$work/t" "$illum" "$model" --resolution 1000,600 --samples 1 -o "$work/out.png" -q
    else
      xvfb-run -a /usr/bin/time -f '%e %U %S %M' -o "$work/t" f3d "$model" --resolution 1000,600 --output "$work/f3d.png"
    fi
    read -r wall user sys kb < <(tail -n 1 "$work/t")
    printf '| %-16s | %-6s | %8.2f | %8.2f | %10.0f |\n' "$(basename "$model")" "$tool" "$wall" \
      "$(awk -v a="$user" -v b="$sys" 'BEGIN { print a + b }')" "$(awk -v k="$kb" 'BEGIN { print k / 1024 }')"
  done
done
