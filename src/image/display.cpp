#include <illum/display.h>

#include <hwy/highway.h>

#include "math/tone_map-inl.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace illum {

std::string_view toString(ToneMap toneMap) {
  switch (toneMap) {
    case ToneMap::None: return "none";
    case ToneMap::Reinhard: return "reinhard";
    case ToneMap::Aces: return "aces";
  }
  return "none";
}

std::string_view toString(Encoding encoding) { return encoding == Encoding::Srgb ? "srgb" : "linear"; }

std::optional<ToneMap> parseToneMap(std::string_view name) {
  for (ToneMap t : {ToneMap::None, ToneMap::Reinhard, ToneMap::Aces})
    if (name == toString(t)) return t;
  return std::nullopt;
}

std::optional<Encoding> parseEncoding(std::string_view name) {
  for (Encoding e : {Encoding::Linear, Encoding::Srgb})
    if (name == toString(e)) return e;
  return std::nullopt;
}

// The lanes' ToneMappedLanes on one lane of the static target (every target computes the same
// bits).
Real toneMapped(Real x, ToneMap toneMap) {
  namespace hn = hwy::HWY_NAMESPACE;
  const hn::CappedTag<Real, 1> d;
  return hn::GetLane(HWY_NAMESPACE::ToneMappedLanes(d, hn::Set(d, x), toneMap));
}

Real srgbEncoded(Real x) {
  x = std::clamp(x, Real(0), Real(1));
  return x <= Real(0.0031308) ? Real(12.92) * x : Real(1.055) * std::pow(x, Real(1) / Real(2.4)) - Real(0.055);
}

Real srgbDecoded(Real x) {
  x = std::clamp(x, Real(0), Real(1));
  return x <= Real(0.04045) ? x / Real(12.92) : std::pow((x + Real(0.055)) / Real(1.055), Real(2.4));
}

Real displayValue(Real x, const Display& display) {
  const Real mapped = std::clamp(toneMapped(x, display.toneMap), Real(0), Real(1));
  return display.encoding == Encoding::Srgb ? srgbEncoded(mapped) : mapped;
}

namespace {
std::uint8_t byte(Real v) { return std::uint8_t(std::lround(std::clamp(v, Real(0), Real(1)) * 255)); }
}  // namespace

std::array<std::uint8_t, 4> backgroundBytes(const Vec4& background, const Display& display) {
  // A tone map shapes radiance, not the backdrop: the background is only encoded.
  const Display encoding{ToneMap::None, display.encoding};
  return {byte(displayValue(background.r, encoding)), byte(displayValue(background.g, encoding)),
          byte(displayValue(background.b, encoding)), byte(background.a)};
}

void applyDisplay(Image& image, const Display& display, const Vec4* background) {
  if (display.identity()) return;
  std::array<std::uint8_t, 256> table;
  for (int i = 0; i < 256; ++i) table[std::size_t(i)] = byte(displayValue(Real(i) / 255, display));
  // Pixels as RGBA words (bytes in memory order): a background pixel, compared whole, takes the
  // background's shown bytes; any other has its three colour bytes mapped and keeps its alpha.
  const auto word = [](const std::array<std::uint8_t, 4>& bytes) {
    std::uint32_t w;
    std::memcpy(&w, bytes.data(), 4);
    return w;
  };
  std::array<std::uint8_t, 4> stored{}, shown{};
  if (background) {
    for (int c = 0; c < 4; ++c) stored[std::size_t(c)] = byte((*background)[c]);
    shown = backgroundBytes(*background, display);
  }
  const std::uint32_t storedWord = word(stored), shownWord = word(shown);
  const bool hasBackground = background != nullptr;
  const std::size_t pixels = image.rgba.size() / 4;
  std::uint8_t* const data = image.rgba.data();
  const auto mapped = [table, storedWord, shownWord, hasBackground](std::uint32_t w) {
    if (hasBackground && w == storedWord) return shownWord;
    return std::uint32_t(table[w & 0xFF]) | std::uint32_t(table[w >> 8 & 0xFF]) << 8 |
           std::uint32_t(table[w >> 16 & 0xFF]) << 16 | (w & 0xFF000000u);
  };
  // Each pixel on its own: any split over threads gives the same bytes. Runs of background (most
  // of a model preview) are found 16 pixels at a time.
  constexpr std::size_t kRun = 16;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, pixels, 1 << 15), [&](const tbb::blocked_range<std::size_t>& r) {
    std::size_t i = r.begin();
    std::uint32_t w[kRun];
    for (; i + kRun <= r.end(); i += kRun) {
      std::uint8_t* p = data + 4 * i;
      std::memcpy(w, p, sizeof w);
      bool all = hasBackground;
      for (std::size_t k = 0; k < kRun; ++k) all &= w[k] == storedWord;
      if (all)
        std::fill_n(w, kRun, shownWord);
      else
        for (std::size_t k = 0; k < kRun; ++k) w[k] = mapped(w[k]);
      std::memcpy(p, w, sizeof w);
    }
    for (; i < r.end(); ++i) {
      std::memcpy(w, data + 4 * i, 4);
      w[0] = mapped(w[0]);
      std::memcpy(data + 4 * i, w, 4);
    }
  });
}

}  // namespace illum
