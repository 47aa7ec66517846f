#include <illum/scene.h>

#include "math/transform.h"

#include <cmath>
#include <string>

namespace illum {

Mat4 Camera::viewFromWorld() const { return lookAt(eye, center, up); }

Mat4 Camera::clipFromView(Real aspect) const {
  return projection == Projection::Perspective ? perspective(fovy, aspect, near, far)
                                               : orthographic(viewHeight, aspect, near, far);
}

CameraFault cameraFault(const Camera& cam, Real aspect) {
  const Vec3 forward = cam.center - cam.eye;
  if (glm::length(forward) == 0) return CameraFault::SamePoint;
  if (glm::length(cam.up) == 0) return CameraFault::ZeroUp;
  // Squares of coordinates near float's limit overflow before anything else does.
  const Real sideways = glm::length(glm::cross(forward, cam.up)), lengths = glm::length(forward) * glm::length(cam.up);
  if (!std::isfinite(sideways) || !std::isfinite(lengths)) return CameraFault::TooLarge;
  if (sideways <= Real(1e-6) * lengths) return CameraFault::UpParallel;
  if (cam.projection == Projection::Perspective && !(cam.fovy >= Real(0.01) && cam.fovy <= Real(179.99)))
    return CameraFault::ViewAngle;
  const Mat4 m = cam.clipFromView(aspect) * cam.viewFromWorld();
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(m[c][r])) return CameraFault::TooLarge;
  return CameraFault::None;
}

std::string describe(CameraFault fault) {
  switch (fault) {
    case CameraFault::None: return "a usable camera";
    case CameraFault::SamePoint: return "expected the camera position and the point it looks at to differ";
    case CameraFault::ZeroUp: return "expected a non-zero up direction";
    case CameraFault::UpParallel: return "expected an up direction not parallel to the view direction";
    case CameraFault::ViewAngle: return "expected a view angle in [0.01, 179.99] degrees";
    case CameraFault::TooLarge:
      return "expected numbers the renderer can transform with: the view and projection overflow " +
             std::string(sizeof(Real) == 4 ? "single" : "double") + " precision";
  }
  return "?";
}

}  // namespace illum
