#include <illum/display.h>

#include <hwy/highway.h>

#include "image/display_bytes.h"
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
  DisplayBytes map;
  for (int i = 0; i < 256; ++i) map.table[i] = byte(displayValue(Real(i) / 255, display));
  // A background pixel, compared whole, takes the background's shown bytes; any other has its
  // three colour bytes mapped and keeps its alpha.
  if (background) {
    std::array<std::uint8_t, 4> stored{};
    for (int c = 0; c < 4; ++c) stored[std::size_t(c)] = byte((*background)[c]);
    const std::array<std::uint8_t, 4> shown = backgroundBytes(*background, display);
    std::memcpy(&map.stored, stored.data(), 4);
    std::memcpy(&map.shown, shown.data(), 4);
    map.hasBackground = true;
  }
  // Each pixel on its own: any split over threads gives the same bytes.
  const std::size_t pixels = image.rgba.size() / 4;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, pixels, 1 << 15), [&](const tbb::blocked_range<std::size_t>& r) {
    mapDisplayBytes(image.rgba.data() + 4 * r.begin(), r.size(), map);
  });
}

}  // namespace illum
