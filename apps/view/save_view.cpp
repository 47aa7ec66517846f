#include "save_view.h"

#include <illum/error.h>
#include <illum/image.h>
#include <illum/output_file.h>
#include <illum/render.h>

#include <string>

namespace illum::view {

Saved saveView(const Frame& frame, bool exr, const std::filesystem::path& folder) {
  if (!frame.scene) throw Error("nothing drawn yet to save");
  // The scene first: one that cannot be written stops the save before any file is made.
  const std::string scene = sceneJson(*frame.scene);
  std::vector<std::uint8_t> picture;
  if (exr) {
    // The linear values, unclamped, drawn again for the file (the window holds bytes).
    Image bytes;
    FloatImage linear;
    Renderer().render(*frame.scene, bytes, nullptr, nullptr, &linear);
    picture = encodeExr(linear);
  } else {
    picture = encodePng(frame.image);
  }
  Saved saved;
  for (int n = 1;; ++n) {
    const std::string stem = "illum_view_" + std::to_string(n);
    saved.picture = folder / (stem + (exr ? ".exr" : ".png"));
    saved.scene = folder / (stem + ".json");
    if (!std::filesystem::exists(saved.picture) && !std::filesystem::exists(saved.scene)) break;
  }
  writeOutputFile(saved.picture, picture);
  try {
    writeOutputFile(saved.scene, std::vector<std::uint8_t>(scene.begin(), scene.end()));
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(saved.picture, ignored);  // both or neither
    throw;
  }
  return saved;
}

}  // namespace illum::view
