// Perspective-correct interpolation against closed forms: a quad slanted away from the camera,
// whose attributes are linear on its plane. For every pixel the expected value is found by
// casting the pixel centre's ray onto the plane; screen-space (affine) interpolation would be off
// by far more than the tolerance. And texel centres: a texture mapped one texel to one pixel
// comes back exactly.
#include <illum/render.h>
#include <illum/scene.h>

#include <gtest/gtest.h>

#include <cmath>

namespace illum {
namespace {

constexpr int kW = 96, kH = 96;

// A quad on the plane y = −1, from z = −1.5 (near) to z = −12 (far), x in [−2, 2]: with the
// camera at the origin looking down −Z it fills the lower half of the view and recedes steeply.
Scene slantedQuad() {
  Scene s;
  s.width = kW, s.height = kH;
  s.background = {0, 0, 0, 1};
  s.camera.eye = {0, 0, 0};
  s.camera.center = {0, 0, -1};
  s.camera.fovy = 60;
  s.camera.near = 0.5;
  s.camera.far = 50;
  s.lights.clear();                      // colour = global ambient × vertex colour
  s.lightModel.ambient = {1, 1, 1};
  s.shading = Shading::Gouraud;
  auto mesh = std::make_shared<Mesh>();
  mesh->positions = {{-2, -1, -1.5f}, {2, -1, -1.5f}, {2, -1, -12}, {-2, -1, -12}};
  mesh->normals.assign(4, Vec3(0, 1, 0));
  mesh->uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  mesh->indices = {0, 1, 2, 0, 2, 3};
  Object o;
  o.mesh = mesh;
  o.material.emission = {0, 0, 0, 1};
  s.objects.push_back(o);
  return s;
}

// Where the ray through pixel centre (x, y) (image rows from the top) meets the plane y = −1.
std::optional<Vec3> hitOnPlane(const Scene& s, int x, int y) {
  const double t = std::tan(double(s.camera.fovy) * M_PI / 360);
  const double aspect = double(s.width) / s.height;
  const double nx = (2 * (x + 0.5) / s.width - 1) * t * aspect;
  const double ny = (1 - 2 * (y + 0.5) / s.height) * t;
  if (ny >= 0) return std::nullopt;
  const double k = -1 / ny;  // ray (nx, ny, −1)·k reaches y = −1
  return Vec3(Real(nx * k), -1, Real(-k));
}

TEST(PerspectiveCorrect, GouraudRampFollowsThePlaneNotTheScreen) {
  Scene s = slantedQuad();
  // Red grows from 0 at the near edge to 1 at the far edge: linear in z on the plane.
  auto mesh = std::make_shared<Mesh>(*s.objects[0].mesh);
  mesh->colors = {{0, 0, 0, 1}, {0, 0, 0, 1}, {1, 0, 0, 1}, {1, 0, 0, 1}};
  s.objects[0].mesh = mesh;
  const Image image = renderScene(s);
  int checked = 0, worst = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const auto p = hitOnPlane(s, x, y);
      // Well inside the quad, away from its edges.
      if (!p || std::abs(p->x) > 1.9f || p->z > -1.6f || p->z < -11.9f) continue;
      const double expected = (-1.5 - double(p->z)) / (12 - 1.5) * 255;
      const int error = int(std::abs(image.pixel(x, y)[0] - expected) + 0.5);
      worst = std::max(worst, error);
      ++checked;
    }
  EXPECT_GT(checked, 1000);
  EXPECT_LE(worst, 1);  // affine interpolation is off by tens of steps here
}

TEST(PerspectiveCorrect, CheckerTextureCellsLandWhereTheGeometrySays) {
  Scene s = slantedQuad();
  // 4×4 cells of 16×16 texels, black and white: bilinear filtering inside a cell is exact.
  constexpr int kCells = 4, kCell = 16;
  Image checker(kCells * kCell, kCells * kCell);
  for (int y = 0; y < checker.height; ++y)
    for (int x = 0; x < checker.width; ++x) {
      const std::uint8_t v = ((x / kCell + y / kCell) % 2) ? 255 : 0;
      std::uint8_t* p = checker.pixel(x, y);
      p[0] = p[1] = p[2] = v, p[3] = 255;
    }
  s.objects[0].diffuseTexture = std::make_shared<const Texture>(checker);
  s.objects[0].material.ambient = {1, 1, 1, 1};  // lit white: the texel is the colour
  const Image image = renderScene(s);
  int checked = 0, wrong = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const auto p = hitOnPlane(s, x, y);
      if (!p || std::abs(p->x) > 1.9f || p->z > -1.6f || p->z < -6) continue;
      // uv on the plane: u across x, v along depth (GL: v = 0 is the image's bottom row).
      const double u = (double(p->x) + 2) / 4, v = (-1.5 - double(p->z)) / (12 - 1.5);
      const double cu = u * kCells, cv = v * kCells;
      // Only pixels well inside a cell (their footprint stays within it).
      if (std::abs(cu - std::round(cu)) < 0.2 || std::abs(cv - std::round(cv)) < 0.2) continue;
      const int row = kCells * kCell - 1 - int(v * kCells * kCell);  // image row of that texel
      const int expected = checker.pixel(int(u * kCells * kCell), row)[0];
      wrong += std::abs(int(image.pixel(x, y)[0]) - expected) > 1;
      ++checked;
    }
  EXPECT_GT(checked, 300);
  EXPECT_EQ(wrong, 0) << "of " << checked;
}

TEST(PerspectiveCorrect, TexelCentresComeBackExactly) {
  // An orthographic quad covering the image exactly, one texel per pixel: every pixel centre is
  // a texel centre, so bilinear filtering returns the texel itself.
  Scene s;
  s.width = 32, s.height = 24;
  s.camera.projection = Projection::Orthographic;
  s.camera.viewHeight = 24;
  s.camera.eye = {16, 12, 5};
  s.camera.center = {16, 12, 0};
  s.lights.clear();
  s.lightModel.ambient = {1, 1, 1};
  s.shading = Shading::Phong;
  auto mesh = std::make_shared<Mesh>();
  mesh->positions = {{0, 0, 0}, {32, 0, 0}, {32, 24, 0}, {0, 24, 0}};
  mesh->normals.assign(4, Vec3(0, 0, 1));
  mesh->uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  mesh->indices = {0, 1, 2, 0, 2, 3};
  Object o;
  o.mesh = mesh;
  o.material.ambient = {1, 1, 1, 1};
  Image texture(32, 24);
  for (std::size_t i = 0; i < texture.rgba.size(); ++i) texture.rgba[i] = std::uint8_t((i * 37) % 251);
  for (std::size_t i = 3; i < texture.rgba.size(); i += 4) texture.rgba[i] = 255;
  o.diffuseTexture = std::make_shared<const Texture>(texture);
  s.objects.push_back(o);
  const Image image = renderScene(s);
  EXPECT_EQ(image.rgba, texture.rgba);
}

}  // namespace
}  // namespace illum
