// Rasterizer properties: watertight shared edges, the top-left rule, clipping that keeps coverage,
// and per-pixel lighting against closed forms.
#include <illum/render.h>

#include "raster/coverage/rasterize.h"
#include "raster/coverage/row_span.h"
#include "raster/setup/setup.h"
#include "raster/tile/multisample.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

namespace illum {
namespace {

constexpr int kW = 64, kH = 48;

// A vertex at window position (x, y) in pixels (GL's, y up), expressed in clip space with w = 1.
ShadedVertex atWindow(double x, double y) {
  ShadedVertex v;
  v.clip = Vec4(Real(x / kW * 2 - 1), Real(y / kH * 2 - 1), 0, 1);
  return v;
}

std::vector<int> coverage(const std::vector<std::array<ShadedVertex, 3>>& triangles) {
  std::vector<int> hits(kW * kH, 0);
  for (const auto& t : triangles) {
    TriangleSetup s;
    if (!setupTriangle(t[0], t[1], t[2], kW, kH, s)) continue;
    rasterizeTriangle(s, [&](int x, int y, Real, Real, Real) { ++hits[y * kW + x]; });
  }
  return hits;
}

TEST(Rasterizer, TriangleFanHasNoCracksAndNoDoubleHits) {
  // A fan of 13 triangles around an off-grid centre, with rim vertices at awkward sub-pixel
  // positions, some exactly on pixel centres; alternate windings too.
  const double cx = 31.3, cy = 23.7;
  std::vector<ShadedVertex> rim;
  for (int i = 0; i < 13; ++i) {
    const double a = 2 * std::numbers::pi * i / 13;
    const double r = i % 3 == 0 ? 20.0 : 17.77;
    rim.push_back(atWindow(std::round(cx + r * std::cos(a)) + (i % 2 ? 0.5 : 0.123), cy + r * std::sin(a)));
  }
  std::vector<std::array<ShadedVertex, 3>> fan;
  for (int i = 0; i < 13; ++i) {
    if (i % 2) fan.push_back({atWindow(cx, cy), rim[i], rim[(i + 1) % 13]});
    else fan.push_back({rim[(i + 1) % 13], rim[i], atWindow(cx, cy)});  // clockwise: a back face
  }
  const auto hits = coverage(fan);
  int covered = 0;
  for (int h : hits) {
    EXPECT_LE(h, 1);
    covered += h;
  }
  // Every pixel strictly inside the fan polygon is hit exactly once.
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const double px = x + 0.5 - cx, py = y + 0.5 - cy;
      if (px * px + py * py < 15 * 15) {
        EXPECT_EQ(hits[y * kW + x], 1) << x << "," << y;
      }
    }
  EXPECT_GT(covered, 900);
}

TEST(Rasterizer, TopLeftRuleOnPixelCentres) {
  // A square whose edges run exactly through pixel centres: x ∈ [2.5, 6.5], y ∈ [3.5, 7.5] (y up).
  // The left and top edges own their centres; the right and bottom edges do not.
  const auto a = atWindow(2.5, 3.5), b = atWindow(6.5, 3.5), c = atWindow(6.5, 7.5), d = atWindow(2.5, 7.5);
  const auto hits = coverage({{a, b, c}, {a, c, d}});
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const bool inside = x >= 2 && x <= 5 && y >= 4 && y <= 7;
      EXPECT_EQ(hits[y * kW + x], inside ? 1 : 0) << x << "," << y;
    }
}

TEST(Rasterizer, DegenerateTrianglesCoverNothing) {
  const auto hits = coverage({{atWindow(1, 1), atWindow(10, 10), atWindow(20, 20)}});
  for (int h : hits) EXPECT_EQ(h, 0);
}

Object emissive(Mesh mesh, Color3 colour) {
  Object o;
  o.mesh = std::make_shared<const Mesh>(std::move(mesh));
  o.material.ambient = {0, 0, 0, 1};
  o.material.diffuse = {0, 0, 0, 1};
  o.material.emission = Color4(colour, 1);
  return o;
}

