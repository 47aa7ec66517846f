// Overlays drawn into the rasterizer's framebuffer after the scene, per multisample pass (so they
// are anti-aliased like edges): lines in world space, depth-tested against the surfaces (a line on
// a surface shows, one behind it does not) without writing depth. (The axes gizmo is drawn over
// the finished picture of any renderer: render/labels.h.)
#pragma once

#include <illum/scene.h>

#include "raster/frame_context.h"
#include "raster/tile/framebuffer.h"

#include <span>
#include <vector>

namespace illum {

struct OverlayLine {
  Vec3 a, b;  // world space
  Color3 color;
};

// The lines the scene's overlays ask for: each object's edges (each once), and a ground grid on
// the plane below everything, across the camera's up axis, at a round spacing.
std::vector<OverlayLine> overlayLines(const Scene& scene);

// Draws `lines` `width` pixels wide into one of `fb`'s samples as the frame sees them (its sample
// position too).
void drawOverlayLines(Framebuffer& fb, const FrameContext& frame, std::span<const OverlayLine> lines, Real width,
                      int sample = 0);

}  // namespace illum
