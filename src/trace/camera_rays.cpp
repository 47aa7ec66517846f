#include "trace/camera_rays.h"

#include <cmath>

namespace illum {

CameraRays::CameraRays(const Camera& camera, int width, int height)
    : width_(width), height_(height), perspective_(camera.projection == Projection::Perspective),
      near_(camera.near), far_(camera.far) {
  const Real aspect = Real(width) / Real(height);
  // gluPerspective maps eye depth 1 to ±tan(fovy/2) vertically; glOrtho's view is view_height tall.
  halfHeight_ = perspective_ ? std::tan(glm::radians(camera.fovy) / 2) : camera.viewHeight / 2;
  halfWidth_ = halfHeight_ * aspect;
  if (perspective_) pixelAngle_ = 2 * halfHeight_ / Real(height);
  else pixelSize_ = 2 * halfHeight_ / Real(height);
}

Ray CameraRays::through(Real x, Real y) const {
  // Normalized device coordinates: x right, y up, in [−1, 1] across the image.
  const Real ndcX = 2 * x / Real(width_) - 1;
  const Real ndcY = 1 - 2 * y / Real(height_);
  Ray ray;
  if (perspective_) {
    ray.origin = Vec3(0);
    ray.direction = Vec3(ndcX * halfWidth_, ndcY * halfHeight_, -1);
  } else {
    ray.origin = Vec3(ndcX * halfWidth_, ndcY * halfHeight_, 0);
    ray.direction = Vec3(0, 0, -1);
  }
  // The rasterizer clips at the near and far planes, eye depths near and far.
  ray.tNear = near_;
  ray.tFar = far_;
  return ray;
}

}  // namespace illum
