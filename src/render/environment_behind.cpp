#include "render/environment_behind.h"

#include <illum/display.h>

#include "scene/environment_use.h"

#include <tbb/parallel_for.h>

#include <cmath>

namespace illum {

bool showsEnvironmentBehind(const Scene& scene) {
  return scene.environment.background != EnvironmentBackground::None && scene.background.a > 0;
}

void layEnvironmentBehind(const Scene& scene, Image& image) {
  const Mat4 viewFromWorld = scene.camera.viewFromWorld();
  const Mat3 mapFromEye = environmentFromEye(scene, viewFromWorld);
  const Mat4 viewFromClip = glm::inverse(scene.camera.clipFromView(Real(image.width) / Real(image.height)));
  const bool blurred = scene.environment.background == EnvironmentBackground::Blurred;
  const auto unproject = [&](Real x, Real y, Real z) {
    const Vec4 p = viewFromClip * Vec4(x, y, z, 1);
    return Vec3(p) / p.w;
  };
  tbb::parallel_for(0, image.height, [&](int y) {
    for (int x = 0; x < image.width; ++x) {
      std::uint8_t* p = image.pixel(x, y);
      const int alpha = p[3];
      if (alpha == 255) continue;
      // The ray through the pixel's centre, from the near plane to the far one (any projection).
      const Real nx = (Real(x) + Real(0.5)) / Real(image.width) * 2 - 1;
      const Real ny = 1 - (Real(y) + Real(0.5)) / Real(image.height) * 2;
      const Vec3 d = glm::normalize(unproject(nx, ny, 1) - unproject(nx, ny, -1));
      const Color3 radiance = environmentRadiance(scene, mapFromEye, d, blurred);
      for (int c = 0; c < 3; ++c) {
        const Real shown = displayValue(radiance[c], scene.display) * 255;
        p[c] = std::uint8_t(std::lround((Real(p[c]) * Real(alpha) + shown * Real(255 - alpha)) / 255));
      }
      p[3] = 255;
    }
  });
}

}  // namespace illum
