#include "math/transform.h"

#include <glm/gtc/matrix_transform.hpp>

namespace illum {

Mat4 lookAt(const Vec3& eye, const Vec3& center, const Vec3& up) {
  return glm::lookAtRH(eye, center, up);
}

Mat4 perspective(Real fovyDegrees, Real aspect, Real near, Real far) {
  return glm::perspectiveRH_NO(glm::radians(fovyDegrees), aspect, near, far);
}

Mat4 orthographic(Real viewHeight, Real aspect, Real near, Real far) {
  const Real h = viewHeight / 2, w = h * aspect;
  return glm::orthoRH_NO(-w, w, -h, h, near, far);
}

Mat3 normalMatrix(const Mat4& viewFromObject) {
  return glm::transpose(glm::inverse(Mat3(viewFromObject)));
}

}  // namespace illum