Mesh quad(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  Mesh m;
  m.positions = {a, b, c, d};
  m.normals.assign(4, glm::normalize(glm::cross(b - a, d - a)));
  m.indices = {0, 1, 2, 0, 2, 3};
  return m;
}

TEST(Clipping, PlaneThroughTheNearPlaneKeepsItsCoverage) {
  // The floor y = −1 from z = +50 (behind the eye) to z = −50, seen from the origin looking
  // down −Z. A pixel is covered exactly when its ray meets the floor between the near plane and
  // z = −50; compare with that closed form away from the boundary.
  Scene s;
  s.width = 80;
  s.height = 60;
  s.camera.eye = {0, 0, 0};
  s.camera.center = {0, 0, -1};
  s.camera.near = 0.1f;
  s.camera.far = 100;
  s.objects.push_back(emissive(quad({-50, -1, 50}, {50, -1, 50}, {50, -1, -50}, {-50, -1, -50}), {1, 1, 1}));
  const Image img = renderScene(s);
  const double t = std::tan(glm::radians(45.0) / 2);
  const double aspect = 80.0 / 60.0;
  int checked = 0;
  for (int row = 0; row < s.height; ++row)
    for (int x = 0; x < s.width; ++x) {
      const double ndcX = (x + 0.5) / s.width * 2 - 1, ndcY = 1 - (row + 0.5) / s.height * 2;
      const double dx = ndcX * t * aspect, dy = ndcY * t;  // ray (dx, dy, −1)
      bool hit = false;
      double margin = 1;
      if (dy < 0) {
        const double depth = 1 / -dy;  // eye-space distance along −Z where the ray meets y = −1
        hit = depth <= 50 && std::abs(dx * depth) <= 50;
        margin = std::min(std::abs(depth - 50), std::abs(std::abs(dx * depth) - 50));
      } else {
        margin = std::abs(dy) * 100;
      }
      if (margin < 0.5) continue;  // too close to the boundary to call
      ++checked;
      EXPECT_EQ(img.pixel(x, row)[0], hit ? 255 : 0) << x << "," << row;
    }
  EXPECT_GT(checked, 4000);
}

TEST(Clipping, HugeTriangleBeyondTheGuardBandFillsTheScreen) {
  Scene s;
  s.width = 40;
  s.height = 30;
  s.objects.push_back(emissive(quad({-1e5f, -1e5f, 0}, {1e5f, -1e5f, 0}, {1e5f, 1e5f, 0}, {-1e5f, 1e5f, 0}), {0, 1, 0}));
  const Image img = renderScene(s);
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x) ASSERT_EQ(img.pixel(x, y)[1], 255) << x << "," << y;
}

TEST(Shading, SphereUnderDirectionalLightMatchesLambertPerPixel) {
  // Orthographic view of a unit sphere down −Z, light from +Z: the diffuse term at the pixel
  // whose centre is (x, y) is N·L = sqrt(1 − x² − y²).
  Scene s;
  s.width = s.height = 101;
  s.model = LightingModel::Lambert;
  s.shading = Shading::Phong;
  s.camera.projection = Projection::Orthographic;
  s.camera.viewHeight = 2.2f;
  s.lightModel.ambient = Color3(0);
  s.lights = {Light{}};  // directional from +Z
  Object o;
  o.mesh = std::make_shared<const Mesh>(makeSphere(1, 256, 128));
  o.material.ambient = {0, 0, 0, 1};
  o.material.diffuse = {1, 1, 1, 1};
  s.objects.push_back(o);
  const Image img = renderScene(s);
  int checked = 0, worst = 0;
  for (int row = 0; row < s.height; ++row)
    for (int col = 0; col < s.width; ++col) {
      const double x = ((col + 0.5) / s.width * 2 - 1) * 1.1, y = (1 - (row + 0.5) / s.height * 2) * 1.1;
      const double r2 = x * x + y * y;
      if (r2 > 0.95 * 0.95) continue;
      const int expected = int(std::lround(std::sqrt(1 - r2) * 255));
      worst = std::max(worst, std::abs(int(img.pixel(col, row)[0]) - expected));
      ++checked;
    }
  EXPECT_GT(checked, 5900);
  EXPECT_LE(worst, 2);
}

