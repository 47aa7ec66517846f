// The denoiser's constants and working planes (denoise.cpp and its lane kernels, only): padded
// float planes in one block, and the sets of them the passes, the guides and the fit use.
#pragma once

#include <cstddef>
#include <cstdlib>
#include <memory>
#include <new>

#include <sys/mman.h>

namespace illum::denoising {

// The filter's constants, tuned on the Cornell box, the built-in scene and glTF models against
// 4096-sample references (bench/denoise.sh).
constexpr int kPasses = 3;  // of the 3×3 kernel, taps 1, 2 and 4 pixels apart
constexpr float kSigmaColor = 4.0f;    // in standard deviations of the pixel's noise
constexpr float kSigmaNormal = 0.3f;   // |n_p − n_q| of unit normals (docs/ray-tracing.md: 0.1 → 0.3)
constexpr float kSigmaAlbedo = 0.04f;  // |a_p − a_q| (docs/ray-tracing.md: 0.02 → 0.04)
// |ln z_p − ln z_q| over a tap's distance in pixels: depths 1 % apart a pixel from each other
// (Cornell box 0.0014 → 0.0011 at 16 samples; 0.5 % or 2 %: 0.0012; the others as good or a little
// better). Two surfaces of one normal and albedo, one behind the other (an engine's fins and the
// gaps between them, a box's lid and what it stands on), are kept apart.
constexpr float kSigmaDepth = 0.01f;
// A pixel brighter than each of its 8 neighbours by less than this many standard errors of its own
// mean (an excess its noise explains: a rare bright path, not a feature) is brought down to the
// brightest of them before the passes (outlierScales and dimOutliers, denoise.cpp).
constexpr float kOutlierDeviations = 4.0f;
// The first-order fit at pixels that hold two surfaces (FitRows): how far a pixel's mean normal
// falls short of a unit normal where it is wholly a mixture, the ridge on the fit's slopes (in
// unscaled normal and albedo units), and how many times the variance left in the passes' value
// the fit may differ from it by, squared, and still be taken (its weight e^(−d²/(k·var))).
constexpr float kMixedShortfall = 0.02f;
constexpr float kFitRidge = 1e-2f;
constexpr float kFitAgreement = 8.0f;
// Pixels around the picture, as far as the widest pass reaches (a tap 2^(kPasses−1) away), whose
// normal is so far from any unit normal that their weight is exactly 0.
constexpr int kPad = 1 << (kPasses - 1);
constexpr float kFarNormal = 1e10f;
// Floats after each padded row that belong to no pixel: a vector that starts at a row's last pixel
// and a tap kPad to its right still ends inside its own row (and inside the planes at the last).
constexpr int kVectorSlack = 64;

// A plane of floats padded by kPad on every side, left uninitialised until its rows are written
// (in parallel: the first touch of its pages is shared by the threads, and nothing is zeroed twice).
struct Plane {
  float* values = nullptr;
  float* data() { return values; }
  const float* data() const { return values; }
};

// One block for every plane (19 of them, 3 MiB each at 1000×600), asked to be backed by the
// kernel's transparent huge pages: first touching 4 KiB pages one by one cost the filter 10k page
// faults a call, about a fifth of its time.
class PlaneArena {
 public:
  PlaneArena(std::size_t planes, std::size_t floats) : planeFloats_(floats) {
    constexpr std::size_t kHugePage = std::size_t(2) << 20;
    const std::size_t bytes = (planes * floats * sizeof(float) + kHugePage - 1) / kHugePage * kHugePage;
    block_.reset(static_cast<float*>(std::aligned_alloc(kHugePage, bytes)));
    if (!block_) throw std::bad_alloc();
#ifdef MADV_HUGEPAGE
    madvise(block_.get(), bytes, MADV_HUGEPAGE);  // a hint: without it the filter is slower, not wrong
#endif
  }
  float* plane(std::size_t i) { return block_.get() + i * planeFloats_; }

 private:
  struct Free {
    void operator()(float* p) const { std::free(p); }
  };
  std::unique_ptr<float, Free> block_;
  std::size_t planeFloats_;
};

struct Layout {
  int width, height, stride;
  std::size_t at(int x, int y) const { return std::size_t(y + kPad) * std::size_t(stride) + std::size_t(x + kPad); }
  std::size_t size() const { return std::size_t(stride) * std::size_t(height + 2 * kPad); }
};

// What a pass reads and writes: the colour, its luminance (what the colour term compares, computed
// once a pixel rather than once a tap) and its variance.
struct Planes {
  Plane color[3], luminance, variance;
};

// What guides every pass: the first hit's normal and albedo, each divided by its σ, so that a tap's
// squared distance in the six is its guides' share of the exponent, and the logarithm of its
// depth divided by its σ (0 where nothing was hit, or no depth was given), whose squared
// difference a pass divides by its taps' distance squared.
struct Guides {
  Plane normal[3], albedo[3], depth;
};

// The first-order fit's input (the radiance as it came, not divided by the albedo: a pixel that
// holds two surfaces is a mix of their radiances, weighed as its guides are) and its output: the
// fitted radiance and its weight against the passes' value (0: not a mixture, or no fit).
struct Fit {
  Plane radiance[3];            // in: the radiance as it came
  Plane fitted[3], weight;      // out
};

}  // namespace illum::denoising
