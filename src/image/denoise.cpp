// The À-trous denoiser (denoise.h): the driver, with its lane kernels (denoise_passes-inl.h,
// denoise_fit-inl.h) compiled once per SIMD target (Highway's foreach_target) and dispatched at
// run time.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "image/denoise.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

#include "image/denoise.h"
#include "image/denoise_fit-inl.h"
#include "image/denoise_passes-inl.h"
#include "image/denoise_planes.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <vector>

#if HWY_ONCE
namespace illum {

using namespace denoising;

HWY_EXPORT(FilterRows);
HWY_EXPORT(LuminanceRows);
HWY_EXPORT(FitRows);
HWY_EXPORT(OutlierRows);

namespace {

// The outliers: a pixel whose luminance l exceeds the largest of its 8 neighbours' m (in the
// picture) by less than kOutlierDeviations standard errors of its mean (the blurred variance) gets
// the scale m / l (else 1; OutlierRows, denoise_passes-inl.h): such a pixel is most likely one rare
// bright path among its samples (its own variance is what that path made it), which the colour
// term would keep apart from its neighbours, where a converged small highlight stands out by far
// more than its noise and stays. A pixel that hit a surface is compared with the neighbours that
// hit one, a pixel that hit nothing with those that hit nothing, and one that has none of its kind
// around it is kept: a lone object a pixel wide on the background is not noise of the background's.
//
// The scales applied (after every pixel has been compared with its neighbours as they came): to
// the colour the passes filter, its luminance and the radiance the fit reads.
void dimOutliers(const Layout& layout, const float* scale, Planes& first, Fit& fit, int y0, int y1) {
  for (int y = y0; y < y1; ++y)
    for (int x = 0; x < layout.width; ++x) {
      const std::size_t at = layout.at(x, y);
      const float f = scale[at];
      if (f == 1.0f) continue;
      for (int k = 0; k < 3; ++k) first.color[k].data()[at] *= f, fit.radiance[k].data()[at] *= f;
      first.luminance.data()[at] *= f;
    }
}

constexpr std::size_t kArenaPlanes = 2 * 5 + 7 + 3;  // the passes' two sets, the guides, the fit's input

Layout layoutOf(int width, int height) { return Layout{width, height, width + 2 * kPad + kVectorSlack}; }

// The albedo channel k of pixel i's colour was seen with (DenoiseInput::demodulation).
float dividedBy(const DenoiseInput& in, std::size_t i, int k) {
  return (in.demodulation.empty() ? in.albedo : in.demodulation)[3 * i + std::size_t(k)];
}

// The filter, its planes in `arena` (as big as the picture's layout needs, or bigger).
void denoiseIn(PlaneArena& arena, const DenoiseInput& in, std::span<float> out) {
  const int w = in.width, h = in.height;
  const Layout layout = layoutOf(w, h);
  Planes planes[2];
  Guides guides;
  Fit fit;
  std::size_t next = 0;
  for (Planes& p : planes)
    for (Plane* plane : {&p.color[0], &p.color[1], &p.color[2], &p.luminance, &p.variance}) plane->values = arena.plane(next++);
  for (int k = 0; k < 3; ++k) guides.normal[k].values = arena.plane(next++), guides.albedo[k].values = arena.plane(next++);
  guides.depth.values = arena.plane(next++);
  for (Plane* plane : {&fit.radiance[0], &fit.radiance[1], &fit.radiance[2]}) plane->values = arena.plane(next++);
  // The fit's output goes where the passes are done with: the planes the last pass read.
  const Planes& last = planes[kPasses % 2];
  Planes& spent = planes[(kPasses + 1) % 2];
  for (int k = 0; k < 3; ++k) fit.fitted[k].values = spent.color[k].values;
  fit.weight.values = spent.luminance.values;
  // Every padded row, in parallel: the padding's colour 0 and its normal so far from any unit
  // normal that a tap there weighs exactly 0; inside, the demodulated colour, the guides (the
  // depth as its logarithm: a difference of logarithms is the relative one), and the
  // variance estimated from a pixel's own samples, which is noisy itself: blurred 3×3 (1 2 1)
  // within the picture. Inside a row only the padding is filled: the pixels are written below
  // (the first planes and the guides) or by the first pass (the second planes).
  tbb::parallel_for(tbb::blocked_range<int>(-kPad, h + kPad, 8), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y < rows.end(); ++y) {
      const std::size_t row = std::size_t(y + kPad) * std::size_t(layout.stride);
      const bool inside = y >= 0 && y < h;
      const auto fill = [&](float* plane, float value) {
        if (!inside) {
          std::fill_n(plane + row, layout.stride, value);
          return;
        }
        std::fill_n(plane + row, kPad, value);
        std::fill(plane + row + std::size_t(kPad + w), plane + row + std::size_t(layout.stride), value);
      };
      for (Planes& p : planes)
        for (Plane* plane : {&p.color[0], &p.color[1], &p.color[2], &p.luminance, &p.variance}) fill(plane->data(), 0.0f);
      for (int k = 0; k < 3; ++k) {
        fill(guides.normal[k].data(), kFarNormal);
        fill(guides.albedo[k].data(), 0.0f);
        fill(fit.radiance[k].data(), 0.0f);
      }
      fill(guides.depth.data(), 0.0f);
      if (!inside) continue;
      for (int x = 0; x < w; ++x) {
        const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x), at = layout.at(x, y);
        for (int k = 0; k < 3; ++k) {
          const float a = in.albedo[3 * i + std::size_t(k)];
          // The albedo divided out (1 where it is near black), multiplied back in at the end.
          planes[0].color[k].data()[at] = in.color[4 * i + std::size_t(k)] / demodulationOf(dividedBy(in, i, k));
          fit.radiance[k].data()[at] = in.color[4 * i + std::size_t(k)];
          guides.normal[k].data()[at] = in.normal[3 * i + std::size_t(k)] * (1 / kSigmaNormal);
          guides.albedo[k].data()[at] = a * (1 / kSigmaAlbedo);
        }
        const float z = in.depth.empty() ? 0.0f : in.depth[i];
        guides.depth.data()[at] = z > 0 ? std::log(z) * (1 / kSigmaDepth) : 0.0f;
        float sum = 0, weight = 0;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const int qx = x + dx, qy = y + dy;
            if (qx < 0 || qy < 0 || qx >= w || qy >= h) continue;
            const float k = float((2 - std::abs(dx)) * (2 - std::abs(dy)));
            sum += k * in.variance[std::size_t(qy) * std::size_t(w) + std::size_t(qx)];
            weight += k;
          }
        planes[0].variance.data()[at] = sum / weight;
      }
    }
  });
  tbb::parallel_for(tbb::blocked_range<int>(0, h, 8), [&](const tbb::blocked_range<int>& rows) {
    HWY_DYNAMIC_DISPATCH(LuminanceRows)(layout, planes[0], rows.begin(), rows.end());
  });
  // The outliers' scales go to a plane the first pass has yet to write.
  float* scale = planes[1].luminance.data();
  tbb::parallel_for(tbb::blocked_range<int>(0, h, 8), [&](const tbb::blocked_range<int>& rows) {
    HWY_DYNAMIC_DISPATCH(OutlierRows)(layout, planes[0], guides, scale, rows.begin(), rows.end());
  });
  tbb::parallel_for(tbb::blocked_range<int>(0, h, 8), [&](const tbb::blocked_range<int>& rows) {
    dimOutliers(layout, scale, planes[0], fit, rows.begin(), rows.end());
  });
  for (int pass = 0; pass < kPasses; ++pass) {
    const Planes& from = planes[pass % 2];
    Planes& to = planes[(pass + 1) % 2];
    tbb::parallel_for(tbb::blocked_range<int>(0, h, 8), [&](const tbb::blocked_range<int>& rows) {
      HWY_DYNAMIC_DISPATCH(FilterRows)(layout, guides, !in.depth.empty(), from, to, 1 << pass, rows.begin(), rows.end());
    });
  }
  tbb::parallel_for(tbb::blocked_range<int>(0, h, 8), [&](const tbb::blocked_range<int>& rows) {
    HWY_DYNAMIC_DISPATCH(FitRows)(layout, guides, last, fit, rows.begin(), rows.end());
    for (int y = rows.begin(); y < rows.end(); ++y)
      for (int x = 0; x < w; ++x) {
        const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x), at = layout.at(x, y);
        const float weight = fit.weight.data()[at];
        for (int k = 0; k < 3; ++k) {
          float c = last.color[k].data()[at] * remodulationOf(in.albedo[3 * i + std::size_t(k)], dividedBy(in, i, k));
          if (weight > 0) c = weight * fit.fitted[k].data()[at] + (1 - weight) * c;
          out[4 * i + std::size_t(k)] = c;
        }
        out[4 * i + 3] = in.color[4 * i + 3];
      }
  });
}

}  // namespace

