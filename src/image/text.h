// Text on images, for labels that explain a picture: DejaVu Sans (Debian's fonts-dejavu-core)
// rasterized by stb_truetype and blended over the image.
#pragma once

#include <illum/image.h>
#include <illum/real.h>

#include <string>

namespace illum {

// The font file labels use.
constexpr const char* kLabelFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

// Whether the label font could be loaded (it is loaded once, on first use).
bool labelFontAvailable();

// The advance width of UTF-8 `text` at `pixelHeight`, in pixels (0 without the font).
Real textWidth(const std::string& text, Real pixelHeight);

// Draws UTF-8 `text` with its baseline centred at (centreX, baselineY), in pixels from the image's
// top-left, `pixelHeight` tall, over a one-pixel dark shadow. Does nothing without the font.
void drawText(Image& image, Real centreX, Real baselineY, const std::string& text, Real pixelHeight, const Vec3& color);

}  // namespace illum
