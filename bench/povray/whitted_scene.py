#!/usr/bin/env python3
"""Writes one triangle-mesh Whitted scene twice: as an illum scene (inline triangles) and as a
POV-Ray 3.7 scene (mesh2), with the same triangles, normals, camera, light, resolution and ray
depth, so that bench/compare_povray.sh times the same work in both.

usage: whitted_scene.py OUT_DIR [--slices N] [--width W] [--height H] [--depth D]
Writes OUT_DIR/whitted_mesh.json and OUT_DIR/whitted_mesh.pov."""
import argparse, json, math, os

ap = argparse.ArgumentParser()
ap.add_argument("out")
ap.add_argument("--slices", type=int, default=256)
ap.add_argument("--width", type=int, default=1280)
ap.add_argument("--height", type=int, default=960)
ap.add_argument("--depth", type=int, default=5)
a = ap.parse_args()

def sphere(cx, cy, cz, r, slices):
    stacks = slices // 2
    pos, nrm, idx = [], [], []
    for i in range(stacks + 1):
        th = math.pi * i / stacks
        for j in range(slices + 1):
            ph = 2 * math.pi * j / slices
            n = (math.sin(th) * math.cos(ph), math.cos(th), -math.sin(th) * math.sin(ph))
            nrm.append(n)
            pos.append((cx + r * n[0], cy + r * n[1], cz + r * n[2]))
    for i in range(stacks):
        for j in range(slices):
            a0, b0 = i * (slices + 1) + j, (i + 1) * (slices + 1) + j
            if i > 0: idx.append((a0, b0, a0 + 1))
            if i < stacks - 1: idx.append((a0 + 1, b0, b0 + 1))
    return pos, nrm, idx

def checker(parity, n=8, size=1.5, y=-1.0):
    pos, nrm, idx = [], [], []
    for i in range(n):
        for j in range(n):
            if (i + j) % 2 != parity: continue
            x0, z0 = (i - n / 2) * size, (j - n / 2) * size - 4
            b = len(pos)
            pos += [(x0, y, z0 + size), (x0 + size, y, z0 + size), (x0 + size, y, z0), (x0, y, z0)]
            nrm += [(0, 1, 0)] * 4
            idx += [(b, b + 1, b + 2), (b, b + 2, b + 3)]
    return pos, nrm, idx

# name, mesh, illum material, POV-Ray finish/interior
objects = [
    ("red", checker(0), {"ambient": [0.85, 0.1, 0.05], "diffuse": [0.85, 0.1, 0.05]}, "pigment { rgb <0.85,0.1,0.05> }", ""),
    ("yellow", checker(1), {"ambient": [0.95, 0.85, 0.15], "diffuse": [0.95, 0.85, 0.15]}, "pigment { rgb <0.95,0.85,0.15> }", ""),
    ("mirror", sphere(1.1, -0.05, -4.2, 0.9, a.slices),
     {"ambient": [0.05] * 3, "diffuse": [0.1] * 3, "specular": [0.8] * 3, "shininess": 80, "reflective": [0.85] * 3},
     "pigment { rgb 0.1 } finish { specular 0.8 roughness 0.0125 reflection 0.85 }", ""),
    ("glass", sphere(-0.35, -0.1, -1.6, 0.7, a.slices),
     {"ambient": [0] * 3, "diffuse": [0] * 3, "specular": [0.9] * 3, "shininess": 120, "reflective": [0.15] * 3,
      "transmissive": [0.9] * 3, "ior": 1.5},
     "pigment { rgbt <1,1,1,0.9> } finish { diffuse 0 specular 0.9 roughness 0.008 reflection 0.15 }",
     "interior { ior 1.5 }"),
]

eye, center, fovy = (0.2, 0.9, 4.2), (0.2, -0.1, -2.5), 42.0
light = (3, 6, 5)
scene = {
    "width": a.width, "height": a.height, "renderer": "whitted", "max_depth": a.depth,
    "background": [0.32, 0.55, 0.88],
    "camera": {"eye": list(eye), "center": list(center), "fovy": fovy},
    "light_model": {"ambient": [0.25] * 3},
    "lights": [{"position": list(light) + [1], "diffuse": [0.9] * 3, "specular": [1] * 3}],
    "objects": [],
}
r6 = lambda v: [round(x, 6) for x in v]
for name, (pos, nrm, idx), mat, _, _ in objects:
    scene["objects"].append({
        "mesh": {"type": "triangles", "positions": [c for p in pos for c in r6(p)],
                 "normals": [c for n in nrm for c in r6(n)], "indices": [k for t in idx for k in t]},
        "material": mat})
os.makedirs(a.out, exist_ok=True)
with open(os.path.join(a.out, "whitted_mesh.json"), "w") as f:
    json.dump(scene, f, separators=(",", ":"))

# POV-Ray is left-handed: z is negated (and with it the triangles' winding, which POV-Ray ignores).
flip = lambda v: "<%g,%g,%g>" % (v[0], v[1], -v[2])
aspect = a.width / a.height
# POV-Ray's angle is horizontal: the horizontal angle of a vertical fovy at this aspect ratio.
hfov = math.degrees(2 * math.atan(math.tan(math.radians(fovy) / 2) * aspect))
with open(os.path.join(a.out, "whitted_mesh.pov"), "w") as f:
    f.write("#version 3.7;\nglobal_settings { assumed_gamma 1.0 max_trace_level %d ambient_light rgb 0.25 }\n" % (a.depth + 1))
    f.write("background { rgb <0.32,0.55,0.88> }\n")
    f.write("camera { perspective location %s look_at %s right x*%g angle %g }\n" % (flip(eye), flip(center), aspect, hfov))
    f.write("light_source { %s color rgb 0.9 }\n" % flip(light))
    for name, (pos, nrm, idx), _, look, interior in objects:
        f.write("mesh2 {\n vertex_vectors { %d, %s }\n" % (len(pos), ",".join(flip(p) for p in pos)))
        f.write(" normal_vectors { %d, %s }\n" % (len(nrm), ",".join(flip(n) for n in nrm)))
        f.write(" face_indices { %d, %s }\n" % (len(idx), ",".join("<%d,%d,%d>" % t for t in idx)))
        f.write(" %s %s\n}\n" % (look, interior))
