// ToneMappedLanes (tone_map-inl.h) maps every value as the tone maps' scalar statement does, bit
// for bit, on every SIMD target: zero, negatives, NaN, infinities, values whose square overflows,
// and a spread over twelve orders of magnitude. (display.cpp's toneMapped is its one-lane instance.)
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "math/tone_map_test.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

#include <illum/real.h>

#include "math/tone_map-inl.h"

#include <cstddef>

HWY_BEFORE_NAMESPACE();
namespace illum::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// out[i] = the tone map of x[i]; n a multiple of 16.
void ToneMapAll(const Real* x, std::size_t n, ToneMap toneMap, Real* out) {
  const hn::ScalableTag<Real> d;
  for (std::size_t i = 0; i < n; i += hn::Lanes(d)) hn::StoreU(ToneMappedLanes(d, hn::LoadU(d, x + i), toneMap), d, out + i);
}

}  // namespace illum::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

namespace illum {
HWY_EXPORT(ToneMapAll);
namespace {

// The tone maps as scalar code states them (Reinhard; Narkowicz's ACES fit, clamped).
Real stated(Real x, ToneMap toneMap) {
  if (!(x > 0)) return 0;
  switch (toneMap) {
    case ToneMap::None: return x;
    case ToneMap::Reinhard: return std::isinf(x) ? Real(1) : x / (1 + x);
    case ToneMap::Aces: {
      if (std::isinf(x)) return 1;
      const Real y = (x * (Real(2.51) * x + Real(0.03))) / (x * (Real(2.43) * x + Real(0.59)) + Real(0.14));
      return std::clamp(y, Real(0), Real(1));
    }
  }
  return x;
}

bool sameBits(Real a, Real b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(ToneMapLanes, MapAsTheScalarStatementOnEveryTarget) {
  constexpr Real kInf = std::numeric_limits<Real>::infinity();
  std::vector<Real> x = {0, -0.0f, -1, 1, 0.5f, 2, 1e-30f, 1e-45f, std::numeric_limits<Real>::quiet_NaN(), kInf, -kInf,
                         1e19f, 2e19f, 1e30f, std::numeric_limits<Real>::max()};
  std::mt19937 rng(7);
  std::uniform_real_distribution<Real> exponent(-6, 6);
  while (x.size() % 64 != 0 || x.size() < 20000) x.push_back(std::pow(Real(10), exponent(rng)));
  for (const ToneMap toneMap : {ToneMap::None, ToneMap::Reinhard, ToneMap::Aces}) {
    for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
      hwy::SetSupportedTargetsForTest(target);
      std::vector<Real> mapped(x.size());
      HWY_DYNAMIC_DISPATCH(ToneMapAll)(x.data(), x.size(), toneMap, mapped.data());
      int wrong = 0;
      for (std::size_t i = 0; i < x.size() && wrong < 5; ++i)
        if (!sameBits(mapped[i], stated(x[i], toneMap)) && !(std::isnan(mapped[i]) && std::isnan(stated(x[i], toneMap)))) {
          ++wrong;
          ADD_FAILURE() << hwy::TargetName(target) << ": tone map " << int(toneMap) << " of " << x[i] << " is "
                        << mapped[i] << ", the statement's " << stated(x[i], toneMap);
        }
    }
    hwy::SetSupportedTargetsForTest(0);
  }
  // Spot values: ACES of 1 is 2.54/3.16; a square that overflows stays NaN, as the clamp leaves it.
  EXPECT_NEAR(stated(1, ToneMap::Aces), 2.54 / 3.16, 1e-6);
  if constexpr (sizeof(Real) == 4) {
    EXPECT_TRUE(std::isnan(stated(1e30f, ToneMap::Aces)));
  }
}

}  // namespace
}  // namespace illum
#endif
