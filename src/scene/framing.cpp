#include <illum/framing.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace illum {
namespace {

// The direction from the model towards the viewer before azimuth and elevation: the model's
// front for its up axis (+Z for a Y-up model, −Y for a Z-up one).
Vec3 frontFor(const Vec3& up) {
  const Vec3 u = glm::normalize(up);
  if (std::abs(u.z) > Real(0.9)) return Vec3(0, u.z > 0 ? -1 : 1, 0);
  const Vec3 f(0, 0, 1);
  return glm::normalize(f - glm::dot(f, u) * u);
}

Vec3 rotateAbout(const Vec3& v, Real degrees, const Vec3& axis) {
  return Vec3(glm::rotate(Mat4(1), glm::radians(degrees), glm::normalize(axis)) * Vec4(v, 0));
}

}  // namespace

std::vector<Vec3> worldPoints(const std::vector<Object>& objects) {
  std::vector<Vec3> points;
  std::size_t count = 0;
  for (const Object& o : objects) count += o.mesh->positions.size();
  points.reserve(count);
  for (const Object& o : objects)
    for (const Vec3& p : o.mesh->positions) points.push_back(Vec3(o.worldFromObject * Vec4(p, 1)));
  return points;
}

Camera framePoints(std::span<const Vec3> points, const ViewOptions& o, Real aspect) {
  Vec3 boundsMin(0), boundsMax(0);
  if (!points.empty()) {
    boundsMin = boundsMax = points.front();
    for (const Vec3& p : points) {
      boundsMin = glm::min(boundsMin, p);
      boundsMax = glm::max(boundsMax, p);
    }
  }
  const Vec3 center = (boundsMin + boundsMax) * Real(0.5);
  Real radius = glm::length(boundsMax - boundsMin) * Real(0.5);
  if (!(radius > 0)) radius = 1;  // a single point: any sensible frame will do
  const Vec3 up = glm::normalize(o.up);

  Camera cam;
  cam.fovy = o.viewAngle;
  cam.up = o.viewUp ? *o.viewUp : up;
  cam.center = o.focalPoint ? *o.focalPoint : center;

  const Real tanY = std::tan(glm::radians(o.viewAngle) / 2), tanX = tanY * aspect;
  if (o.position) {
    cam.eye = *o.position;
  } else {
    Vec3 toViewer = frontFor(up);
    toViewer = rotateAbout(toViewer, o.azimuth, up);
    const Vec3 right = glm::normalize(glm::cross(up, toViewer));
    toViewer = glm::normalize(rotateAbout(toViewer, -o.elevation, right));
    // The nearest distance at which every point lies inside the view, plus a margin.
    const Vec3 viewRight = glm::normalize(glm::cross(cam.up, toViewer));
    const Vec3 viewUp = glm::cross(toViewer, viewRight);
    Real fit = 0;
    for (const Vec3& p : points) {
      const Vec3 c = p - cam.center;
      const Real depth = glm::dot(c, toViewer);
      fit = std::max({fit, depth + std::abs(glm::dot(c, viewRight)) / tanX, depth + std::abs(glm::dot(c, viewUp)) / tanY});
    }
    if (!(fit > 0)) fit = radius / std::min(tanX, tanY);
    cam.eye = cam.center + toViewer * (fit * Real(1.08) / o.zoom);
  }
  // Keep the up vector usable when looking straight along it.
  const Vec3 forward = cam.center - cam.eye;
  if (glm::length(glm::cross(forward, cam.up)) <= Real(1e-6) * glm::length(forward) * glm::length(cam.up))
    cam.up = std::abs(cam.up.y) < Real(0.9) ? Vec3(0, 1, 0) : Vec3(0, 0, -1);

  const Real distanceToCenter = glm::length(cam.eye - center);
  cam.far = distanceToCenter + radius * 2;
  cam.near = std::max({distanceToCenter - radius * 2, cam.far * Real(1e-4), Real(1e-6)});
  if (o.orthographic) {
    cam.projection = Projection::Orthographic;
    cam.viewHeight = radius * Real(2.1) * std::max(Real(1), 1 / aspect) / o.zoom;
    cam.near = std::max(distanceToCenter - radius * 2, -radius * 2);  // orthographic near may lie behind the eye
    if (!(cam.far > cam.near)) cam.far = cam.near + radius * 4;
  }
  return cam;
}

namespace {

// The rig's fill light: from the right, a little below, cool; no highlight.
Color3 fillColor(Encoding encoding) {
  return encoding == Encoding::Srgb ? Color3(0.15, 0.17, 0.21) : Color3(0.36, 0.38, 0.42);
}

}  // namespace

std::vector<Light> cameraLightRig(const Camera& cam, Real intensity, Encoding encoding, bool occluded) {
  const Vec3 back = glm::normalize(cam.eye - cam.center);  // towards the viewer
  const Vec3 right = glm::normalize(glm::cross(cam.up, back));
  const Vec3 up = glm::cross(back, right);
  const auto directional = [&](Real r, Real u, Real b, Color3 diffuse, Color3 specular) {
    Light l;
    l.position = Vec4(glm::normalize(r * right + u * up + b * back), 0);
    l.diffuse = glm::clamp(diffuse * intensity, Color3(0), Color3(1));
    l.specular = glm::clamp(specular * intensity, Color3(0), Color3(1));
    return l;
  };
  const bool srgb = encoding == Encoding::Srgb;
  std::vector<Light> rig = {
      srgb ? directional(-0.5f, 0.6f, 1.0f, {0.86, 0.83, 0.77}, {0.6, 0.6, 0.6})       // key: upper left, in front
           : directional(-0.5f, 0.6f, 1.0f, {0.68, 0.66, 0.62}, {0.55, 0.55, 0.55}),
      srgb ? directional(0.2f, 0.7f, -1.0f, {0.12, 0.12, 0.12}, {0.25, 0.25, 0.25})    // rim: above, from behind
           : directional(0.2f, 0.7f, -1.0f, {0.3, 0.3, 0.3}, {0.3, 0.3, 0.3}),
  };
  if (!occluded) rig.insert(rig.begin() + 1, directional(0.8f, -0.2f, 0.6f, fillColor(encoding), {0, 0, 0}));
  return rig;
}

Color3 cameraRigAmbient(Real intensity, Encoding encoding, bool occluded) {
  const Color3 ambient(encoding == Encoding::Srgb ? Real(0.035) : Real(0.2));
  return glm::clamp((occluded ? ambient + fillColor(encoding) : ambient) * intensity, Color3(0), Color3(1));
}

}  // namespace illum
