// The last step: scene labels drawn over the finished image.
#pragma once

#include <illum/image.h>
#include <illum/scene.h>

namespace illum {

// The axes gizmo too, when the scene asks for it. Returns false when the scene has labels but the
// label font cannot be loaded.
bool drawLabels(Image& image, const Scene& scene);

}  // namespace illum