void denoise(const DenoiseInput& in, std::span<float> out) {
  PlaneArena arena(kArenaPlanes, layoutOf(in.width, in.height).size());
  denoiseIn(arena, in, out);
}

LayerRows layerRows(const DenoiseInput& layer) {
  const std::size_t width = std::size_t(layer.width);
  const auto seen = [&](int y) {
    const auto row = layer.normal.begin() + std::ptrdiff_t(3 * std::size_t(y) * width);
    return std::any_of(row, row + std::ptrdiff_t(3 * width), [](float n) { return n != 0; });
  };
  LayerRows rows{0, layer.height};
  while (!rows.empty() && !seen(rows.first)) ++rows.first;
  while (!rows.empty() && !seen(rows.end - 1)) --rows.end;
  return rows;
}

void denoiseLayers(const DenoiseInput& surfaces, const DenoiseInput& reflections, std::span<float> out) {
  const int w = surfaces.width, h = surfaces.height;
  PlaneArena arena(kArenaPlanes, layoutOf(w, h).size());  // one for both: its pages are touched once
  denoiseIn(arena, surfaces, out);
  // The reflections over the rows that have any (what a mirror saw); elsewhere they are 0, and
  // filtering them would cost as much as the surfaces.
  const std::size_t width = std::size_t(w);
  const LayerRows reflected = layerRows(reflections);
  if (reflected.empty()) return;
  const int y0 = reflected.first, y1 = reflected.end;
  const std::size_t first = std::size_t(y0) * width, pixels = std::size_t(y1 - y0) * width;
  const DenoiseInput rows{w, y1 - y0, reflections.color.subspan(4 * first, 4 * pixels),
                          reflections.albedo.subspan(3 * first, 3 * pixels), reflections.normal.subspan(3 * first, 3 * pixels),
                          reflections.variance.subspan(first, pixels)};
  std::vector<float> filtered(4 * pixels);
  denoiseIn(arena, rows, filtered);
  for (std::size_t i = 0; i < filtered.size(); ++i)
    if (i % 4 != 3) out[4 * first + i] += filtered[i];
}

}  // namespace illum
#endif  // HWY_ONCE
