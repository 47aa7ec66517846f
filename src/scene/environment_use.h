// The scene's environment as the renderers use it besides the path tracer's escaping paths:
// its image-based light for a frame, its rotation and its radiance behind the scene (the built-in
// studio environment is scene.h's studioEnvironment).
#pragma once

#include <illum/scene.h>

#include "shading/image_light.h"

#include <memory>

namespace illum {

// From a renderer's eye space to the environment map's: the view's rotation undone, then the
// scene's environment rotation about +Y undone.
Mat3 environmentFromEye(const Scene& scene, const Mat4& viewFromWorld);

// The environment's radiance towards eye direction `d` (unit), scaled by the scene's
// "environment": the map itself (sharp) or prefiltered as a rough surface reflects it (blurred).
Color3 environmentRadiance(const Scene& scene, const Mat3& mapFromEye, const Vec3& d, bool blurred);

// The image-based light of a frame seen from `viewFromWorld`, or null where the scene's
// environment lights nothing (EnvironmentUse::lighting).
std::shared_ptr<const EyeImageLight> eyeImageLight(const Scene& scene, const Mat4& viewFromWorld);

}  // namespace illum
