// `illum view`: the window (SDL2), its panels (Dear ImGui, drawn by SDL's renderer), and the
// picture drawn by illum's own renderer on the CPU off the input thread and shown as a streaming
// texture. Input is mapped onto the ViewState (view_state.h) as f3d maps it.
#pragma once

#include "scene_options.h"

#include <string>
#include <vector>

namespace illum::view {

// Opens the window on `files` (none: the built-in scene) and runs until it is closed. Throws
// InputError without a display ("no display: ..."), or when the first file cannot be drawn.
int runViewer(const std::vector<std::string>& files, const cli::SceneOptions& options);

}  // namespace illum::view
