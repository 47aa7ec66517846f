// The scalar type of every lighting and geometry computation, and the vectors and colours of it.
// float by default, like OpenGL and llvmpipe; configure with -DILLUM_DOUBLE=ON for double.
#pragma once

#include <glm/glm.hpp>

namespace illum {

#if defined(ILLUM_USE_DOUBLE) && ILLUM_USE_DOUBLE
using Real = double;
#else
using Real = float;
#endif

using Vec2 = glm::vec<2, Real>;
using Vec3 = glm::vec<3, Real>;
using Vec4 = glm::vec<4, Real>;
using Mat3 = glm::mat<3, 3, Real>;
using Mat4 = glm::mat<4, 4, Real>;
// Colours are vectors of the same Reals (RGB, and RGBA with alpha).
using Color3 = Vec3;
using Color4 = Vec4;

}  // namespace illum
