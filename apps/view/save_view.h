// Keeping what the window shows, as a figure for slides: the picture (PNG, or OpenEXR's linear
// values) and its scene as a scene file that `illum render` draws to the same bytes.
#pragma once

#include "render_worker.h"

#include <filesystem>

namespace illum::view {

struct Saved {
  std::filesystem::path picture, scene;
};

// Writes `frame` (a final one: the scene's own sample count) under the first free names
// illum_view_N.png (or .exr) and illum_view_N.json in `folder`; nothing is replaced. Throws Error
// when either cannot be written (a scene whose objects no file made, a full disk); then neither is
// left behind.
Saved saveView(const Frame& frame, bool exr, const std::filesystem::path& folder = ".");

}  // namespace illum::view
