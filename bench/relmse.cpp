// The relative mean squared error of a picture against a reference, both OpenEXR (linear RGB):
// mean over pixels and channels of (x − r)² / (r² + 0.01), the measure of denoising papers
// (Rousselle et al. 2011). For bench/denoise.sh. With --map, also where the error lies: the share
// of it in the worst 0.1 %, 1 % and 10 % of the pixels, and a grey PNG of each pixel's error
// against the mean (black: a sixteenth of it or less, white: 16 times or more, log scale).
//   illum_relmse PICTURE.exr REFERENCE.exr [--map OUT.png]
#include <illum/error.h>
#include <illum/image.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <functional>
#include <vector>

int main(int argc, char** argv) {
  const bool map = argc == 5 && std::strcmp(argv[3], "--map") == 0;
  if (argc != 3 && !map) {
    std::fprintf(stderr, "usage: illum_relmse PICTURE.exr REFERENCE.exr [--map OUT.png]\n");
    return 2;
  }
  try {
    const illum::FloatImage x = illum::readExr(argv[1]), r = illum::readExr(argv[2]);
    if (x.width != r.width || x.height != r.height) {
      std::fprintf(stderr, "illum_relmse: %s is %dx%d, %s %dx%d: expected the same size\n", argv[1], x.width, x.height,
                   argv[2], r.width, r.height);
      return 2;
    }
    std::vector<double> perPixel(x.rgba.size() / 4, 0.0);
    double sum = 0;
    for (std::size_t i = 0; i < x.rgba.size(); i += 4)
      for (std::size_t c = 0; c < 3; ++c) {
        const double d = double(x.rgba[i + c]) - double(r.rgba[i + c]), ref = r.rgba[i + c];
        perPixel[i / 4] += d * d / (ref * ref + 0.01);
      }
    for (double e : perPixel) sum += e;
    std::printf("%.6g\n", sum / double(x.rgba.size() / 4 * 3));
    if (!map) return 0;
    std::vector<double> sorted = perPixel;
    std::sort(sorted.begin(), sorted.end(), std::greater<>());
    for (double share : {0.001, 0.01, 0.1}) {
      const std::size_t n = std::max<std::size_t>(1, std::size_t(share * double(sorted.size())));
      double part = 0;
      for (std::size_t k = 0; k < n; ++k) part += sorted[k];
      std::printf("worst %g %%: %.1f %% of the error\n", share * 100, sum > 0 ? 100 * part / sum : 0.0);
    }
    illum::Image out(x.width, x.height);
    const double mean = sum / double(perPixel.size());
    for (int y = 0; y < x.height; ++y)
      for (int px = 0; px < x.width; ++px) {
        const double e = perPixel[std::size_t(y) * std::size_t(x.width) + std::size_t(px)];
        // 0 at a sixteenth of the mean or less, 255 at 16 times the mean or more, log scale.
        const double level = e > 0 ? std::log2(e / mean) : -8.0;
        const auto v = std::uint8_t(std::clamp((level + 4) / 8 * 255, 0.0, 255.0));
        std::uint8_t* p = out.pixel(px, y);
        p[0] = p[1] = p[2] = v, p[3] = 255;
      }
    illum::writePng(argv[4], out);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "illum_relmse: %s\n", e.what());
    return 2;
  }
}
