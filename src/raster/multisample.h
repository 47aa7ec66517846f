// Multisampling's two ends: where the samples of a pixel lie (the standard patterns of Direct3D
// 10.1, which GPUs use for 4, 8 and 16 samples), and the resolve that averages a pixel's samples
// into one with premultiplied alpha, so that an edge over a transparent background keeps the
// object's colour and takes the coverage as alpha (no dark or light halo).
#pragma once

#include <illum/image.h>

#include "raster/frame_context.h"
#include "raster/framebuffer.h"

#include <cstdint>
#include <span>

namespace illum {

// The sample offsets from the pixel centre for `count` samples (1: the centre alone).
std::span<const SubpixelOffset> multisamplePattern(int count);

// The resolve of one tile (as Framebuffer numbers them) whose samples are kept one per
// framebuffer, into `image` (row 0 at the top): per pixel, colour Σ(c·a) / Σa (Σc / n where no
// sample has alpha), alpha Σa / n, rounded to nearest. Returns how many pixels differ from
// `background8` (an RGBA8 word).
std::size_t resolveTile(std::span<const Framebuffer> samples, int tile, Image& image, std::uint32_t background8);

}  // namespace illum
