// GLUT's solids, laid out as freeglut 3 builds them (fg_geometry.c): the same parameters, the same
// vertex rings and normals, and the same triangle strips turned into triangle lists with the
// strip's provoking vertex kept last.
#include <illum/mesh.h>

#include <cmath>
#include <numbers>

namespace illum {
namespace {

// Sines and cosines of n equal steps around a circle (or half one); a negative n walks the other
// way round. Entry |n| closes the circle (freeglut's fghCircleTable).
struct CircleTable {
  std::vector<Real> sin, cos;
};

CircleTable circleTable(int n, bool halfCircle) {
  const int size = std::abs(n);
  const double angle = (halfCircle ? 1 : 2) * std::numbers::pi / (n == 0 ? 1 : n);
  CircleTable t;
  t.sin.resize(size + 1);
  t.cos.resize(size + 1);
  t.sin[0] = 0;
  t.cos[0] = 1;
  for (int i = 1; i < size; ++i) {
    t.sin[i] = Real(std::sin(angle * i));
    t.cos[i] = Real(std::cos(angle * i));
  }
  if (halfCircle) {
    t.sin[size] = 0;
    t.cos[size] = -1;
  } else {
    t.sin[size] = t.sin[0];
    t.cos[size] = t.cos[0];
  }
  return t;
}

// Appends the triangles of one GL_TRIANGLE_STRIP. GL draws triangle k as (v[k], v[k+1], v[k+2])
// for even k and (v[k+1], v[k], v[k+2]) for odd k; v[k+2] is the provoking vertex. Triangles with
// a repeated vertex cover no pixel and are dropped.
void appendStrip(std::vector<std::uint32_t>& out, const std::vector<std::uint32_t>& strip) {
  for (std::size_t k = 0; k + 2 < strip.size(); ++k) {
    std::uint32_t a = strip[k], b = strip[k + 1], c = strip[k + 2];
    if (k % 2 == 1) std::swap(a, b);
    if (a == b || b == c || a == c) continue;
    out.insert(out.end(), {a, b, c});
  }
}

// GL_QUADS (a,b,c,d) as GL splits a quad: (a,b,d) and (b,c,d), provoking vertex d.
void appendQuad(std::vector<std::uint32_t>& out, std::uint32_t a, std::uint32_t b, std::uint32_t c,
                std::uint32_t d) {
  out.insert(out.end(), {a, b, d, b, c, d});
}

}  // namespace

Mesh makeSphere(Real radius, int slices, int stacks) {
  Mesh m;
  const CircleTable around = circleTable(-slices, false);
  const CircleTable down = circleTable(stacks, true);
  // Top pole, stacks−1 rings of `slices` vertices, bottom pole.
  m.positions.push_back({0, 0, radius});
  m.normals.push_back({0, 0, 1});
  for (int i = 1; i < stacks; ++i) {
    for (int j = 0; j < slices; ++j) {
      Vec3 n(around.cos[j] * down.sin[i], around.sin[j] * down.sin[i], down.cos[i]);
      m.positions.push_back(n * radius);
      m.normals.push_back(n);
    }
  }
  m.positions.push_back({0, 0, -radius});
  m.normals.push_back({0, 0, -1});
  const auto last = std::uint32_t(m.positions.size() - 1);
  const auto s = std::uint32_t(slices);

  std::vector<std::uint32_t> strip;
  // Top cap: alternate ring vertex and the pole.
  for (std::uint32_t j = 0; j <= s; ++j) strip.insert(strip.end(), {1 + j % s, 0});
  appendStrip(m.indices, strip);
  // Middle stacks.
  for (int i = 0; i + 2 < stacks; ++i) {
    strip.clear();
    const auto offset = std::uint32_t(1 + i * slices);
    for (std::uint32_t j = 0; j <= s; ++j) strip.insert(strip.end(), {offset + j % s + s, offset + j % s});
    appendStrip(m.indices, strip);
  }
  // Bottom cap.
  strip.clear();
  const auto offset = std::uint32_t(1 + (stacks - 2) * slices);
  for (std::uint32_t j = 0; j <= s; ++j) strip.insert(strip.end(), {last, offset + j % s});
  appendStrip(m.indices, strip);
  return m;
}

Mesh makeCube(Real size) {
  Mesh m;
  const Real h = size / 2;
  // Each face: its outward normal and two axes spanning it so that (u × v) = normal.
  const Vec3 normals[6] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
  for (const Vec3& n : normals) {
    const Vec3 u = std::abs(n.x) > 0 ? Vec3(0, n.x, 0) : std::abs(n.y) > 0 ? Vec3(0, 0, n.y) : Vec3(n.z, 0, 0);
    const Vec3 v = glm::cross(n, u);
    const auto base = std::uint32_t(m.positions.size());
    for (Vec3 corner : {n + u + v, n - u + v, n - u - v, n + u - v}) {
      m.positions.push_back(corner * h);
      m.normals.push_back(n);
    }
    appendQuad(m.indices, base, base + 1, base + 2, base + 3);
  }
  return m;
}

Mesh makeTorus(Real innerRadius, Real outerRadius, int sides, int rings) {
  Mesh m;
  // freeglut duplicates the seam (sides+1 × rings+1 vertices) so that strips close.
  const CircleTable ring = circleTable(rings, false);
  const CircleTable side = circleTable(-sides, false);
  for (int j = 0; j <= rings; ++j) {
    for (int i = 0; i <= sides; ++i) {
      const Real r = outerRadius + side.cos[i] * innerRadius;
      m.positions.push_back({ring.cos[j] * r, ring.sin[j] * r, side.sin[i] * innerRadius});
      m.normals.push_back({ring.cos[j] * side.cos[i], ring.sin[j] * side.cos[i], side.sin[i]});
    }
  }
  const auto stride = std::uint32_t(sides + 1);
  for (int i = 0; i < sides; ++i) {
    std::vector<std::uint32_t> strip;
    for (int j = 0; j <= rings; ++j) {
      const auto k = std::uint32_t(j) * stride + std::uint32_t(i);
      strip.insert(strip.end(), {k, k + 1});
    }
    appendStrip(m.indices, strip);
  }
  return m;
}

Mesh makeCone(Real base, Real height, int slices, int stacks) {
  Mesh m;
  const Real zStep = height / Real(stacks > 0 ? stacks : 1);
  const Real rStep = base / Real(stacks > 0 ? stacks : 1);
  // The side's normal leans outward by the cone's half-angle.
  const Real slant = std::sqrt(height * height + base * base);
  const Real cosn = height / slant, sinn = base / slant;
  const CircleTable around = circleTable(-slices, false);

  // Base cap: centre, then a ring facing −Z.
  m.positions.push_back({0, 0, 0});
  m.normals.push_back({0, 0, -1});
  for (int j = 0; j < slices; ++j) {
    m.positions.push_back({around.cos[j] * base, around.sin[j] * base, 0});
    m.normals.push_back({0, 0, -1});
  }
  // Side rings from the base up to the apex (the last ring has radius 0).
  for (int i = 0; i <= stacks; ++i) {
    const Real r = base - rStep * Real(i);
    for (int j = 0; j < slices; ++j) {
      m.positions.push_back({around.cos[j] * r, around.sin[j] * r, zStep * Real(i)});
      m.normals.push_back({around.cos[j] * cosn, around.sin[j] * cosn, sinn});
    }
  }
  const auto s = std::uint32_t(slices);
  // The ring runs clockwise seen from +Z, which is counter-clockwise seen from below the base.
  for (std::uint32_t j = 0; j < s; ++j) m.indices.insert(m.indices.end(), {1 + j, 1 + (j + 1) % s, 0});
  for (int i = 0; i < stacks; ++i) {
    std::vector<std::uint32_t> strip;
    const auto offset = std::uint32_t(1 + slices + i * slices);
    for (std::uint32_t j = 0; j <= s; ++j) strip.insert(strip.end(), {offset + j % s, offset + s + j % s});
    appendStrip(m.indices, strip);
  }
  return m;
}

}  // namespace illum
