// The viewer's panels, for what the seeds teach: the lighting model, shading frequency and
// renderer; each light (kind, position or direction, colours, attenuation, spot) with its own
// on/off; each material (GL colours and shininess, or base colour, metallic, roughness); samples,
// ray depth, shadows, occlusion and overlays; the terms of the equation; saving. Each control names the scene key or CLI option it
// changes, and changes it in the ViewState's scene; then the watched pixel's report.
#pragma once

#include "render_worker.h"
#include "view_state.h"

#include <array>
#include <optional>
#include <vector>

namespace illum::view {

// The lights the person switched off: each one's values, to put back when it is switched on.
struct PanelState {
  std::vector<std::optional<Light>> parked;
  std::string message;  // the last error or notice, shown until the next
  bool handles = true;  // the lights' handles over the picture
  bool exr = false;     // save OpenEXR's linear values instead of a PNG
  bool save = false;    // the save button was pressed
};

// The panels' width: they stand beside the picture, never over it.
constexpr int kPanelWidth = 460;
// Draws them at x = `left`, the window's height tall, without a background of their own: the
// window fills their strip with panelBackground() first, one opaque fill (on SDL's software
// renderer ImGui's background would be a textured, blended rectangle, per pixel the slowest thing
// it draws: a quarter of presenting's time at 1280×720).
void drawPanels(ViewState& state, PanelState& panels, const Frame* frame, double fps, int left, int height);
void drawHelp();
// The panels' background: the style's window colour over black, as ImGui would have blended it.
std::array<unsigned char, 3> panelBackground();

}  // namespace illum::view
