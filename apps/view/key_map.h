// The viewer's keys, f3d's where the same action exists: what each key does, and the list the
// window shows on H or ?.
#pragma once

#include <SDL.h>

#include <optional>
#include <string_view>
#include <vector>

namespace illum::view {

enum class Action {
  Quit,           // Esc
  Reset,          // Enter: the framing
  Front, Back, Right, Left, Top, Bottom,  // 1, 3, 7 and with Ctrl the opposite views
  Edges,          // E
  Axes,           // X
  Grid,           // G
  FrameRate,      // Z
  AntiAliasing,   // A
  Occlusion,      // Q
  Environment,    // F (environment lighting)
  Help,           // H or ?
  Panels,         // Tab
  Next, Previous, // arrows, Page Down/Up: the files
  Save,           // F12 or Ctrl+S: the picture
  Unwatch,        // Backspace: no watched pixel
};

std::optional<Action> actionFor(SDL_Keycode key, Uint16 mod);

struct KeyHelp {
  std::string_view keys, what;
};
// Every key with what it does, in the order the window lists them.
const std::vector<KeyHelp>& keyHelp();

}  // namespace illum::view
