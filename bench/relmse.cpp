// The relative mean squared error of a picture against a reference, both OpenEXR (linear RGB):
// mean over pixels and channels of (x − r)² / (r² + 0.01), the measure of denoising papers
// (Rousselle et al. 2011). For bench/denoise.sh. With --map, also where the error lies: the share
// of it in the worst 0.1 %, 1 % and 10 % of the pixels, and a grey PNG of each pixel's error
// against the mean (black: a sixteenth of it or less, white: 16 times or more, log scale). With
// --seeds, pictures of the same input drawn with K different seeds (illum render --seed): their
// mean error, and how it splits into the estimator's bias² and its variance, from the error of
// the pictures' mean, bias² + variance/K.
//   illum_relmse PICTURE.exr REFERENCE.exr [--map OUT.png]
//   illum_relmse --seeds REFERENCE.exr PICTURE.exr PICTURE.exr ...
#include <illum/error.h>
#include <illum/image.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <functional>
#include <vector>

namespace {

// The relative squared error of value x against reference value r.
double relative(double x, double r) { return (x - r) * (x - r) / (r * r + 0.01); }

int seeds(int count, char** files) {
  const illum::FloatImage r = illum::readExr(files[0]);
  std::vector<illum::FloatImage> pictures;
  for (int k = 1; k < count; ++k) {
    pictures.push_back(illum::readExr(files[k]));
    if (pictures.back().width != r.width || pictures.back().height != r.height) {
      std::fprintf(stderr, "illum_relmse: %s is not the reference's size\n", files[k]);
      return 2;
    }
  }
  const double n = double(pictures.size());
  double each = 0, ofMean = 0;
  for (std::size_t i = 0; i < r.rgba.size(); i += 4)
    for (std::size_t c = 0; c < 3; ++c) {
      double sum = 0;
      for (const illum::FloatImage& p : pictures) {
        each += relative(p.rgba[i + c], r.rgba[i + c]) / n;
        sum += p.rgba[i + c];
      }
      ofMean += relative(sum / n, r.rgba[i + c]);
    }
  const double values = double(r.rgba.size() / 4 * 3);
  each /= values, ofMean /= values;
  // E = bias² + variance, M = bias² + variance/K.
  const double variance = (each - ofMean) * n / (n - 1), bias2 = ofMean - variance / n;
  std::printf("error %.6g bias2 %.6g variance %.6g\n", each, bias2, variance);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc >= 2 && std::strcmp(argv[1], "--seeds") == 0) {
    if (argc < 5) {
      std::fprintf(stderr, "usage: illum_relmse --seeds REFERENCE.exr PICTURE.exr PICTURE.exr ...\n");
      return 2;
    }
    try {
      return seeds(argc - 2, argv + 2);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "illum_relmse: %s\n", e.what());
      return 2;
    }
  }
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
        perPixel[i / 4] += relative(x.rgba[i + c], r.rgba[i + c]);
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
