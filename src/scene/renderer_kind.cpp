#include <illum/scene.h>

namespace illum {

std::string_view toString(RendererKind renderer) {
  switch (renderer) {
    case RendererKind::Raster: return "raster";
    case RendererKind::Whitted: return "whitted";
    case RendererKind::Hall: return "hall";
    case RendererKind::Path: return "path";
  }
  return "?";
}

std::optional<RendererKind> parseRendererKind(std::string_view name) {
  if (name == "raster") return RendererKind::Raster;
  if (name == "whitted") return RendererKind::Whitted;
  if (name == "hall") return RendererKind::Hall;
  if (name == "path") return RendererKind::Path;
  return std::nullopt;
}

int samplesPerPixel(const Scene& scene) {
  return scene.rayTracing.samples.value_or(scene.renderer == RendererKind::Path ? 64 : 1);
}

}  // namespace illum
