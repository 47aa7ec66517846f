// How linear values become the bytes of a picture: an optional tone map for radiance above 1
// (Reinhard's x/(1+x), or Narkowicz's fit of the ACES filmic curve), then an encoding, linear (what
// OpenGL writes without GL_FRAMEBUFFER_SRGB, and what the seeds compute) or sRGB (IEC 61966-2-1, what
// screens expect). Alpha is never changed.
#pragma once

#include <illum/image.h>
#include <illum/real.h>
#include <illum/tone_map.h>

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

namespace illum {

std::string_view toString(ToneMap toneMap);
std::string_view toString(Encoding encoding);
std::optional<ToneMap> parseToneMap(std::string_view name);
std::optional<Encoding> parseEncoding(std::string_view name);

struct Display {
  ToneMap toneMap = ToneMap::None;
  Encoding encoding = Encoding::Linear;
  bool identity() const { return toneMap == ToneMap::None && encoding == Encoding::Linear; }
};

// What is left of a display for the rasterizer's framebuffer, whose lit colours took the tone map
// before they were quantised (LightModel::toneMap): the encoding.
inline Display encodingOnly(const Display& display) { return {ToneMap::None, display.encoding}; }

// The tone map alone: none leaves x as it is (clamped later), the others map [0, ∞) into [0, 1).
Real toneMapped(Real x, ToneMap toneMap);
// sRGB's transfer function for x in [0, 1]: 12.92·x up to 0.0031308, else 1.055·x^(1/2.4) − 0.055.
Real srgbEncoded(Real x);
// Its inverse, for colour textures stored sRGB-encoded: x/12.92 up to 0.04045, else ((x+0.055)/1.055)^2.4.
Real srgbDecoded(Real x);
// The displayed value of a linear colour channel, in [0, 1].
Real displayValue(Real x, const Display& display);

// The bytes a background pixel has in every renderer's picture: the colour encoded, not tone
// mapped (a tone map shapes radiance, not the backdrop behind it), round(c·255).
std::array<std::uint8_t, 4> backgroundBytes(const Vec4& background, const Display& display);

// Re-encodes an 8-bit image whose RGB bytes are linear values (the rasterizer's framebuffer, which
// is 8-bit as GL's is) through a table of the 256 displayed values. Pixels that hold exactly the
// `background` colour's bytes get its encoded value computed from the colour itself, without the
// tone map (which shapes radiance, not the backdrop), so that a background comes out the same
// bytes from every renderer, tone map or not.
void applyDisplay(Image& image, const Display& display, const Vec4* background = nullptr);

}  // namespace illum
