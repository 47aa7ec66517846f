// display_bytes.h, compiled once per SIMD target (Highway's foreach_target), dispatched at run time.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "image/display_bytes.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

#include "image/display_bytes.h"

#include <cstring>

HWY_BEFORE_NAMESPACE();
namespace illum::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

std::uint32_t MappedWord(std::uint32_t w, const DisplayBytes& map) {
  if (map.hasBackground && w == map.stored) return map.shown;
  return map.table[w & 0xFF] | map.table[w >> 8 & 0xFF] << 8 | map.table[w >> 16 & 0xFF] << 16 | (w & 0xFF000000u);
}

// Whole vectors of pixels: a run of background (most of a model preview) is one compare, any other
// vector three gathers from the table.
void MapDisplayBytes(std::uint8_t* rgba, std::size_t count, const DisplayBytes& map) {
  const hn::ScalableTag<std::uint32_t> du;
  const hn::RebindToSigned<decltype(du)> di;
  const std::size_t lanes = hn::Lanes(du);
  const auto stored = hn::Set(du, map.stored), shown = hn::Set(du, map.shown);
  const auto byte = hn::Set(du, 0xFF), alpha = hn::Set(du, 0xFF000000u);
  const auto* table = reinterpret_cast<const std::int32_t*>(map.table);
  const auto lookUp = [&](auto index) { return hn::BitCast(du, hn::GatherIndex(di, table, hn::BitCast(di, index))); };
  auto* words = reinterpret_cast<std::uint32_t*>(rgba);
  std::size_t i = 0;
  for (; i + lanes <= count; i += lanes) {
    const auto w = hn::LoadU(du, words + i);
    const auto background = map.hasBackground ? hn::Eq(w, stored) : hn::FirstN(du, 0);
    if (hn::AllTrue(du, background)) {
      hn::StoreU(shown, du, words + i);
      continue;
    }
    const auto mapped = hn::Or(hn::Or(lookUp(hn::And(w, byte)), hn::ShiftLeft<8>(lookUp(hn::And(hn::ShiftRight<8>(w), byte)))),
                               hn::Or(hn::ShiftLeft<16>(lookUp(hn::And(hn::ShiftRight<16>(w), byte))), hn::And(w, alpha)));
    hn::StoreU(hn::IfThenElse(background, shown, mapped), du, words + i);
  }
  for (; i < count; ++i) words[i] = MappedWord(words[i], map);
}

}  // namespace illum::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace illum {

HWY_EXPORT(MapDisplayBytes);

void mapDisplayBytes(std::uint8_t* rgba, std::size_t count, const DisplayBytes& map) {
  HWY_DYNAMIC_DISPATCH(MapDisplayBytes)(rgba, count, map);
}

}  // namespace illum
#endif
