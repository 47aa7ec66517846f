// The last steps of a picture, after whichever renderer drew it.
#pragma once

#include <illum/image.h>
#include <illum/render.h>
#include <illum/scene.h>

namespace illum {

// The rasterizer's linear 8-bit picture finished: its linear values copied to `linear` if asked,
// the scene's display encoding applied, the environment laid behind it when it was drawn over a
// transparent background for that (environment_behind.h), then the scene's labels and gizmo.
void finishRasterPicture(const Scene& scene, RenderStats& stats, Image& image, FloatImage* linear,
                         bool environmentBehind = false);

// The ray tracers encode their own pixels from the float means (ray_tracer.h): the environment
// behind, where asked, and the labels.
void finishTracedPicture(const Scene& scene, RenderStats& stats, Image& image, bool environmentBehind = false);

}  // namespace illum
