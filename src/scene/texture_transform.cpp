#include "scene/texture_transform.h"

#include <cmath>

namespace illum {

UvTransform fromAssimpGltf(const aiUVTransform& t) {
  UvTransform out;
  out.scale = Vec2(t.mScaling.x, t.mScaling.y);
  out.rotation = -Real(t.mRotation);
  // assimp: translation.x = sx/2·(−cos r + sin r + 1) + offset.x,
  //         translation.y = sy/2·(sin r + cos r − 1) + 1 − sy − offset.y   (r the extension's rotation).
  const Real c = std::cos(out.rotation), s = std::sin(out.rotation);
  out.offset.x = Real(t.mTranslation.x) - Real(0.5) * out.scale.x * (-c + s + 1);
  out.offset.y = Real(0.5) * out.scale.y * (s + c - 1) + 1 - out.scale.y - Real(t.mTranslation.y);
  return out;
}

void applyUvTransform(const UvTransform& t, std::vector<Vec2>& uvs) {
  const Real c = std::cos(t.rotation), s = std::sin(t.rotation);
  for (Vec2& uv : uvs) {
    // glTF's texture space has v down: v = 1 − GL's.
    const Real u = uv.x, v = 1 - uv.y;
    const Real su = t.scale.x * u, sv = t.scale.y * v;
    uv = Vec2(c * su + s * sv + t.offset.x, 1 - (-s * su + c * sv + t.offset.y));
  }
}

}  // namespace illum