Scene oneTriangleScene(Shading shading, bool twoSided, bool facingAway) {
  Scene s;
  s.width = s.height = 16;
  s.shading = shading;
  s.lightModel.ambient = Color3(0);
  s.lightModel.twoSided = twoSided;
  Light light;
  light.position = {0, 0, 1, 0};
  s.lights = {light};
  Mesh m;
  // A triangle in the z = 0 plane covering the centre; its normals face +Z or −Z.
  m.positions = {{-3, -3, 0}, {3, -3, 0}, {0, 3, 0}};
  m.normals.assign(3, Vec3(0, 0, facingAway ? -1 : 1));
  m.indices = facingAway ? std::vector<std::uint32_t>{0, 2, 1} : std::vector<std::uint32_t>{0, 1, 2};
  Object o;
  o.mesh = std::make_shared<const Mesh>(m);
  o.material.ambient = {0, 0, 0, 1};
  o.material.diffuse = {0.4, 0.4, 0.4, 1};
  s.objects.push_back(o);
  return s;
}

TEST(Shading, TwoSidedLightingLightsBackFacesWithMinusN) {
  for (Shading shading : {Shading::Flat, Shading::Gouraud, Shading::Phong}) {
    // Back face (clockwise on screen), normal pointing away from the light and viewer.
    EXPECT_EQ(renderScene(oneTriangleScene(shading, true, true)).pixel(8, 8)[0], 102);  // −N faces the light
    EXPECT_EQ(renderScene(oneTriangleScene(shading, false, true)).pixel(8, 8)[0], 0);   // one-sided: dark
    EXPECT_EQ(renderScene(oneTriangleScene(shading, true, false)).pixel(8, 8)[0], 102);  // front face: N
  }
}

TEST(Shading, FlatUsesTheLastVertex) {
  Scene s = oneTriangleScene(Shading::Flat, false, false);
  Mesh m = *s.objects[0].mesh;
  const Real c60 = std::cos(glm::radians(Real(60)));
  m.normals = {{0, 0, 1}, {0, 0, 1}, {std::sin(glm::radians(Real(60))), 0, c60}};  // last vertex: N·L = 0.5
  s.objects[0].mesh = std::make_shared<const Mesh>(m);
  const Image img = renderScene(s);
  EXPECT_EQ(img.pixel(8, 8)[0], std::lround(0.4 * 0.5 * 255));
  EXPECT_EQ(img.pixel(8, 12)[0], std::lround(0.4 * 0.5 * 255));
}

TEST(Render, LabelsAreDrawnOverThePicture) {
  Scene s;
  s.width = 120;
  s.height = 40;
  Label title;
  title.text = "N·L";
  title.pixel = Vec2(60, 28);
  title.size = 20;
  s.labels.push_back(title);
  Label behind;
  behind.text = "behind the camera";
  behind.position = Vec3(0, 0, 10);  // the default camera sits at z = 5 looking towards −Z
  s.labels.push_back(behind);
  RenderStats stats;
  const Image img = renderScene(s, &stats);
  ASSERT_FALSE(stats.labelsSkipped) << "install fonts-dejavu-core";
  int lit = 0, minX = s.width, maxX = 0;
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x)
      if (img.pixel(x, y)[0] > 128) {
        ++lit;
        minX = std::min(minX, x);
        maxX = std::max(maxX, x);
      }
  EXPECT_GT(lit, 40);
  EXPECT_NEAR((minX + maxX) / 2.0, 60, 3);  // centred on its pixel
  EXPECT_LT(maxX - minX, 60);               // only the short title; nothing from behind the camera
}

