// The SIMD vertex transform computes, on every target, the bits of the one-vertex formulas: glm's
// products, clipOutcode and toWindow, over random vertices, vertices beyond every clip plane,
// behind the eye, at infinity and not a number, and zero normals.
#include "raster/setup/vertex_transform.h"

#include "math/transform.h"
#include "raster/setup/clip.h"
#include "raster/setup/setup.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <cstring>
#include <limits>
#include <random>
#include <vector>

namespace illum {
namespace {

bool sameBits(Real a, Real b) { return std::memcmp(&a, &b, sizeof(Real)) == 0; }

TEST(VertexTransform, EveryTargetComputesTheScalarFormulasBits) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<Real> u(-1, 1);
  const int width = 641, height = 479;
  const Mat4 view = glm::lookAt(Vec3(1, 2, 6), Vec3(0.2f, -0.1f, 0), Vec3(0, 1, 0));
  const Mat4 model = glm::rotate(glm::translate(Mat4(1), Vec3(0.3f, -0.2f, 0.1f)), Real(0.7), glm::normalize(Vec3(1, 2, 3))) *
                     glm::scale(Mat4(1), Vec3(1.5f, 0.8f, 1.1f));
  VertexTransform t;
  t.viewFromObject = view * model;
  t.clipFromObject = glm::perspective(Real(0.9), Real(width) / Real(height), Real(0.5), Real(30)) * t.viewFromObject;
  t.normalFromObject = normalMatrix(t.viewFromObject);
  t.width = width, t.height = height;

  // 251 vertices (not a whole number of vectors): random ones, far beyond the sides and the far
  // plane, behind the eye, on it, and not finite; some normals zero.
  std::vector<Vec3> positions, normals;
  const Real inf = std::numeric_limits<Real>::infinity(), nan = std::numeric_limits<Real>::quiet_NaN();
  for (int i = 0; i < 251; ++i) {
    Vec3 p(2 * u(rng), 2 * u(rng), 2 * u(rng));
    if (i % 17 == 3) p *= Real(5000);
    if (i % 23 == 5) p = Vec3(1, 2, 6) + Real(0.001) * p;  // about the eye
    if (i == 7) p.x = inf;
    if (i == 8) p.y = -inf;
    if (i == 9) p.z = nan;
    positions.push_back(p);
    normals.push_back(i % 11 == 0 ? Vec3(0) : Vec3(u(rng), u(rng), u(rng)));
  }
  int targets = 0;
  for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
    hwy::SetSupportedTargetsForTest(target);
    ++targets;
    TransformedVertices out;
    transformVertices(t, positions.data(), normals.data(), positions.size(), out);
    int inside = 0;
    for (std::size_t k = 0; k < positions.size(); ++k) {
      const Vec4 p(positions[k], 1);
      const Vec4 clip = t.clipFromObject * p;
      const Vec3 eye = Vec3(t.viewFromObject * p);
      Vec3 n = t.normalFromObject * normals[k];
      const Real len = glm::length(n);
      if (len > 0) n = n / len;
      const std::string where = "vertex " + std::to_string(k) + " on " + hwy::TargetName(target);
      for (int c = 0; c < 4; ++c) EXPECT_TRUE(sameBits(out.clip[c][k], clip[c])) << where;
      for (int c = 0; c < 3; ++c) EXPECT_TRUE(sameBits(out.eye[c][k], eye[c])) << where;
      for (int c = 0; c < 3; ++c) EXPECT_TRUE(sameBits(out.normal[c][k], n[c])) << where;
      const unsigned code = clipOutcode(clip, width, height);
      EXPECT_EQ(out.outcode[k], code) << where;
      if (code != 0) continue;
      ++inside;
      const WindowPosition w = toWindow(clip, width, height);
      EXPECT_EQ(out.windowX[k], w.x) << where;
      EXPECT_EQ(out.windowY[k], w.y) << where;
      EXPECT_TRUE(sameBits(out.windowZ[k], w.z)) << where;
      EXPECT_TRUE(sameBits(out.invW[k], w.invW)) << where;
    }
    EXPECT_GT(inside, 150);
    EXPECT_LT(inside, 240);
  }
  hwy::SetSupportedTargetsForTest(0);
  EXPECT_GE(targets, 2);
}

}  // namespace
}  // namespace illum
