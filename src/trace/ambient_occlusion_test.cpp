// Ambient occlusion against closed forms: an open plane keeps all of its ambient light, a floor
// beside a wall keeps half (the wall hides half of the cosine-weighted hemisphere), and in the
// corner of two walls a quarter; per pixel under Phong shading, per vertex under flat and Gouraud.
#include "trace/ambient_occlusion.h"

#include <illum/render.h>
#include <illum/scene.h>

#include <gtest/gtest.h>
#include <tbb/global_control.h>

namespace illum {
namespace {

// A quad p0 p1 p2 p3, counter-clockwise seen from its front, lit by ambient light alone.
Object plane(Vec3 p0, Vec3 p1, Vec3 p2, Vec3 p3) {
  auto m = std::make_shared<Mesh>();
  m->positions = {p0, p1, p2, p3};
  m->normals.assign(4, glm::normalize(glm::cross(p1 - p0, p2 - p0)));
  m->indices = {0, 1, 2, 0, 2, 3};
  Object o;
  o.mesh = m;
  o.material.ambient = {0.8f, 0.8f, 0.8f, 1};
  o.material.diffuse = {0, 0, 0, 1};
  return o;
}

// Looking straight down at the floor y = 0 around the origin.
Scene floorScene() {
  Scene s;
  s.width = s.height = 64;
  s.lights.clear();
  s.lightModel.ambient = Color3(1);
  s.camera.projection = Projection::Orthographic;
  s.camera.eye = {0, 10, 0};
  s.camera.up = {0, 0, -1};
  s.camera.viewHeight = 2;
  const Real far = 500;
  s.objects.push_back(plane({-far, 0, far}, {far, 0, far}, {far, 0, -far}, {-far, 0, -far}));
  s.ambientOcclusion.rays = 64;
  s.ambientOcclusion.distance = 1000;
  return s;
}

// The mean red byte of the pixels in columns [x0, x1) and rows [y0, y1).
double meanRed(const Image& image, int x0, int x1, int y0, int y1) {
  double sum = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) sum += image.pixel(x, y)[0];
  return sum / double((x1 - x0) * (y1 - y0));
}

TEST(AmbientOcclusion, AnOpenPlaneKeepsAllItsAmbientLight) {
  Scene s = floorScene();
  const Image off = renderScene(s);
  EXPECT_EQ(off.pixel(32, 32)[0], 204);  // 0.8
  s.ambientOcclusion.enabled = true;
  EXPECT_EQ(renderScene(s).rgba, off.rgba);
}

TEST(AmbientOcclusion, AWallHidesHalfAndTwoWallsThreeQuarters) {
  Scene s = floorScene();
  s.ambientOcclusion.enabled = true;
  const Real far = 500, high = 500;
  // The wall x = 0 facing +x (seen edge-on from above): the floor at x > 0 right beside it.
  s.objects.push_back(plane({0, 0, far}, {0, 0, -far}, {0, high, -far}, {0, high, far}));
  const Image one = renderScene(s);
  // Columns 33..40 are x in (0.03, 0.28): beside the wall, far nearer than the rays reach.
  EXPECT_NEAR(meanRed(one, 33, 41, 8, 56), 0.8 * 0.5 * 255, 4);
  EXPECT_NEAR(meanRed(one, 2, 30, 8, 56), 0.8 * 0.5 * 255, 4);  // the other side has the wall's back
  // A second wall z = 0 facing +z: the quarter x > 0, z > 0 (rows below the middle) sees a quarter.
  s.objects.push_back(plane({-far, 0, 0}, {far, 0, 0}, {far, high, 0}, {-far, high, 0}));
  const Image two = renderScene(s);
  EXPECT_NEAR(meanRed(two, 34, 44, 34, 44), 0.8 * 0.25 * 255, 4);
  // The same bytes on one thread.
  const tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
  EXPECT_EQ(renderScene(s).rgba, two.rgba);
}

// Flat and Gouraud shading light the vertices: each vertex's ambient is occluded as seen from it,
// and the pixels between take the vertices' colours. A strip of floor beside a wall, every vertex
// far nearer the wall than its size, keeps half at every vertex, so everywhere.
TEST(AmbientOcclusion, VerticesLitBesideAWallKeepHalf) {
  for (Shading shading : {Shading::Flat, Shading::Gouraud}) {
    Scene s = floorScene();
    s.shading = shading;
    s.objects.clear();
    // (The wall reaches far past the strip's ends, which its rays, 1000 long, never see beyond.)
    s.objects.push_back(plane({0.01f, 0, 500}, {0.3f, 0, 500}, {0.3f, 0, -500}, {0.01f, 0, -500}));
    s.objects.push_back(plane({0, 0, 5000}, {0, 0, -5000}, {0, 5000, -5000}, {0, 5000, 5000}));
    const Image off = renderScene(s);
    EXPECT_EQ(off.pixel(36, 32)[0], 204) << toString(shading);
    s.ambientOcclusion.enabled = true;
    EXPECT_NEAR(meanRed(renderScene(s), 33, 41, 8, 56), 0.8 * 0.5 * 255, 8) << toString(shading);
  }
}

// Multisampled, each pixel is lit once per surface it shows, at its centre, with that surface's
// occlusion: a pixel a surface covers whole is as one sample draws it.
TEST(AmbientOcclusion, MultisampledPixelsKeepTheirOneSampleOcclusion) {
  Scene s = floorScene();
  s.ambientOcclusion.enabled = true;
  const Real far = 500, high = 500;
  s.objects.push_back(plane({0, 0, far}, {0, 0, -far}, {0, high, -far}, {0, high, far}));
  const Image one = renderScene(s);
  s.multisample = 8;
  const Image eight = renderScene(s);
  for (int y = 8; y < 56; ++y)
    for (int x = 34; x < 60; ++x) ASSERT_EQ(eight.pixel(x, y)[0], one.pixel(x, y)[0]) << x << "," << y;
}

TEST(AmbientOcclusion, OccludersBeyondTheDistanceDoNotCount) {
  Scene s = floorScene();
  s.ambientOcclusion.enabled = true;
  s.ambientOcclusion.distance = 0.01f;
  s.objects.push_back(plane({0, 0, 500}, {0, 0, -500}, {0, 500, -500}, {0, 500, 500}));
  const Image image = renderScene(s);
  EXPECT_NEAR(meanRed(image, 40, 60, 8, 56), 204, 0.5);  // x > 0.25: the wall is out of reach
}

}  // namespace
}  // namespace illum
