// The pipeline's reference driver: every triangle drawn in submission order over the whole
// viewport on one thread, the way the first rasterizer worked. The test oracle for the binned,
// parallel pipeline (pipeline.cpp), whose images must equal these bit for bit.
#pragma once

#include <illum/render.h>

#include "shading/occlusion.h"

namespace illum {

// The scene's linear 8-bit picture, as RasterPipeline::draw gives it (render/ finishes both the
// same way: render/reference_render.h).
void drawSceneReference(const Scene& scene, Image& image, RenderStats& stats,
                        const OcclusionQuery* occlusion = nullptr);

}  // namespace illum
