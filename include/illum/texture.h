// Textures: an RGBA image with its mipmap chain, sampled like GL_LINEAR_MIPMAP_LINEAR with
// GL_REPEAT. Texel values are used as stored (GL without sRGB decoding), scaled to [0,1].
#pragma once

#include <illum/image.h>
#include <illum/real.h>

#include <vector>

namespace illum {

// How a texture's bytes encode its values: as they are (GL without sRGB textures, and data such as
// normal and metallic-roughness maps), or sRGB-encoded colour (GL_SRGB8_ALPHA8, glTF's colour
// textures), decoded to linear before filtering. Alpha is always linear.
enum class TexelEncoding { Linear, Srgb };

class Texture {
 public:
  explicit Texture(const Image& image, TexelEncoding encoding = TexelEncoding::Linear);
  TexelEncoding encoding() const { return encoding_; }

  int width() const { return levels_.front().width; }
  int height() const { return levels_.front().height; }
  int levelCount() const { return int(levels_.size()); }
  bool hasTransparency() const { return hasTransparency_; }  // any texel with alpha < 1
  // The 8-bit image this texture was made from (its base level, rows top to bottom, re-encoded as
  // it was stored), exactly.
  Image baseImage() const;

  // Trilinear sample at `uv` (GL convention: v = 0 is the image's bottom row) for a footprint of
  // `texelsPerPixel` base-level texels per pixel (the mip level is log2 of it).
  Vec4 sample(const Vec2& uv, Real texelsPerPixel) const;
  // Bilinear sample of one mip level.
  Vec4 sampleLevel(const Vec2& uv, int level) const;

 private:
  struct Level {
    int width, height;
    std::vector<Vec4> texels;  // rows bottom to top, as GL stores them
  };
  std::vector<Level> levels_;
  bool hasTransparency_ = false;
  TexelEncoding encoding_ = TexelEncoding::Linear;
};

}  // namespace illum
