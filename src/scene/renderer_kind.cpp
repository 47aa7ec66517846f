#include <illum/scene.h>

namespace illum {

std::string_view toString(RendererKind renderer) {
  switch (renderer) {
    case RendererKind::Raster: return "raster";
    case RendererKind::Whitted: return "whitted";
    case RendererKind::Hall: return "hall";
  }
  return "?";
}

std::optional<RendererKind> parseRendererKind(std::string_view name) {
  if (name == "raster") return RendererKind::Raster;
  if (name == "whitted") return RendererKind::Whitted;
  if (name == "hall") return RendererKind::Hall;
  return std::nullopt;
}

}  // namespace illum
