// The last steps of a picture, after whichever renderer drew it.
#pragma once

#include <illum/image.h>
#include <illum/render.h>
#include <illum/scene.h>

namespace illum {

// The rasterizer's linear 8-bit picture finished: its linear values copied to `linear` if asked,
// the scene's display encoding applied, then the scene's labels and gizmo drawn over it.
void finishRasterPicture(const Scene& scene, RenderStats& stats, Image& image, FloatImage* linear);

// The ray tracers encode their own pixels from the float means (ray_tracer.h): only the labels.
void finishTracedPicture(const Scene& scene, RenderStats& stats, Image& image);

}  // namespace illum
