# Compares two linear OpenEXR pictures inside Blender (which reads EXR):
#   blender -b --factory-startup -P compare.py -- A.exr B.exr DIFF.png
# Prints the ratio of the two pictures' mean radiance, the mean relative error of B against A over
# 8×8-pixel blocks (which averages most of both renders' sampling noise away) and over single
# pixels, where A is not black, and writes |A − B| × 8 as a picture.
import bpy, math, sys

a_path, b_path, diff_path = sys.argv[sys.argv.index("--") + 1:][:3]
a, b = bpy.data.images.load(a_path), bpy.data.images.load(b_path)
if tuple(a.size) != tuple(b.size):
    raise SystemExit("compare.py: the pictures differ in size")
pa, pb = list(a.pixels), list(b.pixels)
relative, counted, squared, n = 0.0, 0, 0.0, len(pa) // 4
for i in range(n):
    for c in range(3):
        x, y = pa[4 * i + c], pb[4 * i + c]
        squared += (x - y) ** 2
    la = sum(pa[4 * i:4 * i + 3]) / 3
    lb = sum(pb[4 * i:4 * i + 3]) / 3
    if la > 0.01:
        relative += abs(lb - la) / la
        counted += 1
W, H = a.size
block_error, blocks = 0.0, 0
BW, BH = W // 8, H // 8
block_diff = [0.0] * (BW * BH * 4)
for by in range(0, BH * 8, 8):
    for bx in range(0, BW * 8, 8):
        sa = sb = 0.0
        ca, cb = [0.0] * 3, [0.0] * 3
        for y in range(by, by + 8):
            for x in range(bx, bx + 8):
                i = 4 * (y * W + x)
                for c in range(3):
                    ca[c] += pa[i + c]
                    cb[c] += pb[i + c]
        sa, sb = sum(ca), sum(cb)
        j = 4 * ((by // 8) * BW + bx // 8)
        for c in range(3):
            block_diff[j + c] = min(1.0, abs(cb[c] - ca[c]) / 64 * 16)
        block_diff[j + 3] = 1.0
        if sa > 0.01 * 3 * 64:
            block_error += abs(sb - sa) / sa
            blocks += 1
mean_a = sum(pa[i] + pa[i + 1] + pa[i + 2] for i in range(0, len(pa), 4))
mean_b = sum(pb[i] + pb[i + 1] + pb[i + 2] for i in range(0, len(pb), 4))
out = bpy.data.images.new("diff", BW, BH, float_buffer=True)
out.pixels = block_diff
out.filepath_raw = diff_path
out.file_format = "PNG"
out.save()
print("illum-compare: mean radiance ratio %.4f; mean relative error %.4f over %d 8x8 blocks, %.4f over %d pixels; "
      "RMS error %.4f" % (mean_b / mean_a, block_error / max(1, blocks), blocks, relative / max(1, counted), counted,
                          math.sqrt(squared / (3 * n))))
