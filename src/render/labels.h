// The last step of every renderer's picture: the scene's labels and axes gizmo drawn over it.
#pragma once

#include <illum/image.h>
#include <illum/scene.h>

namespace illum {

// The world's X (red), Y (green) and Z (blue) axes as the camera sees them, from a point in the
// picture's lower left corner, labelled.
void drawAxesGizmo(Image& image, const Scene& scene);

// The axes gizmo too, when the scene asks for it. Returns false when the scene has labels but the
// label font cannot be loaded.
bool drawLabels(Image& image, const Scene& scene);

}  // namespace illum
