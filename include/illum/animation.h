// Animations (turntables, orbiting lights) as single files: an animated GIF through giflib (each
// frame quantized to its own 256-colour palette, fully transparent pixels kept transparent) and a
// lossless animated WebP through libwebp, both looping forever. Frames are equal-sized RGBA, and go
// to the encoder one by one as they are drawn: a long turntable holds its encoded bytes, never its
// pictures.
#pragma once

#include <illum/image.h>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace illum {

class AnimationEncoder {
 public:
  virtual ~AnimationEncoder() = default;
  // The next frame, of the size the encoder was made for.
  virtual void add(const Image& frame) = 0;
  // The file's bytes, once every frame was added (at least one).
  virtual std::vector<std::uint8_t> finish() = 0;
};

// `exact`: a colour (the background's) that every frame's palette holds exactly, for the pixels of
// exactly that colour; the others are quantized.
std::unique_ptr<AnimationEncoder> makeGifEncoder(int width, int height, int delayMs,
                                                 std::optional<std::array<std::uint8_t, 3>> exact = std::nullopt);
std::unique_ptr<AnimationEncoder> makeWebpEncoder(int width, int height, int delayMs);

}  // namespace illum
