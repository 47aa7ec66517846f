// Textures: an RGBA image with its mipmap chain, sampled like GL_LINEAR_MIPMAP_LINEAR with the
// texture's wrap modes (GL_REPEAT unless the model's sampler says otherwise). Every level is kept as GL keeps an RGBA8 texture, 8 bits a channel; the sampler
// decodes each texel it reads through a table (value/255, or sRGB to linear), so a 4096² texture
// costs its 64 MiB and a third more for the mipmaps.
#pragma once

#include <illum/image.h>
#include <illum/real.h>

#include <cstdint>
#include <vector>

namespace illum {

// How a texture's bytes encode its values: as they are (GL without sRGB textures, and data such as
// normal and metallic-roughness maps), or sRGB-encoded colour (GL_SRGB8_ALPHA8, glTF's colour
// textures), decoded to linear before filtering. Alpha is always linear.
enum class TexelEncoding { Linear, Srgb };

// What a texture coordinate outside [0, 1] reads, per axis (GL's TEXTURE_WRAP_S and _T, glTF's
// sampler wrapS and wrapT): the texture repeated, repeated mirrored every other time, or its edge
// texels stretched on (OpenGL 4.6, section 8.14.2, applied to the texel indices of GL_LINEAR).
enum class TextureWrap : std::uint8_t { Repeat, MirroredRepeat, ClampToEdge };
struct TextureWraps {
  TextureWrap s = TextureWrap::Repeat, t = TextureWrap::Repeat;
  bool operator==(const TextureWraps&) const = default;
};

class Texture {
 public:
  // Takes the image's bytes as the base level (moved in, not copied, when given an rvalue).
  explicit Texture(Image image, TexelEncoding encoding = TexelEncoding::Linear, TextureWraps wraps = {});
  TexelEncoding encoding() const { return encoding_; }
  TextureWraps wraps() const { return wraps_; }

  int width() const { return levels_.front().width; }
  int height() const { return levels_.front().height; }
  int levelCount() const { return int(levels_.size()); }
  bool hasTransparency() const { return hasTransparency_; }  // any texel with alpha < 1
  // The 8-bit image this texture was made from (its base level, rows top to bottom), exactly.
  const Image& baseImage() const { return levels_.front(); }
  // Bytes in memory, every level.
  std::size_t byteSize() const;

  // Trilinear sample at `uv` (GL convention: v = 0 is the image's bottom row) for a footprint of
  // `texelsPerPixel` base-level texels per pixel (the mip level is log2 of it).
  Vec4 sample(const Vec2& uv, Real texelsPerPixel) const;
  // Bilinear sample of one mip level.
  Vec4 sampleLevel(const Vec2& uv, int level) const;

  // What a sampler over SIMD lanes reads (src/image/texture_lanes-inl.h, the same filtering): a
  // level's RGBA8 image, and the value of each colour byte (alpha's: alphaTable(), byte/255).
  const Image& level(int i) const { return levels_[std::size_t(i)]; }
  const Real* colorTable() const { return decode_; }
  static const Real* alphaTable();
  // The colour table's entries as 32-bit floats, split into four planes of bytes (byte k of entry
  // i at 256·k + i, 64-byte aligned): what a sampler looks up with byte permutes.
  const std::uint8_t* colorTableBytes() const { return decodeBytes_; }

 private:
  // Each level an RGBA8 image, rows top to bottom as images are (row 0 is GL's v = 1 end).
  using Level = Image;
  Vec4 texel(const Level& level, int x, int glRow) const;
  std::vector<Level> levels_;
  const Real* decode_;  // 256 entries: a colour byte's value (alpha is always byte/255)
  const std::uint8_t* decodeBytes_;  // the same, as byte planes
  bool hasTransparency_ = false;
  TexelEncoding encoding_ = TexelEncoding::Linear;
  TextureWraps wraps_;
};

}  // namespace illum
