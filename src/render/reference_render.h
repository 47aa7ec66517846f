// The rasterizer's reference driver (raster/reference/), finished as every picture is: the oracle
// the parallel pipeline's pictures are compared with, bit for bit.
#pragma once

#include <illum/render.h>

namespace illum {

Image renderSceneReference(const Scene& scene, RenderStats* stats = nullptr);

}  // namespace illum
