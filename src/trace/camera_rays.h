// Primary rays in eye space through image points, for the camera the rasterizer projects with
// (gluPerspective or glOrtho), limited to the same depth range [near, far].
#pragma once

#include <illum/scene.h>

#include "trace/ray_scene.h"

namespace illum {

class CameraRays {
 public:
  CameraRays(const Camera& camera, int width, int height);

  // The ray through image point (x, y), in pixels from the top-left corner: the centre of pixel
  // (i, j) is (i + 0.5, j + 0.5). Perspective rays have direction.z = −1, so t is the eye depth.
  Ray through(Real x, Real y) const;
  // The width of a pixel's footprint at eye depth `depth` (texture filtering with ray cones).
  Real pixelWidthAt(Real depth) const { return pixelAngle_ * depth + pixelSize_; }

 private:
  int width_, height_;
  bool perspective_;
  Real halfWidth_, halfHeight_;  // of the view at eye depth 1 (perspective) or of the view (orthographic)
  Real near_, far_;
  Real pixelAngle_ = 0, pixelSize_ = 0;
};

}  // namespace illum
