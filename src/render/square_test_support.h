// For tests of what a renderer does to one surface: a square in the z = 0 plane, facing an
// orthographic camera looking down −z, with the texture coordinates asked for at its corners.
#pragma once

#include <illum/scene.h>

#include <array>
#include <memory>

namespace illum::test {

// Corners (±half, ±half, 0) counter-clockwise from the bottom left, normals +z, uvs in that order.
inline std::shared_ptr<Mesh> facingSquare(Real half, const std::array<Vec2, 4>& uvs = {{{0, 0}, {1, 0}, {1, 1}, {0, 1}}}) {
  auto m = std::make_shared<Mesh>();
  m->positions = {{-half, -half, 0}, {half, -half, 0}, {half, half, 0}, {-half, half, 0}};
  m->normals.assign(4, Vec3(0, 0, 1));
  m->uvs.assign(uvs.begin(), uvs.end());
  m->indices = {0, 1, 2, 0, 2, 3};
  return m;
}

// A square picture of `pixels` on a side, the orthographic view `viewHeight` high.
inline Scene orthographicScene(int pixels, Real viewHeight) {
  Scene s;
  s.width = s.height = pixels;
  s.camera.projection = Projection::Orthographic;
  s.camera.viewHeight = viewHeight;
  return s;
}

}  // namespace illum::test
