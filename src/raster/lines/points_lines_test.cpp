// GL_POINTS and GL_LINES: GL's shapes (aliased squares, multisampled discs, wide lines), the depth
// test against surfaces, GL's colours (unlit without normals, lit as a vertex with them), lines
// smooth-shaded between their ends.
#include "raster/lines/points_lines.h"

#include <illum/render.h>
#include <illum/scene.h>

#include <gtest/gtest.h>

#include <numbers>

namespace illum {
namespace {

constexpr int kSize = 64;

// An orthographic 64×64 view of [-1, 1]²: window x = (world x + 1)·32, the same for y.
Scene flatScene() {
  Scene s;
  s.width = s.height = kSize;
  s.camera.projection = Projection::Orthographic;
  s.camera.viewHeight = 2;
  return s;
}

Vec3 atWindow(Real x, Real y, Real z = 0) { return {x / 32 - 1, y / 32 - 1, z}; }

// The pixel at window (x, y), y up.
const std::uint8_t* at(const Image& image, int x, int y) { return image.pixel(x, kSize - 1 - y); }

int drawnPixels(const Image& image) {
  int n = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) n += image.pixel(x, y)[0] != 0 || image.pixel(x, y)[1] != 0;
  return n;
}

Object points(std::vector<Vec3> positions, const Color4& colour) {
  auto m = std::make_shared<Mesh>();
  m->positions = std::move(positions);
  for (std::uint32_t i = 0; i < m->positions.size(); ++i) m->pointIndices.push_back(i);
  Object o;
  o.mesh = m;
  o.material.diffuse = colour;
  return o;
}

// An unlit (emissive) square of half-size `half` at depth z.
Object square(Real half, Real z, const Color3& colour) {
  auto m = std::make_shared<Mesh>();
  m->positions = {{-half, -half, z}, {half, -half, z}, {half, half, z}, {-half, half, z}};
  m->normals.assign(4, Vec3(0, 0, 1));
  m->indices = {0, 1, 2, 0, 2, 3};
  Object o;
  o.mesh = m;
  o.material.ambient = o.material.diffuse = {0, 0, 0, 1};
  o.material.emission = Color4(colour, 1);
  return o;
}

TEST(PointsAndLines, AliasedPointsAreGlsSquares) {
  Scene s = flatScene();
  s.objects.push_back(points({atWindow(10.3f, 20.7f)}, {0.2f, 0.4f, 0.6f, 1}));
  // Size 1: the one pixel the point lies in, in the material's diffuse colour (no normals: unlit).
  Image image = renderScene(s);
  EXPECT_EQ(drawnPixels(image), 1);
  EXPECT_EQ(at(image, 10, 20)[0], 51);
  EXPECT_EQ(at(image, 10, 20)[1], 102);
  EXPECT_EQ(at(image, 10, 20)[2], 153);
  // Size 2: the pixels whose centres lie in [9.3, 11.3) × [19.7, 21.7).
  s.pointSize = 2;
  image = renderScene(s);
  EXPECT_EQ(drawnPixels(image), 4);
  for (int y : {20, 21})
    for (int x : {9, 10}) EXPECT_EQ(at(image, x, y)[0], 51) << x << "," << y;
  // Size 3: centred on the pixel the point lies in.
  s.pointSize = 3;
  image = renderScene(s);
  EXPECT_EQ(drawnPixels(image), 9);
  EXPECT_EQ(at(image, 9, 19)[0], 51);
  EXPECT_EQ(at(image, 11, 21)[0], 51);
}

TEST(PointsAndLines, MultisampledPointsAreDiscsOfTheirSize) {
  Scene s = flatScene();
  s.multisample = 16;
  s.pointSize = 12;
  s.objects.push_back(points({atWindow(32.3f, 30.6f)}, {1, 1, 1, 1}));
  const Image image = renderScene(s);
  double area = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) area += image.pixel(x, y)[0] / 255.0;
  EXPECT_NEAR(area, std::numbers::pi * 36, std::numbers::pi * 36 * 0.03);
  // Whole inside, edge-softened outside.
  EXPECT_EQ(at(image, 32, 30)[0], 255);
  EXPECT_EQ(at(image, 32, 23)[0], 0);
}

TEST(PointsAndLines, PointsAreHiddenBehindSurfacesAndShowInFront) {
  Scene s = flatScene();
  s.lights.clear();
  s.objects.push_back(square(0.5f, 0, {0, 0, 1}));
  s.objects.push_back(points({atWindow(30.5f, 30.5f, 0.5f), atWindow(34.5f, 34.5f, -0.5f)}, {1, 0, 0, 1}));
  const Image image = renderScene(s);
  EXPECT_EQ(at(image, 30, 30)[0], 255);  // in front of the square
  EXPECT_EQ(at(image, 34, 34)[0], 0);    // behind it
  EXPECT_EQ(at(image, 34, 34)[2], 255);
}

