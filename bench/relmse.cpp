// The relative mean squared error of a picture against a reference, both OpenEXR (linear RGB):
// mean over pixels and channels of (x − r)² / (r² + 0.01), the measure of denoising papers
// (Rousselle et al. 2011). For bench/denoise.sh.
//   illum_relmse PICTURE.exr REFERENCE.exr
#include <illum/error.h>
#include <illum/image.h>

#include <cstdio>
#include <exception>

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: illum_relmse PICTURE.exr REFERENCE.exr\n");
    return 2;
  }
  try {
    const illum::FloatImage x = illum::readExr(argv[1]), r = illum::readExr(argv[2]);
    if (x.width != r.width || x.height != r.height) {
      std::fprintf(stderr, "illum_relmse: %s is %dx%d, %s %dx%d: expected the same size\n", argv[1], x.width, x.height,
                   argv[2], r.width, r.height);
      return 2;
    }
    double sum = 0;
    for (std::size_t i = 0; i < x.rgba.size(); i += 4)
      for (std::size_t c = 0; c < 3; ++c) {
        const double d = double(x.rgba[i + c]) - double(r.rgba[i + c]), ref = r.rgba[i + c];
        sum += d * d / (ref * ref + 0.01);
      }
    std::printf("%.6g\n", sum / double(x.rgba.size() / 4 * 3));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "illum_relmse: %s\n", e.what());
    return 2;
  }
}
