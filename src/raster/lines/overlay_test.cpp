// Overlays: edges where the triangles meet and hidden where a surface is in front, a grid below
// the scene, and the axes gizmo in the corner of every renderer's picture.
#include "raster/lines/overlay.h"

#include <illum/render.h>
#include <illum/scene.h>

#include <gtest/gtest.h>

namespace illum {
namespace {

// A flat, unlit (emissive) quad at depth z, with its diagonal from corner 0 to corner 2.
Object quad(Real half, Real z, bool antiDiagonal, const Color3& colour) {
  auto m = std::make_shared<Mesh>();
  m->positions = {{-half, -half, z}, {half, -half, z}, {half, half, z}, {-half, half, z}};
  m->normals.assign(4, Vec3(0, 0, 1));
  m->indices = antiDiagonal ? std::vector<std::uint32_t>{1, 2, 3, 1, 3, 0} : std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3};
  Object o;
  o.mesh = m;
  o.material.ambient = o.material.diffuse = {0, 0, 0, 1};
  o.material.emission = Color4(colour, 1);
  return o;
}

Scene flatScene() {
  Scene s;
  s.width = s.height = 64;
  s.lights.clear();
  s.camera.projection = Projection::Orthographic;
  s.camera.viewHeight = 2;
  return s;
}

bool isInk(const std::uint8_t* p) { return p[0] < 30 && p[1] < 30 && p[2] < 30; }

TEST(Overlay, EdgesShowWhereTrianglesMeetAndHideBehindSurfaces) {
  Scene s = flatScene();
  s.objects.push_back(quad(0.9f, -0.5f, false, {0.8f, 0.8f, 0.8f}));  // behind, its diagonal ↗
  s.objects.push_back(quad(0.5f, 0, true, {0.9f, 0.3f, 0.3f}));       // in front, its diagonal ↖
  const Image plain = renderScene(s);
  s.overlays.edges = true;
  const Image edged = renderScene(s);
  // The back quad's diagonal shows outside the front quad (x = y, row 0 at the top: x = 63 − row).
  EXPECT_TRUE(isInk(edged.pixel(8, 55)));
  EXPECT_FALSE(isInk(plain.pixel(8, 55)));
  // ... and is hidden where the front quad covers it, which shows its own anti-diagonal.
  EXPECT_EQ(edged.pixel(26, 37)[0], plain.pixel(26, 37)[0]);
  EXPECT_TRUE(isInk(edged.pixel(26, 26)) || isInk(edged.pixel(26, 27)) || isInk(edged.pixel(27, 26)));
  // Outlines: the front quad's border at x = ±0.5 (pixels 16 and 47).
  EXPECT_TRUE(isInk(edged.pixel(16, 32)) || isInk(edged.pixel(15, 32)));
  // Anti-aliased with multisampling, the same lines.
  s.multisample = 8;
  EXPECT_LT(renderScene(s).pixel(8, 55)[0], 128);
}

TEST(Overlay, TheGridLiesBelowTheSceneAndBehindIt) {
  Scene s = flatScene();
  s.width = 96;
  s.camera.projection = Projection::Perspective;
  s.camera.eye = {0, 3, 4};
  s.camera.up = {0, 1, 0};
  Object box = quad(0.5f, 0, false, {0.2f, 0.6f, 0.9f});  // standing up, facing the camera
  s.objects.push_back(box);
  const Image plain = renderScene(s);
  s.overlays.grid = true;
  const Image grid = renderScene(s);
  int changed = 0, changedInside = 0;
  for (int y = 0; y < grid.height; ++y)
    for (int x = 0; x < grid.width; ++x) {
      const bool differs = grid.pixel(x, y)[0] != plain.pixel(x, y)[0];
      changed += differs;
      // The quad's own pixels (bright blue) never change: the grid is behind or below it.
      if (plain.pixel(x, y)[2] > 200) changedInside += differs;
    }
  EXPECT_GT(changed, 100);
  EXPECT_EQ(changedInside, 0);
  // The lines lie on the plane y = −0.5, the quad's lowest point: the picture above the quad's
  // top edge (rows near the top of the picture) shows none... beyond the grid's far edge, rows at
  // the very top stay background.
  int top = 0;
  for (int x = 0; x < grid.width; ++x) top += grid.pixel(x, 0)[0] != plain.pixel(x, 0)[0];
  EXPECT_EQ(top, 0);
}

TEST(Overlay, AxesInTheCornerOfEveryRenderersPicture) {
  for (RendererKind renderer : {RendererKind::Raster, RendererKind::Whitted}) {
    Scene s = flatScene();
    s.renderer = renderer;
    s.width = s.height = 160;
    s.objects.push_back(quad(0.2f, 0, false, {0.5f, 0.5f, 0.5f}));
    s.overlays.axes = true;
    const Image image = renderScene(s);
    int red = 0, green = 0;
    for (int y = 80; y < 160; ++y)
      for (int x = 0; x < 80; ++x) {
        const std::uint8_t* p = image.pixel(x, y);
        red += p[0] > 150 && p[1] < 100;
        green += p[1] > 150 && p[0] < 120;
      }
    // Seen from +Z: X points right, Y up; both drawn.
    EXPECT_GT(red, 10) << toString(renderer);
    EXPECT_GT(green, 10) << toString(renderer);
  }
}

TEST(Overlay, LinesAreEachEdgeOnce) {
  Scene s = flatScene();
  s.objects.push_back(quad(1, 0, false, Color3(1)));
  s.overlays.edges = true;
  EXPECT_EQ(overlayLines(s).size(), 5u);  // 4 sides and the diagonal
}

}  // namespace
}  // namespace illum
