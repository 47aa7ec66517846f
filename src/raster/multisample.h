// Multisampling's two ends: where the samples of a pixel lie (the standard patterns of Direct3D
// 10.1, which GPUs use for 4, 8 and 16 samples), and the resolve that averages the sample passes
// into one picture with premultiplied alpha, so that an edge over a transparent background keeps
// the object's colour and takes the coverage as alpha (no dark or light halo).
#pragma once

#include <illum/image.h>

#include "raster/frame_context.h"

#include <cstdint>
#include <span>
#include <vector>

namespace illum {

// The sample offsets from the pixel centre for `count` samples (1: the centre alone).
std::span<const SubpixelOffset> multisamplePattern(int count);

class MultisampleResolve {
 public:
  MultisampleResolve(int width, int height);
  // One sample pass's picture (straight alpha, as the framebuffer holds it).
  void add(const Image& pass);
  // The average: colour Σ(c·a) / Σa (Σc / n where no sample has alpha), alpha Σa / n, rounded.
  void finish(Image& out) const;

 private:
  int width_, height_, passes_ = 0;
  std::vector<std::uint32_t> premultiplied_;  // Σ c·a per colour channel, Σ a for alpha
  std::vector<std::uint32_t> straight_;       // Σ c per colour channel
};

}  // namespace illum
