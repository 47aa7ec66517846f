#include <illum/error.h>
#include <illum/image.h>

#include <cmath>
#include <cstdlib>
#include <limits>

namespace illum {

ImageDifference compareImages(const Image& a, const Image& b, int tolerance) {
  if (a.width != b.width || a.height != b.height) throw Error("cannot compare images of different sizes");
  ImageDifference d;
  std::size_t within = 0;
  double squared = 0;
  const std::size_t pixels = std::size_t(a.width) * std::size_t(a.height);
  for (std::size_t p = 0; p < pixels; ++p) {
    int worst = 0;
    for (int c = 0; c < 4; ++c) {
      const int e = std::abs(int(a.rgba[p * 4 + c]) - int(b.rgba[p * 4 + c]));
      worst = std::max(worst, e);
      if (c < 3) squared += double(e) * e;
    }
    d.maxError = std::max(d.maxError, worst);
    within += worst <= tolerance ? 1 : 0;
  }
  d.fractionWithin = pixels ? double(within) / double(pixels) : 1.0;
  const double mse = pixels ? squared / (3.0 * double(pixels)) : 0.0;
  d.psnr = mse == 0 ? std::numeric_limits<double>::infinity() : 10 * std::log10(255.0 * 255.0 / mse);
  return d;
}

Image differenceImage(const Image& a, const Image& b, int gain) {
  if (a.width != b.width || a.height != b.height) throw Error("cannot compare images of different sizes");
  Image out(a.width, a.height);
  for (std::size_t i = 0; i < out.rgba.size(); i += 4) {
    for (int c = 0; c < 3; ++c)
      out.rgba[i + c] = std::uint8_t(std::min(255, gain * std::abs(int(a.rgba[i + c]) - int(b.rgba[i + c]))));
    out.rgba[i + 3] = 255;
  }
  return out;
}

}  // namespace illum