TEST(Render, BlendingDrawsTranslucentObjectsOverOpaqueOnes) {
  // A half-transparent red quad in front of an opaque blue one, listed first in the scene.
  Scene s;
  s.width = s.height = 8;
  s.blend = true;
  Object front = emissive(quad({-5, -5, 1}, {5, -5, 1}, {5, 5, 1}, {-5, 5, 1}), {1, 0, 0});
  front.material.diffuse.a = 0.5f;
  s.objects.push_back(front);
  s.objects.push_back(emissive(quad({-5, -5, -1}, {5, -5, -1}, {5, 5, -1}, {-5, 5, -1}), {0, 0, 1}));
  const Image img = renderScene(s);
  const std::uint8_t* p = img.pixel(4, 4);
  EXPECT_EQ(p[0], 128);  // 1·0.5 + 0·0.5
  EXPECT_EQ(p[2], 128);  // 0·0.5 + 1·0.5
  EXPECT_EQ(p[3], 255);  // over an opaque background the result stays opaque
  // Without blending GL writes the fragment as it is, alpha included; the front quad, drawn
  // first, hides the blue one by the depth test.
  s.blend = false;
  const Image plain = renderScene(s);
  EXPECT_EQ(plain.pixel(4, 4)[0], 255);
  EXPECT_EQ(plain.pixel(4, 4)[2], 0);
  EXPECT_EQ(plain.pixel(4, 4)[3], 128);
}

TEST(Render, SameBytesEveryRun) {
  const Scene s = defaultScene();
  EXPECT_EQ(renderScene(s).rgba, renderScene(s).rgba);
}

// A row's span (RowSpans, stepped from row to row in double) keeps every pixel that has a sample
// inside the triangle, as the exact integer test finds it, on thin slivers and wide triangles at 4
// and 8 samples; and it does narrow: over the slivers' bounds it keeps under half the pixels.
TEST(RowSpans, KeepEveryPixelWithACoveredSampleAndNarrowTheRest) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> at(-8, 72), nudge(-0.6, 0.6);
  for (const int count : {4, 8}) {
    const std::span<const SubpixelOffset> pattern = multisamplePattern(count);
    long kept = 0, bounded = 0;
    for (int n = 0; n < 3000; ++n) {
      const bool sliver = n % 2 == 0;
      const double x0 = at(rng), y0 = at(rng) * kH / kW;
      const double x1 = sliver ? x0 + nudge(rng) * 40 : at(rng), y1 = sliver ? y0 + 30 + nudge(rng) : at(rng) * kH / kW;
      const double x2 = sliver ? x1 + nudge(rng) * 2 : at(rng), y2 = sliver ? y1 + nudge(rng) : at(rng) * kH / kW;
      TriangleSetup t;
      if (!setupTriangle(atWindow(x0, y0), atWindow(x1, y1), atWindow(x2, y2), kW, kH, t)) continue;
      const RowSpans spans(t, pattern, t.minX, t.minY);
      const int rows = t.maxY - t.minY + 1;
      std::vector<std::int32_t> firsts(std::size_t(rows + kRowSpansRoom)), lasts(firsts.size());
      narrowRows(spans, t, rows, t.maxX, firsts.data(), lasts.data());
      for (int y = t.minY; y <= t.maxY; ++y) {
        const int first = firsts[std::size_t(y - t.minY)], last = lasts[std::size_t(y - t.minY)];
        const bool any = first <= last;
        for (int x = t.minX; x <= t.maxX; ++x) {
          const std::int64_t fx = std::int64_t(x) * kSubpixelOne + kSubpixelOne / 2;
          const std::int64_t fy = std::int64_t(y) * kSubpixelOne + kSubpixelOne / 2;
          bool covered = false;
          for (const SubpixelOffset& o : pattern) {
            bool inside = true;
            for (const EdgeFunction& e : t.edge)
              inside = inside && e.at(fx, fy) + std::int64_t(e.a) * o.x + std::int64_t(e.b) * o.y + e.bias >= 0;
            covered = covered || inside;
          }
          if (covered) {
            EXPECT_TRUE(any && first <= x && x <= last) << count << " samples, triangle " << n << ": pixel (" << x
                                                        << ", " << y << ") has a sample inside, span " << first << ".."
                                                        << last;
          }
        }
        if (sliver) bounded += t.maxX - t.minX + 1, kept += any ? last - first + 1 : 0;
      }
    }
    EXPECT_LT(kept * 2, bounded) << count << " samples";
  }
}

}  // namespace
}  // namespace illum
