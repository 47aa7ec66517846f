#include <illum/scene.h>

#include "math/transform.h"

namespace illum {

Mat4 Camera::viewFromWorld() const { return lookAt(eye, center, up); }

Mat4 Camera::clipFromView(Real aspect) const {
  return projection == Projection::Perspective ? perspective(fovy, aspect, near, far)
                                               : orthographic(viewHeight, aspect, near, far);
}

}  // namespace illum
