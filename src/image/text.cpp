#include "image/text.h"

// stb_truetype compiled here, its functions static to this file: no other library (Dear ImGui
// links the system's copy) can bind to illum's.
#define STBTT_STATIC
#define STB_TRUETYPE_IMPLEMENTATION
#include <stb_truetype.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <vector>

namespace illum {
namespace {

struct Font {
  std::vector<unsigned char> data;
  stbtt_fontinfo info{};
  bool ok = false;
};

const Font& labelFont() {
  static const Font font = [] {
    Font f;
    std::ifstream in(kLabelFontPath, std::ios::binary);
    f.data.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    f.ok = !f.data.empty() && stbtt_InitFont(&f.info, f.data.data(), stbtt_GetFontOffsetForIndex(f.data.data(), 0)) != 0;
    return f;
  }();
  return font;
}

std::vector<int> decodeUtf8(const std::string& s) {
  std::vector<int> out;
  for (std::size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    int cp = c, extra = 0;
    if (c >= 0xF0) cp = c & 0x07, extra = 3;
    else if (c >= 0xE0) cp = c & 0x0F, extra = 2;
    else if (c >= 0xC0) cp = c & 0x1F, extra = 1;
    ++i;
    for (int k = 0; k < extra && i < s.size(); ++k, ++i) cp = (cp << 6) | (static_cast<unsigned char>(s[i]) & 0x3F);
    out.push_back(cp);
  }
  return out;
}

// Blends one glyph's coverage at (x0, y0) in colour `c`.
void blendGlyph(Image& img, const unsigned char* coverage, int w, int h, int x0, int y0, const Vec3& c) {
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int px = x0 + x, py = y0 + y;
      if (px < 0 || py < 0 || px >= img.width || py >= img.height) continue;
      const Real a = Real(coverage[y * w + x]) / 255;
      if (a == 0) continue;
      std::uint8_t* p = img.pixel(px, py);
      for (int k = 0; k < 3; ++k) p[k] = std::uint8_t(std::lround(double(p[k] * (1 - a) + c[k] * 255 * a)));
      p[3] = std::uint8_t(std::lround(double(p[3] * (1 - a) + 255 * a)));
    }
}

void drawRun(Image& img, const Font& f, const std::vector<int>& cps, Real scale, Real x, int baseline, const Vec3& c) {
  for (std::size_t i = 0; i < cps.size(); ++i) {
    int advance = 0, lsb = 0;
    stbtt_GetCodepointHMetrics(&f.info, cps[i], &advance, &lsb);
    const Real shift = x - std::floor(x);
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    stbtt_GetCodepointBitmapBoxSubpixel(&f.info, cps[i], scale, scale, float(shift), 0, &x0, &y0, &x1, &y1);
    const int w = x1 - x0, h = y1 - y0;
    if (w > 0 && h > 0) {
      std::vector<unsigned char> bitmap(std::size_t(w) * std::size_t(h));
      stbtt_MakeCodepointBitmapSubpixel(&f.info, bitmap.data(), w, h, w, scale, scale, float(shift), 0, cps[i]);
      blendGlyph(img, bitmap.data(), w, h, int(std::floor(x)) + x0, baseline + y0, c);
    }
    x += Real(advance) * scale;
    if (i + 1 < cps.size()) x += Real(stbtt_GetCodepointKernAdvance(&f.info, cps[i], cps[i + 1])) * scale;
  }
}

}  // namespace

bool labelFontAvailable() { return labelFont().ok; }

Real textWidth(const std::string& text, Real pixelHeight) {
  const Font& f = labelFont();
  if (!f.ok) return 0;
  const Real scale = stbtt_ScaleForPixelHeight(&f.info, float(pixelHeight));
  const std::vector<int> cps = decodeUtf8(text);
  Real width = 0;
  for (std::size_t i = 0; i < cps.size(); ++i) {
    int advance = 0, lsb = 0;
    stbtt_GetCodepointHMetrics(&f.info, cps[i], &advance, &lsb);
    width += Real(advance) * scale;
    if (i + 1 < cps.size()) width += Real(stbtt_GetCodepointKernAdvance(&f.info, cps[i], cps[i + 1])) * scale;
  }
  return width;
}

void drawText(Image& image, Real centreX, Real baselineY, const std::string& text, Real pixelHeight, const Vec3& color) {
  const Font& f = labelFont();
  if (!f.ok) return;
  const Real scale = stbtt_ScaleForPixelHeight(&f.info, float(pixelHeight));
  const std::vector<int> cps = decodeUtf8(text);
  const Real width = textWidth(text, pixelHeight);
  const Real x = std::round(centreX - width / 2);
  const int baseline = int(std::lround(double(baselineY)));
  drawRun(image, f, cps, scale, x + 1, baseline + 1, Vec3(0));  // shadow, for legibility on any background
  drawRun(image, f, cps, scale, x, baseline, color);
}

}  // namespace illum