TEST(PointsAndLines, PointsWithNormalsAreLitAsGlLightsAVertex) {
  // A Gouraud-lit square whose every normal is n, under the default directional light and viewer
  // at infinity, is one colour: the colour of a vertex with normal n, which a point with n gets.
  const Vec3 n = glm::normalize(Vec3(0.6f, 0.3f, 0.8f));
  for (Shading shading : {Shading::Gouraud, Shading::Flat, Shading::Phong}) {
    Scene s = flatScene();
    s.shading = shading;
    Object quad = square(0.4f, 0, {0, 0, 0});
    auto m = std::make_shared<Mesh>(*quad.mesh);
    m->normals.assign(4, n);
    quad.mesh = m;
    quad.material = Material{};
    quad.material.specular = {0.5f, 0.5f, 0.5f, 1};
    quad.material.shininess = 20;
    Object point = points({atWindow(56.5f, 56.5f)}, {});
    auto pm = std::make_shared<Mesh>(*point.mesh);
    pm->normals = {n};
    point.mesh = pm;
    point.material = quad.material;
    s.objects = {quad, point};
    const Image image = renderScene(s);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(at(image, 56, 56)[c], at(image, 32, 32)[c], 1) << int(shading);
    EXPECT_GT(at(image, 56, 56)[0], 100);
  }
}

TEST(PointsAndLines, LinesAreSmoothShadedBetweenTheirEnds) {
  Scene s = flatScene();
  auto m = std::make_shared<Mesh>();
  m->positions = {atWindow(8, 32.5f), atWindow(56, 32.5f)};
  m->colors = {{1, 0, 0, 1}, {0, 0, 1, 1}};
  m->lineIndices = {0, 1};
  Object o;
  o.mesh = m;
  s.objects.push_back(o);
  Image image = renderScene(s);
  // Width 1 along row 32 only, from x = 8 to 56.
  EXPECT_EQ(at(image, 31, 31)[0] + at(image, 31, 33)[0], 0);
  const Real t = (Real(32.5) - 8) / 48;
  EXPECT_NEAR(at(image, 32, 32)[0], (1 - t) * 255, 1);
  EXPECT_NEAR(at(image, 32, 32)[2], t * 255, 1);
  EXPECT_NEAR(at(image, 8, 32)[0], 255, 3);
  EXPECT_EQ(at(image, 4, 32)[0], 0);
  // Wider: three rows.
  s.lineWidth = 3;
  image = renderScene(s);
  EXPECT_GT(at(image, 32, 31)[0], 0);
  EXPECT_GT(at(image, 32, 33)[0], 0);
  EXPECT_EQ(at(image, 32, 35)[0], 0);
  // Flat shading: the second (provoking) vertex's colour throughout.
  s.shading = Shading::Flat;
  image = renderScene(s);
  EXPECT_EQ(at(image, 20, 32)[0], 0);
  EXPECT_EQ(at(image, 20, 32)[2], 255);
}

TEST(PointsAndLines, LineColoursArePerspectiveCorrect) {
  // A line from z = 0 to z = −20 seen in perspective: its far part is foreshortened, so its window
  // midpoint lies near its near end in the world, and the colour there is mostly the near end's
  // (a window-space mix would be half and half).
  Scene s;
  s.width = s.height = kSize;
  s.camera.eye = {0, 2, 5};
  s.camera.center = {0, 0, -5};
  auto m = std::make_shared<Mesh>();
  m->positions = {{0, 0, 0}, {0, 0, -20}};
  m->colors = {{1, 0, 0, 1}, {0, 0, 1, 1}};
  m->lineIndices = {0, 1};
  Object o;
  o.mesh = m;
  s.objects.push_back(o);
  const Image image = renderScene(s);
  // The closed form: window-space t maps to u = (t/w1) / ((1 − t)/w0 + t/w1) along the line.
  const Mat4 clip = s.camera.clipFromView(1) * s.camera.viewFromWorld();
  const Vec4 a = clip * Vec4(0, 0, 0, 1), b = clip * Vec4(0, 0, -20, 1);
  const Real ya = (a.y / a.w + 1) * 32, yb = (b.y / b.w + 1) * 32;
  const int row = int((ya + yb) / 2);
  const Real t = (Real(row) + Real(0.5) - ya) / (yb - ya);
  const Real u = (t / b.w) / ((1 - t) / a.w + t / b.w);
  EXPECT_LT(u, Real(0.3));
  EXPECT_NEAR(at(image, 32, row)[2], u * 255, 2);
  EXPECT_NEAR(at(image, 32, row)[0], (1 - u) * 255, 2);
}

}  // namespace
}  // namespace illum
