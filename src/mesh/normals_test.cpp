#include <illum/mesh.h>

#include <gtest/gtest.h>

#include <cmath>

namespace illum {
namespace {

// A unit cube as an STL would store it: 12 triangles, no shared vertices.
Mesh cubeSoup() {
  const Mesh indexed = makeCube(2);
  Mesh soup;
  for (std::uint32_t i : indexed.indices) {
    soup.positions.push_back(indexed.positions[i]);
    soup.indices.push_back(std::uint32_t(soup.indices.size()));
  }
  soup.normals.assign(soup.positions.size(), Vec3(0));
  return soup;
}

TEST(CreaseNormals, CubeEdgesStaySharpBelowNinetyDegrees) {
  Mesh m = cubeSoup();
  generateCreaseNormals(m, 40);
  ASSERT_EQ(m.indices.size(), 36u);
  EXPECT_EQ(m.positions.size(), 24u);  // four corners per face, shared within the face only
  for (std::size_t t = 0; t < m.indices.size(); t += 3) {
    const Vec3 face = glm::normalize(glm::cross(m.positions[m.indices[t + 1]] - m.positions[m.indices[t]],
                                                m.positions[m.indices[t + 2]] - m.positions[m.indices[t]]));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(glm::dot(m.normals[m.indices[t + std::size_t(c)]], face), 1, 1e-5);
  }
}

TEST(CreaseNormals, AboveTheCreaseAngleCornersAreSmoothed) {
  Mesh m = cubeSoup();
  generateCreaseNormals(m, 180);
  EXPECT_EQ(m.positions.size(), 8u);
  // Every face meets a corner at 90°, so each corner normal points along the diagonal.
  for (std::size_t i = 0; i < m.positions.size(); ++i)
    EXPECT_NEAR(glm::dot(m.normals[i], glm::normalize(m.positions[i])), 1, 1e-5);
}

TEST(CreaseNormals, KeepsUvsAndColoursWithTheirVertices) {
  Mesh m = cubeSoup();
  for (const Vec3& p : m.positions) {
    m.uvs.push_back({p.x, p.y});
    m.colors.push_back({p.x, p.y, p.z, 1});
  }
  generateCreaseNormals(m, 40);
  ASSERT_EQ(m.uvs.size(), m.positions.size());
  ASSERT_EQ(m.colors.size(), m.positions.size());
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    EXPECT_EQ(m.uvs[i], Vec2(m.positions[i].x, m.positions[i].y));
    EXPECT_EQ(Vec3(m.colors[i]), m.positions[i]);
  }
}

TEST(FlatNormals, EveryTriangleGetsItsFaceNormal) {
  Mesh m = makeSphere(1, 8, 6);
  generateFlatNormals(m);
  EXPECT_EQ(m.positions.size(), m.indices.size());
  for (std::size_t t = 0; t < m.indices.size(); t += 3) {
    const Vec3 face = glm::normalize(glm::cross(m.positions[t + 1] - m.positions[t], m.positions[t + 2] - m.positions[t]));
    EXPECT_NEAR(glm::dot(m.normals[t], face), 1, 1e-5);
  }
}

TEST(SmoothNormals, SphereNormalsPointOutwards) {
  Mesh m = makeSphere(2, 16, 12);
  const auto n = generateSmoothNormals(m.positions, m.indices);
  for (std::size_t i = 0; i < n.size(); ++i) EXPECT_NEAR(glm::dot(n[i], glm::normalize(m.positions[i])), 1, 0.02);
}

// GLUT's solids are counter-clockwise from outside: every triangle's face agrees with its normals.
TEST(Primitives, FrontFacesAreCounterClockwiseAndNormalsUnit) {
  for (const Mesh& m : {makeSphere(1, 20, 16), makeCube(1), makeTorus(0.3f, 1, 16, 32), makeCone(1, 2, 20, 8),
                        makeTeapot(1)}) {
    ASSERT_EQ(m.normals.size(), m.positions.size());
    ASSERT_FALSE(m.indices.empty());
    for (const Vec3& n : m.normals) EXPECT_NEAR(glm::length(n), 1, 1e-4);
    int disagreeing = 0;
    for (std::size_t t = 0; t < m.indices.size(); t += 3) {
      const Vec3 face = glm::cross(m.positions[m.indices[t + 1]] - m.positions[m.indices[t]],
                                   m.positions[m.indices[t + 2]] - m.positions[m.indices[t]]);
      if (glm::length(face) < 1e-9f) continue;  // the cone's apex ring: zero area, never drawn
      if (glm::dot(face, m.normals[m.indices[t]] + m.normals[m.indices[t + 1]] + m.normals[m.indices[t + 2]]) <= 0)
        ++disagreeing;
    }
    EXPECT_EQ(disagreeing, 0);
  }
}

TEST(Primitives, GlutSizes) {
  const Mesh sphere = makeSphere(2, 20, 16);
  for (const Vec3& p : sphere.positions) EXPECT_NEAR(glm::length(p), 2, 1e-5);
  const Mesh cube = makeCube(3);
  for (const Vec3& p : cube.positions) EXPECT_NEAR(std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}), 1.5, 1e-6);
  const Mesh cone = makeCone(1, 2, 20, 8);
  Real top = 0;
  for (const Vec3& p : cone.positions) top = std::max(top, p.z);
  EXPECT_NEAR(top, 2, 1e-6);
  const Mesh torus = makeTorus(0.25f, 1, 16, 32);
  for (const Vec3& p : torus.positions) {
    const Real ring = std::sqrt(p.x * p.x + p.y * p.y) - 1;
    EXPECT_NEAR(std::sqrt(ring * ring + p.z * p.z), 0.25, 1e-5);
  }
  // glutSolidTeapot(1): the body's widest ring (control radius 2 at scale 1/2) reaches 1.
  const Mesh teapot = makeTeapot(1);
  Real widestBody = 0;
  for (const Vec3& p : teapot.positions)
    if (std::abs(p.x) < 1e-6f) widestBody = std::max(widestBody, std::abs(p.z));
  EXPECT_NEAR(widestBody, 1, 1e-3);
}

// A triangle soup (every triangle with vertices of its own, as STL stores them) is welded by
// position, −0 and +0 alike: the shared vertices get one smooth normal.
TEST(CreaseNormals, SoupIsWeldedByPositionIncludingSignedZeros) {
  Mesh soup;
  // Two triangles folded 60° along the edge from (0,0,0) to (0,1,0); the second spells 0 as −0.
  soup.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-0.0f, 0, -0.0f}, {0, 1, -0.0f}, {-0.5f, 0, 0.866025f}};
  soup.indices = {0, 1, 2, 3, 4, 5};
  generateCreaseNormals(soup, 90);
  // The edge's two positions each become one vertex shared by both triangles.
  EXPECT_EQ(soup.positions.size(), 4u);
  const Vec3 n = soup.normals[soup.indices[0]];
  EXPECT_EQ(soup.indices[0], soup.indices[3]);
  EXPECT_NEAR(glm::length(n), 1, 1e-6);
  EXPECT_GT(n.x, 0.2f);  // between the two faces' normals, (0,0,1) and (0.87,0,0.5)
  EXPECT_GT(n.z, 0.6f);
}

}  // namespace
}  // namespace illum
