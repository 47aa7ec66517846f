#include "view_state.h"

#include <illum/error.h>
#include <illum/framing.h>

#include <algorithm>
#include <cmath>

namespace illum::view {
namespace {

// The camera's frame as cameraLightRig builds it: right, up, and towards the viewer.
struct CameraFrame {
  Vec3 right, up, back;
  explicit CameraFrame(const Camera& c) {
    back = glm::normalize(c.eye - c.center);
    right = glm::normalize(glm::cross(c.up, back));
    up = glm::cross(back, right);
  }
};

// Where a directional light's handle sits: on a sphere about the focal point, a third of the way
// to the eye, in the light's direction.
Vec3 handlePoint(const Light& l, const Camera& c) {
  const Vec3 p(l.position);
  if (l.position.w != 0) return p / l.position.w;
  const Real len = glm::length(p);
  return c.center + (len > 0 ? p / len : Vec3(0, 0, 1)) * (glm::length(c.eye - c.center) / 3);
}

Mat4 clipFromWorld(const Scene& s) {
  return s.camera.clipFromView(Real(s.width) / Real(s.height)) * s.camera.viewFromWorld();
}

}  // namespace

Scene withTerms(Scene scene, const Terms& terms) {
  if (terms.all()) return scene;
  if (!terms.emission)
    for (Object& o : scene.objects) o.material.emission = Color4(0, 0, 0, o.material.emission.a);
  if (!terms.globalAmbient) scene.lightModel.ambient = Color3(0);
  for (Light& l : scene.lights) {
    if (!terms.ambient) l.ambient = Color3(0);
    if (!terms.diffuse) l.diffuse = Color3(0);
    if (!terms.specular) l.specular = Color3(0);
  }
  return scene;
}

ViewState::ViewState(std::vector<std::string> files, cli::SceneOptions options)
    : files_(std::move(files)), options_(std::move(options)) {}

const std::string& ViewState::current() const {
  static const std::string builtIn;
  return files_.empty() ? builtIn : files_[index_];
}

void ViewState::load() {
  cli::SceneOptions o = options_;
  o.input = current();
  if (width_ > 0) {
    // The window's size, once there is a window; the first file sets it (its own size, or the
    // options').
    o.width = width_, o.height = height_;
    o.resolution.clear();
  }
  Scene next = cli::prepareScene(o, nullptr, &cache_);
  width_ = next.width, height_ = next.height;
  // The person's toggles outlive the file.
  if (version_ > 1) {
    next.overlays = scene_.overlays;
    next.multisample = scene_.multisample;
    next.ambientOcclusion.enabled = scene_.ambientOcclusion.enabled;
    if (scene_.environment.lighting == EnvironmentLighting::All && next.environment.lighting != EnvironmentLighting::All) {
      if (!next.rayTracing.environmentMap) {
        next.rayTracing.environmentMap = scene_.rayTracing.environmentMap;
        next.rayTracing.environment = scene_.rayTracing.environment;
        next.environment.studio = scene_.environment.studio;
      }
      next.environment.lighting = EnvironmentLighting::All;
    }
  }
  model_ = cli::isModelInput(o.input);
  lightsFollow_ = model_;
  scene_ = std::move(next);
  trackball_ = Trackball(scene_.camera, boundsOf(scene_), scene_.camera.up);
  rig();
  probe_.reset();
  ++version_;
}

void ViewState::rig() {
  rigDirections_.clear();
  if (!model_) return;
  const CameraFrame f(scene_.camera);
  for (const Light& l : scene_.lights) {
    const Vec3 d(l.position);
    rigDirections_.push_back({glm::dot(d, f.right), glm::dot(d, f.up), glm::dot(d, f.back)});
  }
}

bool ViewState::step(int delta) {
  if (files_.size() < 2) return false;
  const std::size_t before = index_;
  const auto n = std::int64_t(files_.size());
  index_ = std::size_t(((std::int64_t(index_) + delta) % n + n) % n);
  try {
    load();
  } catch (...) {
    index_ = before;
    throw;
  }
  return true;
}

void ViewState::open(const std::string& path) {
  const std::size_t before = index_;
  files_.insert(files_.begin() + std::ptrdiff_t(files_.empty() ? 0 : index_ + 1), path);
  index_ = files_.size() == 1 ? 0 : index_ + 1;
  try {
    load();
  } catch (...) {
    files_.erase(files_.begin() + std::ptrdiff_t(index_));
    index_ = before;
    throw;
  }
}

void ViewState::resize(int width, int height) {
  width = std::max(width, 1), height = std::max(height, 1);
  if (width == width_ && height == height_) return;
  width_ = width, height_ = height;
  scene_.width = width, scene_.height = height;
  probe_.reset();
  ++version_;
}

void ViewState::cameraMoved() {
  scene_.camera = trackball_.camera();
  if (model_ && lightsFollow_ && rigDirections_.size() == scene_.lights.size()) {
    const CameraFrame f(scene_.camera);
    for (std::size_t i = 0; i < scene_.lights.size(); ++i) {
      const Vec3& d = rigDirections_[i];
      scene_.lights[i].position = Vec4(glm::normalize(d.x * f.right + d.y * f.up + d.z * f.back), 0);
    }
  }
  ++version_;
}

void ViewState::setLightsFollow(bool follow) {
  if (follow == lightsFollow_) return;
  lightsFollow_ = follow && model_;
  if (lightsFollow_) rig();  // from where the lights are now
  ++version_;
}

void ViewState::toggleEdges() {
  scene_.overlays.edges = !scene_.overlays.edges;
  ++version_;
}
void ViewState::toggleAxes() {
  scene_.overlays.axes = !scene_.overlays.axes;
  ++version_;
}
void ViewState::toggleGrid() {
  scene_.overlays.grid = !scene_.overlays.grid;
  ++version_;
}
void ViewState::toggleAntiAliasing() {
  scene_.multisample = scene_.multisample > 1 ? 1 : 8;
  ++version_;
}

void ViewState::toggleOcclusion() {
  scene_.ambientOcclusion.enabled = !scene_.ambientOcclusion.enabled;
  if (model_) {
    // As `illum render --ambient-occlusion` lights a preview: the fill light made ambient.
    const Real intensity = options_.lightIntensity ? Real(*options_.lightIntensity) : Real(1);
    const Encoding encoding = scene_.display.encoding == Encoding::Srgb ? Encoding::Srgb : Encoding::Linear;
    scene_.lights = cameraLightRig(scene_.camera, intensity, encoding, scene_.ambientOcclusion.enabled);
    scene_.lightModel.ambient = cameraRigAmbient(intensity, encoding, scene_.ambientOcclusion.enabled);
    rig();
  }
  ++version_;
}

void ViewState::setRenderer(RendererKind renderer) {
  scene_.renderer = renderer;
  if (model_ && options_.toneMap.empty()) scene_.display.toneMap = cli::previewToneMap(scene_);
  ++version_;
}

void ViewState::toggleEnvironment() {
  EnvironmentUse& use = scene_.environment;
  if (use.lighting == EnvironmentLighting::All) {
    use.lighting = EnvironmentLighting::None;
  } else {
    if (!scene_.rayTracing.environmentMap) {
      scene_.rayTracing.environmentMap = studioEnvironment();
      scene_.rayTracing.environment = Color3(1);
      use.studio = true;
    }
    use.lighting = EnvironmentLighting::All;
  }
  // A preview's display follows, as `illum render MODEL --environment studio|none` would show it.
  if (model_ && options_.toneMap.empty()) scene_.display.toneMap = cli::previewToneMap(scene_);
  ++version_;
}

void ViewState::setTerms(const Terms& terms) {
  terms_ = terms;
  ++version_;
}

Handle ViewState::handle(std::size_t light) const {
  Handle h;
  if (light >= scene_.lights.size()) return h;
  const Vec4 clip = clipFromWorld(scene_) * Vec4(handlePoint(scene_.lights[light], scene_.camera), 1);
  if (!(clip.w > 0)) return h;
  const Vec3 ndc = Vec3(clip) / clip.w;
  const Vec2 size(Real(scene_.width), Real(scene_.height));
  h.pixel = {(ndc.x + 1) / 2 * size.x, (1 - ndc.y) / 2 * size.y};
  h.depth = ndc.z;
  h.inFront = true;
  h.inside = std::abs(ndc.x) <= 1 && std::abs(ndc.y) <= 1;
  const Real margin = 12;
  h.shown = glm::clamp(h.pixel, Vec2(margin), glm::max(size - margin, Vec2(margin)));
  return h;
}

void ViewState::dragLight(std::size_t light, Real dx, Real dy) {
  const Handle h = handle(light);
  if (!h.inFront) return;
  const Vec2 to = h.pixel + Vec2(dx, dy);
  const Mat4 worldFromClip = glm::inverse(clipFromWorld(scene_));
  const auto unproject = [&](Real depth) {
    const Vec4 w = worldFromClip * Vec4(to.x / Real(scene_.width) * 2 - 1, 1 - to.y / Real(scene_.height) * 2, depth, 1);
    return Vec3(w) / w.w;
  };
  Light& l = scene_.lights[light];
  if (l.position.w != 0) {
    const Vec3 p = unproject(h.depth);
    if (!std::isfinite(p.x + p.y + p.z)) return;
    l.position = Vec4(p, 1);
  } else {
    // The handle slides on its sphere under the pointer, on the side it was on; a pointer beyond
    // the sphere's outline turns it to the outline.
    const Vec3 c = scene_.camera.center, was = handlePoint(l, scene_.camera);
    const Real r = glm::length(was - c);
    const Vec3 o = unproject(-1), d = glm::normalize(unproject(1) - o);
    if (!std::isfinite(o.x + o.y + o.z + d.x + d.y + d.z)) return;
    const Real b = glm::dot(d, o - c), disc = b * b - (glm::dot(o - c, o - c) - r * r);
    const bool front = glm::dot(was - c, scene_.camera.eye - c) >= 0;
    const Real t = disc >= 0 ? (front ? -b - std::sqrt(disc) : -b + std::sqrt(disc)) : -b;
    const Vec3 towards = o + t * d - c;
    if (glm::length(towards) == 0) return;
    l.position = Vec4(glm::normalize(towards), 0);
  }
  lightsFollow_ = false;  // the person placed it
  ++version_;
}

void ViewState::watch(int x, int y) {
  if (x < 0 || y < 0 || x >= scene_.width || y >= scene_.height) return;
  probe_ = {x, y};
  ++version_;
}

void ViewState::unwatch() {
  probe_.reset();
  ++version_;
}

}  // namespace illum::view
