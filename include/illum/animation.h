// Animations (turntables, orbiting lights) as single files: an animated GIF through giflib (each
// frame quantized to its own 256-colour palette, fully transparent pixels kept transparent) and a
// lossless animated WebP through libwebp, both looping forever. Frames are equal-sized RGBA.
#pragma once

#include <illum/image.h>

#include <cstdint>
#include <vector>

namespace illum {

std::vector<std::uint8_t> encodeGif(const std::vector<Image>& frames, int delayMs);
std::vector<std::uint8_t> encodeWebp(const std::vector<Image>& frames, int delayMs);

}  // namespace illum
