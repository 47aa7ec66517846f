#include "render/finish.h"

#include <illum/display.h>

#include "render/environment_behind.h"
#include "render/labels.h"

namespace illum {

void finishRasterPicture(const Scene& scene, RenderStats& stats, Image& image, FloatImage* linear,
                         bool environmentBehind) {
  if (linear) {
    *linear = FloatImage{image.width, image.height, std::vector<float>(image.rgba.size()), {}};
    for (std::size_t i = 0; i < image.rgba.size(); ++i) linear->rgba[i] = float(image.rgba[i]) / 255;
  }
  applyDisplay(image, encodingOnly(scene.display), &scene.background);
  finishTracedPicture(scene, stats, image, environmentBehind);
}

void finishTracedPicture(const Scene& scene, RenderStats& stats, Image& image, bool environmentBehind) {
  if (environmentBehind) layEnvironmentBehind(scene, image);
  stats.labelsSkipped = !drawLabels(image, scene);
}

}  // namespace illum
