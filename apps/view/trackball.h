// The viewer's camera, moved as f3d moves it (VTK's trackball camera): dragging turns the eye
// about the focal point (azimuth about the view-up, elevation about the view's right), zooming
// moves the eye towards the focal point or away, panning moves both across the view; the axis
// views look along the model's axes. Near and far follow the distance so that the model's bounds
// stay between them.
#pragma once

#include <illum/scene.h>

namespace illum::view {

// What a camera may frame: the bounding sphere of the scene's geometry.
struct Bounds {
  Vec3 center{0};
  Real radius = 1;
};
Bounds boundsOf(const Scene& scene);

// The axis views of keys 1, 3 and 7 (f3d's): front, right and top, and with Ctrl the opposite
// ones, for a model whose up axis is `up`.
enum class AxisView { Front, Back, Right, Left, Top, Bottom };

class Trackball {
 public:
  Trackball() = default;
  Trackball(const Camera& framing, const Bounds& bounds, Vec3 up) : home_(framing), bounds_(bounds), up_(up) {
    reset();
  }

  const Camera& camera() const { return camera_; }
  // Back to the framing (Enter).
  void reset();
  // Turns by a drag of (dx, dy) pixels in a window `height` pixels high: a drag across the
  // window's height turns by 200°, as VTK's default does.
  void orbit(Real dx, Real dy, int height);
  // Moves towards the focal point by `factor` (> 1 closer, < 1 farther); the eye never reaches it.
  void zoom(Real factor);
  // Moves eye and focal point so that what was under the pointer follows a drag of (dx, dy) pixels.
  void pan(Real dx, Real dy, int height);
  void look(AxisView view);

 private:
  void fitDepthRange();
  Camera home_, camera_;
  Bounds bounds_;
  Vec3 up_{0, 1, 0};
};

}  // namespace illum::view
