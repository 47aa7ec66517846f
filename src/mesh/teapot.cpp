// glutSolidTeapot: the Utah teapot as SGI's GLUT draws it (glut_teapot.c, Mark J. Kilgard 1994):
// ten bicubic Bézier patches, the rim, body, lid and bottom mirrored into four quadrants and the
// handle and spout into two, each evaluated on a 14×14 grid (glMapGrid2f + glEvalMesh2) with
// GL_AUTO_NORMAL's normal ∂P/∂u × ∂P/∂v, then placed by glRotatef(270,1,0,0),
// glScalef(size/2) and glTranslatef(0,0,-1.5).
//
// Control points and patch indices: the teapot data of SGI's GLUT,
// (c) Copyright 1993, Silicon Graphics, Inc. Permission to use, copy, modify, and distribute this
// software for any purpose and without fee is hereby granted, provided that the above copyright
// notice appear in all copies and that both the copyright notice and this permission notice
// appear in supporting documentation. (Data from Martin Newell's 1975 teapot.)
#include <illum/mesh.h>

#include <glm/gtc/matrix_transform.hpp>

#include <array>

namespace illum {
namespace {

constexpr int kGrid = 14;  // glutSolidTeapot's tessellation

constexpr int kPatches[10][16] = {
    {102, 103, 104, 105, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15},            // rim
    {12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27},          // body
    {24, 25, 26, 27, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40},          // body
    {96, 96, 96, 96, 97, 98, 99, 100, 101, 101, 101, 101, 0, 1, 2, 3},         // lid
    {0, 1, 2, 3, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117},  // lid
    {118, 118, 118, 118, 124, 122, 119, 121, 123, 126, 125, 120, 40, 39, 38, 37},  // bottom
    {41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56},          // handle
    {53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 28, 65, 66, 67},          // handle
    {68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83},          // spout
    {80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95},          // spout
};
constexpr int kMirroredPatches = 6;  // the first six are mirrored into all four quadrants

constexpr float kPoints[127][3] = {
    {0.2f, 0, 2.7f}, {0.2f, -0.112f, 2.7f}, {0.112f, -0.2f, 2.7f}, {0, -0.2f, 2.7f},
    {1.3375f, 0, 2.53125f}, {1.3375f, -0.749f, 2.53125f}, {0.749f, -1.3375f, 2.53125f}, {0, -1.3375f, 2.53125f},
    {1.4375f, 0, 2.53125f}, {1.4375f, -0.805f, 2.53125f}, {0.805f, -1.4375f, 2.53125f}, {0, -1.4375f, 2.53125f},
    {1.5f, 0, 2.4f}, {1.5f, -0.84f, 2.4f}, {0.84f, -1.5f, 2.4f}, {0, -1.5f, 2.4f},
    {1.75f, 0, 1.875f}, {1.75f, -0.98f, 1.875f}, {0.98f, -1.75f, 1.875f}, {0, -1.75f, 1.875f},
    {2, 0, 1.35f}, {2, -1.12f, 1.35f}, {1.12f, -2, 1.35f}, {0, -2, 1.35f},
    {2, 0, 0.9f}, {2, -1.12f, 0.9f}, {1.12f, -2, 0.9f}, {0, -2, 0.9f},
    {-2, 0, 0.9f}, {2, 0, 0.45f}, {2, -1.12f, 0.45f}, {1.12f, -2, 0.45f},
    {0, -2, 0.45f}, {1.5f, 0, 0.225f}, {1.5f, -0.84f, 0.225f}, {0.84f, -1.5f, 0.225f},
    {0, -1.5f, 0.225f}, {1.5f, 0, 0.15f}, {1.5f, -0.84f, 0.15f}, {0.84f, -1.5f, 0.15f},
    {0, -1.5f, 0.15f}, {-1.6f, 0, 2.025f}, {-1.6f, -0.3f, 2.025f}, {-1.5f, -0.3f, 2.25f},
    {-1.5f, 0, 2.25f}, {-2.3f, 0, 2.025f}, {-2.3f, -0.3f, 2.025f}, {-2.5f, -0.3f, 2.25f},
    {-2.5f, 0, 2.25f}, {-2.7f, 0, 2.025f}, {-2.7f, -0.3f, 2.025f}, {-3, -0.3f, 2.25f},
    {-3, 0, 2.25f}, {-2.7f, 0, 1.8f}, {-2.7f, -0.3f, 1.8f}, {-3, -0.3f, 1.8f},
    {-3, 0, 1.8f}, {-2.7f, 0, 1.575f}, {-2.7f, -0.3f, 1.575f}, {-3, -0.3f, 1.35f},
    {-3, 0, 1.35f}, {-2.5f, 0, 1.125f}, {-2.5f, -0.3f, 1.125f}, {-2.65f, -0.3f, 0.9375f},
    {-2.65f, 0, 0.9375f}, {-2, -0.3f, 0.9f}, {-1.9f, -0.3f, 0.6f}, {-1.9f, 0, 0.6f},
    {1.7f, 0, 1.425f}, {1.7f, -0.66f, 1.425f}, {1.7f, -0.66f, 0.6f}, {1.7f, 0, 0.6f},
    {2.6f, 0, 1.425f}, {2.6f, -0.66f, 1.425f}, {3.1f, -0.66f, 0.825f}, {3.1f, 0, 0.825f},
    {2.3f, 0, 2.1f}, {2.3f, -0.25f, 2.1f}, {2.4f, -0.25f, 2.025f}, {2.4f, 0, 2.025f},
    {2.7f, 0, 2.4f}, {2.7f, -0.25f, 2.4f}, {3.3f, -0.25f, 2.4f}, {3.3f, 0, 2.4f},
    {2.8f, 0, 2.475f}, {2.8f, -0.25f, 2.475f}, {3.525f, -0.25f, 2.49375f}, {3.525f, 0, 2.49375f},
    {2.9f, 0, 2.475f}, {2.9f, -0.15f, 2.475f}, {3.45f, -0.15f, 2.5125f}, {3.45f, 0, 2.5125f},
    {2.8f, 0, 2.4f}, {2.8f, -0.15f, 2.4f}, {3.2f, -0.15f, 2.4f}, {3.2f, 0, 2.4f},
    {0, 0, 3.15f}, {0.8f, 0, 3.15f}, {0.8f, -0.45f, 3.15f}, {0.45f, -0.8f, 3.15f},
    {0, -0.8f, 3.15f}, {0, 0, 2.85f}, {1.4f, 0, 2.4f}, {1.4f, -0.784f, 2.4f},
    {0.784f, -1.4f, 2.4f}, {0, -1.4f, 2.4f}, {0.4f, 0, 2.55f}, {0.4f, -0.224f, 2.55f},
    {0.224f, -0.4f, 2.55f}, {0, -0.4f, 2.55f}, {1.3f, 0, 2.55f}, {1.3f, -0.728f, 2.55f},
    {0.728f, -1.3f, 2.55f}, {0, -1.3f, 2.55f}, {1.3f, 0, 2.4f}, {1.3f, -0.728f, 2.4f},
    {0.728f, -1.3f, 2.4f}, {0, -1.3f, 2.4f}, {0, 0, 0}, {1.425f, -0.798f, 0},
    {1.5f, 0, 0.075f}, {1.425f, 0, 0}, {0.798f, -1.425f, 0}, {0, -1.5f, 0.075f},
    {0, -1.425f, 0}, {1.5f, -0.84f, 0.075f}, {0.84f, -1.5f, 0.075f},
};

using Patch = std::array<Vec3, 16>;  // [v][u], v = row j, u = column k as glMap2f reads them

void bernstein(Real t, Real b[4], Real d[4]) {
  const Real s = 1 - t;
  b[0] = s * s * s;
  b[1] = 3 * t * s * s;
  b[2] = 3 * t * t * s;
  b[3] = t * t * t;
  d[0] = -3 * s * s;
  d[1] = 3 * s * s - 6 * t * s;
  d[2] = 6 * t * s - 3 * t * t;
  d[3] = 3 * t * t;
}

struct PatchSample {
  Vec3 position, dPdu, dPdv;
};

PatchSample evaluate(const Patch& p, Real u, Real v) {
  Real bu[4], du[4], bv[4], dv[4];
  bernstein(u, bu, du);
  bernstein(v, bv, dv);
  PatchSample s{Vec3(0), Vec3(0), Vec3(0)};
  for (int j = 0; j < 4; ++j)
    for (int k = 0; k < 4; ++k) {
      s.position += bv[j] * bu[k] * p[j * 4 + k];
      s.dPdu += bv[j] * du[k] * p[j * 4 + k];
      s.dPdv += dv[j] * bu[k] * p[j * 4 + k];
    }
  return s;
}

// GL_AUTO_NORMAL's normal; at a pole one derivative vanishes, so step into the patch for it.
Vec3 autoNormal(const Patch& p, Real u, Real v) {
  PatchSample s = evaluate(p, u, v);
  Vec3 n = glm::cross(s.dPdu, s.dPdv);
  for (Real eps : {Real(1e-3), Real(1e-2)}) {
    if (glm::length(n) > Real(1e-6)) break;
    const PatchSample t = evaluate(p, glm::clamp(u, eps, 1 - eps), glm::clamp(v, eps, 1 - eps));
    n = glm::cross(t.dPdu, t.dPdv);
  }
  return glm::length(n) > 0 ? glm::normalize(n) : Vec3(0, 0, 1);
}

// glEvalMesh2(GL_FILL): one triangle strip per grid row, corners (u,v),(u,v+1),(u+1,v),...
void tessellate(const Patch& p, const Mat4& worldFromPatch, const Mat3& normalFromPatch, Mesh& m) {
  const auto base = std::uint32_t(m.positions.size());
  for (int j = 0; j <= kGrid; ++j)
    for (int i = 0; i <= kGrid; ++i) {
      const Real u = Real(i) / kGrid, v = Real(j) / kGrid;
      m.positions.push_back(Vec3(worldFromPatch * Vec4(evaluate(p, u, v).position, 1)));
      m.normals.push_back(glm::normalize(normalFromPatch * autoNormal(p, u, v)));
    }
  const auto at = [&](int i, int j) { return base + std::uint32_t(j * (kGrid + 1) + i); };
  for (int j = 0; j < kGrid; ++j)
    for (int i = 0; i < kGrid; ++i) {
      const std::uint32_t a = at(i, j), b = at(i, j + 1), c = at(i + 1, j), d = at(i + 1, j + 1);
      // Keep the triangles whose corners differ (the lid's pole collapses a row), wound so that
      // their face agrees with the patch normal.
      for (auto [x, y, z] : {std::array{a, c, b}, std::array{b, c, d}}) {
        const Vec3 &px = m.positions[x], &py = m.positions[y], &pz = m.positions[z];
        const Vec3 face = glm::cross(py - px, pz - px);
        if (glm::length(face) <= Real(1e-12)) continue;
        if (glm::dot(face, m.normals[x] + m.normals[y] + m.normals[z]) >= 0) m.indices.insert(m.indices.end(), {x, y, z});
        else m.indices.insert(m.indices.end(), {y, x, z});
      }
    }
}

}  // namespace

Mesh makeTeapot(Real size) {
  Mat4 worldFromPatch(1);
  worldFromPatch = glm::rotate(worldFromPatch, glm::radians(Real(270)), Vec3(1, 0, 0));
  worldFromPatch = glm::scale(worldFromPatch, Vec3(size / 2));
  worldFromPatch = glm::translate(worldFromPatch, Vec3(0, 0, Real(-1.5)));
  const Mat3 normalFromPatch = glm::transpose(glm::inverse(Mat3(worldFromPatch)));

  Mesh m;
  for (int i = 0; i < 10; ++i) {
    // The patch and its mirror images: across y (all), across x and across both (rim to bottom).
    Patch p, mirrorY, mirrorX, mirrorXY;
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k) {
        const float* a = kPoints[kPatches[i][j * 4 + k]];
        const float* b = kPoints[kPatches[i][j * 4 + (3 - k)]];
        p[j * 4 + k] = Vec3(a[0], a[1], a[2]);
        mirrorY[j * 4 + k] = Vec3(b[0], -b[1], b[2]);
        mirrorX[j * 4 + k] = Vec3(-b[0], b[1], b[2]);
        mirrorXY[j * 4 + k] = Vec3(-a[0], -a[1], a[2]);
      }
    tessellate(p, worldFromPatch, normalFromPatch, m);
    tessellate(mirrorY, worldFromPatch, normalFromPatch, m);
    if (i < kMirroredPatches) {
      tessellate(mirrorX, worldFromPatch, normalFromPatch, m);
      tessellate(mirrorXY, worldFromPatch, normalFromPatch, m);
    }
  }
  return m;
}

}  // namespace illum
