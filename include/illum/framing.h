// Looking at a model with no scene file: a camera that frames its bounds, and a light rig that
// follows the camera (key, fill and rim lights plus ambient), in f3d's spirit.
#pragma once

#include <illum/display.h>
#include <illum/scene.h>

#include <optional>
#include <span>
#include <vector>

namespace illum {

struct ViewOptions {
  Vec3 up{0, 1, 0};                 // the model's up axis (--up)
  std::optional<Vec3> position;     // --camera-position
  std::optional<Vec3> focalPoint;   // --camera-focal-point
  std::optional<Vec3> viewUp;       // --camera-view-up
  Real viewAngle = 30;              // --camera-view-angle, vertical, degrees
  Real azimuth = 35;                // --camera-azimuth-angle: turn about the up axis, degrees
  Real elevation = 25;              // --camera-elevation-angle: raise towards the up axis, degrees
  Real zoom = 1;                    // --camera-zoom-factor
  bool orthographic = false;        // --orthographic
};

// The camera that shows all of `points` (world space) from the options' direction: the focal
// point is the centre of their bounds, and the distance the nearest at which every point lies
// inside the view, with a small margin.
Camera framePoints(std::span<const Vec3> points, const ViewOptions& options, Real aspect);

// Every vertex of the objects in world space, for framing.
std::vector<Vec3> worldPoints(const std::vector<Object>& objects);

// The default light rig, fixed to the camera: a warm key light from the upper left, a cool fill
// from the right, a rim light from behind. `intensity` scales every light. For a picture encoded
// sRGB the lights are set in linear light (a stronger key, much weaker fill, rim and ambient), so
// that the encoding's lift of dark values does not wash the picture out.
// With `occluded` (ambient occlusion on), the fill light is left out of the rig and joins the
// ambient instead: soft light from everywhere, which the occlusion shades, so that crevices darken.
std::vector<Light> cameraLightRig(const Camera& camera, Real intensity, Encoding encoding = Encoding::Linear,
                                  bool occluded = false);
// The light-model ambient that goes with the rig.
Color3 cameraRigAmbient(Real intensity, Encoding encoding = Encoding::Linear, bool occluded = false);

}  // namespace illum
