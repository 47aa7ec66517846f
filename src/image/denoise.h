// The path tracer's denoiser: the edge-avoiding À-trous wavelet filter of Dammertz, Sewtz, Hanika
// and Lensch ("Edge-Avoiding À-Trous Wavelet Transform for fast Global Illumination Filtering",
// HPG 2010), guided by the first non-specular hit's albedo, normal and depth (z, its distance from
// the eye: compared relative to itself and to the taps' distance), with the colour's edge
// stopping scaled by each pixel's estimated variance as in Schied et al.'s SVGF (HPG 2017):
//   three passes i = 0..2 of a 3×3 kernel h = (1 2 1)/4 ⊗ (1 2 1)/4 whose taps lie 2^i pixels apart
//   (Dammertz et al.'s 5×5 B3 spline over five passes blurred more than the noise needs once the
//   colour term scales with the variance: bench/denoise.sh's error fell on all three inputs, in
//   a third of the time),
//   c'(p) = Σ_q h(q) w(p,q) c(q) / Σ_q h(q) w(p,q),
//   w(p,q) = exp(−(l_p − l_q)² / (σ_c²·var(p) + ε) − |n_p − n_q|² / σ_n² − |a_p − a_q|² / σ_a²
//                − (ln z_p − ln z_q)² / (σ_z·2^i)²),
//   (l the colour's luminance; var the variance of its mean, blurred 3×3 before the first pass),
//   var'(p) = Σ (h w)² var(q) / (Σ h w)²   (the variance of the filtered value, for the next pass).
// The colour filtered is the radiance divided by the albedo (texture detail is put back after,
// not blurred), channel by channel where the albedo is not near black (demodulate). Before the
// passes, a pixel brighter than all 8 neighbours of its kind (those that hit a surface, or those
// that hit nothing, as it did) by less than 4 standard errors of its mean (one rare bright path
// among its samples, most likely) is brought down to the brightest of them.
// A pixel that holds two surfaces (its mean normal shorter than a unit one) matches no neighbour
// and comes out of the passes nearly as noisy as it went in; there a first-order fit of the
// radiance over its 3×3 neighbours as an affine function of the guides (Bitterli et al. 2016's
// regression, in its simplest form) gives its value as the mix its guides say it is, taken where
// it agrees with the passes' value within the noise.
// SIMD (Highway, with an exponential of plain multiplications and additions, so every target gives
// the same bits) and threaded by rows: the same input gives the same bytes on every machine and
// thread count.
#pragma once

#include <cstddef>
#include <span>

namespace illum {

// A colour channel divided by the albedo's, unless that is too dark to divide by.
constexpr float kDenoiseMinAlbedo = 0.02f;
inline float demodulationOf(float albedo) { return albedo > kDenoiseMinAlbedo ? albedo : 1.0f; }
// What a colour divided by demodulationOf(divided) is multiplied back by: `albedo`, a truer one
// (DenoiseInput's guides taken over more samples), where both can be divided by; else what it
// was divided by.
inline float remodulationOf(float albedo, float divided) {
  return albedo > kDenoiseMinAlbedo && divided > kDenoiseMinAlbedo ? albedo : demodulationOf(divided);
}

struct DenoiseInput {
  int width = 0, height = 0;
  std::span<const float> color;     // RGBA per pixel: the radiance (linear, unclamped) and alpha
  std::span<const float> albedo;    // RGB per pixel: the first non-specular hit's albedo (0: none)
  std::span<const float> normal;    // RGB per pixel: its normal (0 where nothing was hit), a mean
                                    // of unit normals: shorter than 1 where they differ
  // Per pixel: the variance of the mean of the samples' luminances, each sample's radiance
  // divided by its albedo (demodulationOf each channel).
  std::span<const float> variance;
  // Per pixel: the mean distance from the eye to the first hit (0 where nothing was hit); empty:
  // not a guide.
  std::span<const float> depth = {};
  // RGB per pixel: the albedo the colour's own samples saw, which it is divided by, where the
  // guides (`albedo`, `normal`, `depth`) were taken over more samples than the colour (a truer
  // albedo at a texture's edge, which the filtered colour is multiplied back by: remodulationOf);
  // empty: `albedo`'s.
  std::span<const float> demodulation = {};
};

// The rows [first, end) of a layer that have anything in it (a normal: something was seen there).
struct LayerRows {
  int first = 0, end = 0;
  bool empty() const { return first == end; }
};
LayerRows layerRows(const DenoiseInput& layer);

// The filtered radiance, RGBA per pixel into `out` (width·height·4 floats), alpha as it came.
void denoise(const DenoiseInput& in, std::span<float> out);

// A picture in two layers, each filtered by its own guides and their sum written into `out`: the
// surfaces the paths first met, and what part mirrors there reflected (guided by what the mirrors
// saw, as the path tracer splits them: path_tracer.h's PathFeatures; 0 with a 0 normal where a
// pixel has no reflection). Its alpha is the surfaces'.
void denoiseLayers(const DenoiseInput& surfaces, const DenoiseInput& reflections, std::span<float> out);

}  // namespace illum
