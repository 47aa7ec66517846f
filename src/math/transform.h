// The classic GL matrix builders as thin names over glm, named aFromB so products read right.
#pragma once

#include <illum/real.h>

namespace illum {

// gluLookAt: viewFromWorld.
Mat4 lookAt(const Vec3& eye, const Vec3& center, const Vec3& up);
// gluPerspective: clipFromView, depth mapped to [-1,1] in NDC like GL.
Mat4 perspective(Real fovyDegrees, Real aspect, Real near, Real far);
// glOrtho centred on the view axis with the given height.
Mat4 orthographic(Real viewHeight, Real aspect, Real near, Real far);
// The normal matrix: inverse transpose of the upper-left 3×3 of viewFromObject.
Mat3 normalMatrix(const Mat4& viewFromObject);

}  // namespace illum
