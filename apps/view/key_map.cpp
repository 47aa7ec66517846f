#include "key_map.h"

namespace illum::view {

std::optional<Action> actionFor(SDL_Keycode key, Uint16 mod) {
  const bool ctrl = (mod & KMOD_CTRL) != 0;
  switch (key) {
    case SDLK_ESCAPE: return Action::Quit;
    case SDLK_RETURN:
    case SDLK_KP_ENTER: return Action::Reset;
    case SDLK_1:
    case SDLK_KP_1: return ctrl ? Action::Back : Action::Front;
    case SDLK_3:
    case SDLK_KP_3: return ctrl ? Action::Left : Action::Right;
    case SDLK_7:
    case SDLK_KP_7: return ctrl ? Action::Bottom : Action::Top;
    case SDLK_e: return Action::Edges;
    case SDLK_x: return Action::Axes;
    case SDLK_g: return Action::Grid;
    case SDLK_z: return Action::FrameRate;
    case SDLK_a: return Action::AntiAliasing;
    case SDLK_q: return Action::Occlusion;
    case SDLK_f: return Action::Environment;
    case SDLK_h:
    case SDLK_QUESTION: return Action::Help;
    case SDLK_SLASH: return (mod & KMOD_SHIFT) ? std::optional(Action::Help) : std::nullopt;
    case SDLK_TAB: return Action::Panels;
    case SDLK_RIGHT:
    case SDLK_DOWN:
    case SDLK_PAGEDOWN: return Action::Next;
    case SDLK_LEFT:
    case SDLK_UP:
    case SDLK_PAGEUP: return Action::Previous;
    case SDLK_F12: return Action::Save;
    case SDLK_s: return ctrl ? std::optional(Action::Save) : std::nullopt;
    case SDLK_BACKSPACE: return Action::Unwatch;
    default: return std::nullopt;
  }
}

const std::vector<KeyHelp>& keyHelp() {
  static const std::vector<KeyHelp> help = {
      {"left drag", "turn about the focal point"},
      {"right drag, wheel", "zoom"},
      {"middle drag, Shift+left drag", "pan"},
      {"click", "watch a pixel: its --debug-pixel report"},
      {"Enter", "back to the framing"},
      {"1, 3, 7", "front, right, top view (Ctrl: back, left, bottom)"},
      {"E", "edges (--edges)"},
      {"X", "axes (--axes)"},
      {"G", "grid (--grid)"},
      {"A", "anti-aliasing: 8 samples or 1 (--samples)"},
      {"Q", "ambient occlusion (--ambient-occlusion)"},
      {"F", "environment lighting (the scene's map, or illum's studio)"},
      {"Z", "frame rate and the last frame's time"},
      {"Tab", "the panels"},
      {"H, ?", "this list"},
      {"arrows, Page Up/Down", "the previous or next file"},
      {"F12, Ctrl+S", "save the picture (PNG)"},
      {"Backspace", "stop watching the pixel"},
      {"drop a file", "open it"},
      {"Esc", "quit"},
  };
  return help;
}

}  // namespace illum::view
