#include "scene/environment_use.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>

namespace illum {
namespace {

constexpr Real kPi = Real(3.14159265358979323846);

// A soft round light: full radiance within `radius` degrees of `centre`, falling smoothly to
// nothing over the next `edge` degrees (compared as cosines: no arc cosine per texel).
Real softbox(const Vec3& d, const Vec3& centre, Real radius, Real edge) {
  const Real inner = std::cos(radius * kPi / 180), outer = std::cos((radius + edge) * kPi / 180);
  const Real t = std::clamp((inner - glm::dot(d, glm::normalize(centre))) / (inner - outer), Real(0), Real(1));
  return 1 - t * t * (3 - 2 * t);
}

std::shared_ptr<const EnvironmentMap> makeStudio() {
  constexpr int kWidth = 256, kHeight = 128;
  std::vector<Vec3> texels(std::size_t(kWidth) * kHeight);
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const Vec3 d = latLongDirection(Real(x) + Real(0.5), Real(y) + Real(0.5), kWidth, kHeight);
      // A cool sky brightening towards the zenith over a warm grey floor, a soft horizon between.
      const Real up = std::clamp(d.y, Real(0), Real(1));
      const Color3 sky = glm::mix(Color3(0.42, 0.44, 0.47), Color3(0.62, 0.66, 0.72), up);
      const Color3 floor(0.16, 0.15, 0.14);
      const Real horizon = std::clamp(d.y / Real(0.08) * Real(0.5) + Real(0.5), Real(0), Real(1));
      Color3 c = glm::mix(floor, sky, horizon * horizon * (3 - 2 * horizon));
      // Studio lights, high at the front right (key), lower at the left (fill) and behind (rim).
      c += Color3(4.0) * softbox(d, {0.8, 0.9, 0.7}, 14, 10);
      c += Color3(1.2) * softbox(d, {-1.0, 0.35, 0.55}, 20, 14);
      c += Color3(2.0) * softbox(d, {0.2, 0.55, -1.0}, 10, 8);
      // Dim enough that, with the preview's light rig, a white surface stays below white: E/π is
      // about 0.3 facing up.
      texels[std::size_t(y) * kWidth + std::size_t(x)] = Real(0.35) * c;
    }
  return std::make_shared<const EnvironmentMap>(kWidth, kHeight, texels);
}

// A uniform environment of radiance 1 (the scene's "environment" colour scales it).
const EnvironmentMap& uniformEnvironment() {
  static const EnvironmentMap map(8, 4, std::vector<Vec3>(32, Vec3(1)));
  return map;
}

// The image light of a scene's map, kept per map file while that file lives (the viewer asks
// every frame), found by content otherwise (ImageLight::of).
std::shared_ptr<const ImageLight> imageLightOf(const std::shared_ptr<const EnvironmentMapFile>& file) {
  if (!file) {
    static const std::shared_ptr<const ImageLight> uniform = ImageLight::of(uniformEnvironment());
    return uniform;
  }
  static std::mutex mutex;
  static std::map<const EnvironmentMapFile*, std::pair<std::weak_ptr<const EnvironmentMapFile>, std::shared_ptr<const ImageLight>>> known;
  {
    std::lock_guard lock(mutex);
    if (auto it = known.find(file.get()); it != known.end() && it->second.first.lock() == file) return it->second.second;
  }
  std::shared_ptr<const ImageLight> light = ImageLight::of(file->map());
  std::lock_guard lock(mutex);
  std::erase_if(known, [](const auto& entry) { return entry.second.first.expired(); });
  known[file.get()] = {file, light};
  return light;
}

}  // namespace

std::string_view toString(EnvironmentLighting lighting) {
  switch (lighting) {
    case EnvironmentLighting::None: return "none";
    case EnvironmentLighting::PhysicallyBased: return "physically_based";
    case EnvironmentLighting::All: return "all";
  }
  return "?";
}

std::string_view toString(EnvironmentBackground background) {
  switch (background) {
    case EnvironmentBackground::None: return "none";
    case EnvironmentBackground::Sharp: return "sharp";
    case EnvironmentBackground::Blurred: return "blurred";
  }
  return "?";
}

std::optional<EnvironmentLighting> parseEnvironmentLighting(std::string_view name) {
  for (EnvironmentLighting l : {EnvironmentLighting::None, EnvironmentLighting::PhysicallyBased, EnvironmentLighting::All})
    if (name == toString(l)) return l;
  return std::nullopt;
}

std::optional<EnvironmentBackground> parseEnvironmentBackground(std::string_view name) {
  for (EnvironmentBackground b : {EnvironmentBackground::None, EnvironmentBackground::Sharp, EnvironmentBackground::Blurred})
    if (name == toString(b)) return b;
  return std::nullopt;
}

Mat3 environmentFromEye(const Scene& scene, const Mat4& viewFromWorld) {
  const Mat3 worldFromEye = glm::transpose(Mat3(viewFromWorld));  // a rotation: its inverse is its transpose
  const Real a = -scene.environment.rotation * kPi / 180;
  const Mat3 turn(std::cos(a), 0, -std::sin(a), 0, 1, 0, std::sin(a), 0, std::cos(a));  // about +Y, by a
  return turn * worldFromEye;
}

Color3 environmentRadiance(const Scene& scene, const Mat3& mapFromEye, const Vec3& d, bool blurred) {
  const Color3& scale = scene.rayTracing.environment;
  const std::shared_ptr<const EnvironmentMapFile>& file = scene.rayTracing.environmentMap;
  if (!file) return scale;
  const Vec3 m = glm::normalize(mapFromEye * d);
  if (blurred) return scale * imageLightOf(file)->prefiltered(m, Real(0.4));
  return scale * file->map().radiance(m);
}

std::shared_ptr<const EyeImageLight> eyeImageLight(const Scene& scene, const Mat4& viewFromWorld) {
  if (scene.environment.lighting == EnvironmentLighting::None) return nullptr;
  auto eye = std::make_shared<EyeImageLight>();
  eye->light = imageLightOf(scene.rayTracing.environmentMap);
  eye->mapFromEye = environmentFromEye(scene, viewFromWorld);
  eye->scale = scene.rayTracing.environment;
  eye->lightsClassic = scene.environment.lighting == EnvironmentLighting::All;
  return eye;
}

void prepareImageLight(const std::shared_ptr<const EnvironmentMapFile>& map) { imageLightOf(map); }

std::shared_ptr<const EnvironmentMapFile> studioEnvironment() {
  static const std::shared_ptr<const EnvironmentMapFile> studio = EnvironmentMapFile::of(makeStudio());
  return studio;
}

}  // namespace illum
