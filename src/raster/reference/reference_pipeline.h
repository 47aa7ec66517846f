// The pipeline's reference driver: every triangle drawn in submission order over the whole
// viewport on one thread, the way the first rasterizer worked. The test oracle for the binned,
// parallel pipeline (pipeline.cpp), whose images must equal these bit for bit.
#pragma once

#include <illum/render.h>

namespace illum {

Image renderSceneReference(const Scene& scene, RenderStats* stats = nullptr);

}  // namespace illum
