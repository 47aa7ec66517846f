#include "trackball.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace illum::view {
namespace {

Vec3 rotateAbout(const Vec3& v, Real degrees, const Vec3& axis) {
  return Vec3(glm::rotate(Mat4(1), glm::radians(degrees), glm::normalize(axis)) * Vec4(v, 0));
}

// The model's front for its up axis, as framing.cpp turns a model towards the viewer.
Vec3 frontFor(const Vec3& up) {
  const Vec3 u = glm::normalize(up);
  if (std::abs(u.z) > Real(0.9)) return Vec3(0, u.z > 0 ? -1 : 1, 0);
  const Vec3 f(0, 0, 1);
  return glm::normalize(f - glm::dot(f, u) * u);
}

}  // namespace

Bounds boundsOf(const Scene& scene) {
  Vec3 lo(std::numeric_limits<Real>::max()), hi(-std::numeric_limits<Real>::max());
  bool any = false;
  for (const Object& o : scene.objects)
    for (const Vec3& p : o.mesh->positions) {
      const Vec3 w(o.worldFromObject * Vec4(p, 1));
      lo = glm::min(lo, w), hi = glm::max(hi, w);
      any = true;
    }
  if (!any) return {};
  const Real radius = glm::length(hi - lo) / 2;
  return {(lo + hi) / Real(2), radius > 0 ? radius : Real(1)};
}

void Trackball::reset() { camera_ = home_; }  // exactly the framing, its depth range too

void Trackball::orbit(Real dx, Real dy, int height) {
  const Real perPixel = Real(200) / Real(std::max(height, 1));
  Vec3 toEye = camera_.eye - camera_.center;
  const Vec3 up = glm::normalize(camera_.up);
  // Azimuth about the view-up through the focal point; elevation about the view's right.
  toEye = rotateAbout(toEye, -dx * perPixel, up);
  const Vec3 right = glm::normalize(glm::cross(up, toEye));
  const Vec3 turned = rotateAbout(toEye, dy * perPixel, right);
  camera_.eye = camera_.center + turned;
  // The view-up made orthogonal to the new view again (VTK's OrthogonalizeViewUp).
  camera_.up = glm::normalize(glm::cross(glm::normalize(turned), right));
  fitDepthRange();
}

void Trackball::zoom(Real factor) {
  if (!(factor > 0) || !std::isfinite(factor)) return;
  if (camera_.projection == Projection::Orthographic) {
    camera_.viewHeight = std::max(camera_.viewHeight / factor, bounds_.radius * Real(1e-4));
    return;
  }
  const Vec3 toEye = camera_.eye - camera_.center;
  const Real distance = glm::length(toEye);
  const Real next = std::max(distance / factor, bounds_.radius * Real(1e-3));
  camera_.eye = camera_.center + toEye * (next / distance);
  fitDepthRange();
}

void Trackball::pan(Real dx, Real dy, int height) {
  const Vec3 toEye = camera_.eye - camera_.center;
  const Vec3 forward = -glm::normalize(toEye);
  const Vec3 right = glm::normalize(glm::cross(forward, camera_.up));
  const Vec3 up = glm::cross(right, forward);
  // World units per pixel at the focal point.
  const Real view = camera_.projection == Projection::Orthographic
                        ? camera_.viewHeight
                        : 2 * glm::length(toEye) * std::tan(glm::radians(camera_.fovy) / 2);
  const Real perPixel = view / Real(std::max(height, 1));
  const Vec3 move = (-dx * right + dy * up) * perPixel;  // (window y runs down)
  camera_.eye += move;
  camera_.center += move;
  fitDepthRange();
}

void Trackball::look(AxisView view) {
  const Vec3 up = glm::normalize(up_), front = frontFor(up), right = glm::normalize(glm::cross(up, front));
  const Real distance = glm::length(camera_.eye - camera_.center);
  Vec3 toEye = front, viewUp = up;
  switch (view) {
    case AxisView::Front: toEye = front; break;
    case AxisView::Back: toEye = -front; break;
    case AxisView::Right: toEye = right; break;
    case AxisView::Left: toEye = -right; break;
    case AxisView::Top: toEye = up, viewUp = -front; break;
    case AxisView::Bottom: toEye = -up, viewUp = front; break;
  }
  camera_.center = bounds_.center;
  camera_.eye = camera_.center + toEye * distance;
  camera_.up = viewUp;
  fitDepthRange();
}

void Trackball::fitDepthRange() {
  // The bounds in front of the eye, with room: as framing sets them.
  const Real distance = glm::length(camera_.eye - bounds_.center);
  const Real reach = bounds_.radius * 2;
  camera_.far = std::max(distance + reach, home_.far);
  if (camera_.projection == Projection::Orthographic) {
    camera_.near = std::min(distance - reach, home_.near);
    return;
  }
  camera_.near = std::max({distance - reach, camera_.far * Real(1e-4), Real(1e-6)});
}

}  // namespace illum::view
