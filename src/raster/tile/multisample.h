// Multisampling's two ends: where the samples of a pixel lie (the standard patterns of Direct3D
// 10.1, which GPUs use for 4, 8 and 16 samples), and the resolve that averages a pixel's samples
// into one with premultiplied alpha, so that an edge over a transparent background keeps the
// object's colour and takes the coverage as alpha (no dark or light halo).
#pragma once

#include "raster/frame_context.h"

#include <cstddef>
#include <cstdint>
#include <span>

namespace illum {

// The sample offsets from the pixel centre for `count` samples (1: the centre alone).
std::span<const SubpixelOffset> multisamplePattern(int count);

// One pixel from its n samples' RGBA8 words: colour Σ(c·a) / Σa (Σc / n where no sample has
// alpha), alpha Σa / n, each rounded to nearest. A pixel whose samples agree is that colour.
std::uint32_t resolvePixel(const std::uint32_t* samples, int n);

// resolvePixel over `rows` rows of `count` pixels, each `samples` words side by side: row r of the
// source starts at src + r·srcRowPixels·samples, of the output (RGBA8 bytes) at dst + r·dstStride
// bytes (which may be negative: an image's rows run the other way). Returns how many differ from
// `background` (an RGBA8 word).
std::size_t resolvePixels(const std::uint32_t* src, int samples, int srcRowPixels, std::uint8_t* dst,
                          std::ptrdiff_t dstStride, int count, int rows, std::uint32_t background);

}  // namespace illum
