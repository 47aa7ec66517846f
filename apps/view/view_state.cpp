#include "view_state.h"

#include <illum/error.h>
#include <illum/framing.h>

#include <algorithm>

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

}  // namespace

ViewState::ViewState(std::vector<std::string> files, cli::SceneOptions options)
    : files_(std::move(files)), options_(std::move(options)) {
  if (options_.width) width_ = *options_.width;
  if (options_.height) height_ = *options_.height;
}

const std::string& ViewState::current() const {
  static const std::string builtIn;
  return files_.empty() ? builtIn : files_[index_];
}

void ViewState::load() {
  cli::SceneOptions o = options_;
  o.input = current();
  o.width = width_, o.height = height_;
  o.resolution.clear();
  Scene next = cli::prepareScene(o, nullptr, &cache_);
  // The person's toggles outlive the file.
  if (version_ > 1) {
    next.overlays = scene_.overlays;
    next.multisample = scene_.multisample;
    next.ambientOcclusion.enabled = scene_.ambientOcclusion.enabled;
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
