// PackUnorm8 (unorm8-inl.h) converts every float as toUnorm8 does, on every SIMD target: the
// floats nearest each rounding boundary (k + ½)/255, both ends, values out of range, NaN and
// infinities, and a spread of random ones.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "math/unorm8_test.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

#include "math/unorm8-inl.h"

#include <cstddef>
#include <cstdint>

HWY_BEFORE_NAMESPACE();
namespace illum::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// out[i] = the RGBA8 word of (c[i], c[i + n], c[i + 2n], c[i + 3n]); n a multiple of 16.
void PackChannels(const float* c, std::size_t n, std::uint32_t* out) {
  const hn::ScalableTag<float> df;
  const hn::RebindToUnsigned<decltype(df)> du;
  for (std::size_t i = 0; i < n; i += hn::Lanes(df))
    hn::StoreU(PackUnorm8(df, hn::LoadU(df, c + i), hn::LoadU(df, c + n + i), hn::LoadU(df, c + 2 * n + i),
                          hn::LoadU(df, c + 3 * n + i)),
               du, out + i);
}

}  // namespace illum::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
#include "math/unorm8.h"

#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace illum {
HWY_EXPORT(PackChannels);
namespace {

std::vector<float> hardValues() {
  std::vector<float> v = {0.0f, -0.0f, 1.0f, 0.5f, -1.0f, 2.0f, 1e-30f, 1e-45f, std::numeric_limits<float>::quiet_NaN(),
                          std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity()};
  for (int k = 0; k <= 255; ++k) {
    float c = float((k + 0.5) / 255.0);
    for (int i = 0; i < 64; ++i) c = std::nextafter(c, 0.0f);
    for (int i = 0; i < 128; ++i, c = std::nextafter(c, 2.0f)) v.push_back(c);
  }
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> unit(-0.1f, 1.1f);
  while (v.size() % 64 != 0 || v.size() < 40000) v.push_back(unit(rng));
  return v;
}

TEST(Unorm8, PacksAsToUnorm8OnEveryTarget) {
  const std::vector<float> values = hardValues();
  const std::size_t n = values.size();
  // Each channel sees every value: the channels are the values rotated by a quarter.
  std::vector<float> channels(4 * n);
  for (std::size_t c = 0; c < 4; ++c)
    for (std::size_t i = 0; i < n; ++i) channels[c * n + i] = values[(i + c * n / 4) % n];
  std::vector<std::uint32_t> expected(n);
  for (std::size_t i = 0; i < n; ++i)
    expected[i] = packUnorm8(Color4(channels[i], channels[n + i], channels[2 * n + i], channels[3 * n + i]));
  for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
    hwy::SetSupportedTargetsForTest(target);
    std::vector<std::uint32_t> actual(n);
    HWY_DYNAMIC_DISPATCH(PackChannels)(channels.data(), n, actual.data());
    int wrong = 0;
    for (std::size_t i = 0; i < n && wrong < 5; ++i)
      if (actual[i] != expected[i]) {
        ++wrong;
        ADD_FAILURE() << hwy::TargetName(target) << ": (" << channels[i] << ", " << channels[n + i] << ", "
                      << channels[2 * n + i] << ", " << channels[3 * n + i] << ") packs to " << std::hex << actual[i]
                      << ", toUnorm8 to " << expected[i];
      }
  }
  hwy::SetSupportedTargetsForTest(0);
}

}  // namespace
}  // namespace illum
#endif
