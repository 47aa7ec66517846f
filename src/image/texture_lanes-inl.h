// Texture::sample over SIMD lanes (Highway, included once per target by the kernels that shade
// textured pixels): GL_LINEAR_MIPMAP_LINEAR with the texture's wrap modes, each lane its own uv and footprint,
// with the same operations in the same order as the one-texel sampler (texture.cpp), so every
// lane's texel is the bits Texture::sample gives (it takes its mip level from MipLevelLanes, one
// lane). Texel fetches are the cost: on AVX-512 the decode table is read from registers rather
// than gathered (by byte permutes where the CPU has VBMI: linear bytes too, without a division), a
// row's two texels are one read (gather_pairs-inl.h), and an opaque texture's alpha is not read.

#if defined(ILLUM_IMAGE_TEXTURE_LANES_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef ILLUM_IMAGE_TEXTURE_LANES_INL_H_
#undef ILLUM_IMAGE_TEXTURE_LANES_INL_H_
#else
#define ILLUM_IMAGE_TEXTURE_LANES_INL_H_
#endif

#include <hwy/highway.h>

#include <illum/texture.h>

#include "image/texel_lookup.h"
#include "math/gather_pairs-inl.h"

#include <cstddef>
#include <cstdint>
#include <type_traits>

HWY_BEFORE_NAMESPACE();
namespace illum::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

#if (HWY_TARGET == HWY_AVX3 || HWY_TARGET == HWY_AVX3_DL) && !ILLUM_USE_DOUBLE
// A 256-entry float table held in sixteen registers and read with two-table permutes (each
// vpermi2ps picks from 32 entries by an index's low five bits, and the top three bits choose among
// the eight results): the table's own bits, without a gather's memory traffic per lane.
struct TableRegisters {
  __m512 part[16];
  explicit TableRegisters(const float* table) {
    for (int k = 0; k < 16; ++k) part[k] = _mm512_loadu_ps(table + 16 * k);
  }
  HWY_INLINE hn::Vec512<float> operator()(hn::Vec512<std::int32_t> index) const {
    const __m512i i = index.raw;
    __m512 r[8];
    for (int k = 0; k < 8; ++k) r[k] = _mm512_permutex2var_ps(part[2 * k], i, part[2 * k + 1]);
    const __mmask16 b5 = _mm512_test_epi32_mask(i, _mm512_set1_epi32(32));
    const __mmask16 b6 = _mm512_test_epi32_mask(i, _mm512_set1_epi32(64));
    const __mmask16 b7 = _mm512_test_epi32_mask(i, _mm512_set1_epi32(128));
    for (int k = 0; k < 4; ++k) r[k] = _mm512_mask_blend_ps(b5, r[2 * k], r[2 * k + 1]);
    for (int k = 0; k < 2; ++k) r[k] = _mm512_mask_blend_ps(b6, r[2 * k], r[2 * k + 1]);
    return hn::Vec512<float>{_mm512_mask_blend_ps(b7, r[0], r[1])};
  }
};

// The three colour channels of a vector of 16 RGBA8 words, each channel's byte looked up in a
// 256-entry float table held as four planes of bytes (Texture::colorTableBytes) with AVX-512
// VBMI's byte permutes: each plane's byte for all 64 bytes of a vector at once (two 128-entry
// permutes and a blend on the byte's top bit), then each channel's four bytes brought together
// into its lanes' floats (two permutes and a blend), 22 instructions a vector where float
// permutes take 54. Compiled for VBMI, and used only where the CPU has it (texelByteLookups):
// by a caller compiled for it too (ILLUM_VBMI), which keeps the planes in registers across its
// texels, or through LookUpColorBytes.
#define ILLUM_VBMI __attribute__((target(HWY_TARGET_STR ",avx512vbmi")))
struct ColorBytePlanes {
  __m512i table[16];  // plane k's entries 64q .. 64q + 63 in table[4k + q]
  ILLUM_VBMI explicit ColorBytePlanes(const std::uint8_t* planes) {
    for (int i = 0; i < 16; ++i) table[i] = _mm512_load_si512(planes + 64 * i);
  }
  // out[c]: channel c of the words' texels.
  ILLUM_VBMI inline void operator()(__m512i w, __m512* out) const {
    // Byte 4l + j of channel c's index: byte 4l + c of the first (j even) or the second (j odd)
    // plane of a pair, so that bytes 0, 1 of each lane come from planes 0, 1 and bytes 2, 3 from
    // planes 2, 3.
    struct Indices {
      alignas(64) std::uint8_t channel[3][64];
    };
    static constexpr Indices kIndices = [] {
      Indices out{};
      for (int c = 0; c < 3; ++c)
        for (int b = 0; b < 64; ++b) out.channel[c][b] = std::uint8_t((b & 1 ? 64 : 0) + (b & ~3) + c);
      return out;
    }();
    const __mmask64 upperHalf = 0xCCCCCCCCCCCCCCCCull;  // bytes 2 and 3 of each lane
    const __mmask64 high = _mm512_movepi8_mask(w);     // bytes 128 .. 255
    __m512i plane[4];
    for (int k = 0; k < 4; ++k)
      plane[k] = _mm512_mask_blend_epi8(high, _mm512_permutex2var_epi8(table[4 * k], w, table[4 * k + 1]),
                                        _mm512_permutex2var_epi8(table[4 * k + 2], w, table[4 * k + 3]));
    for (int c = 0; c < 3; ++c) {
      const __m512i index = _mm512_load_si512(kIndices.channel[c]);
      const __m512i bytes01 = _mm512_permutex2var_epi8(plane[0], index, plane[1]);
      const __m512i bytes23 = _mm512_permutex2var_epi8(plane[2], index, plane[3]);
      out[c] = _mm512_castsi512_ps(_mm512_mask_blend_epi8(upperHalf, bytes01, bytes23));
    }
  }
};

// ColorBytePlanes out of line, for a caller not compiled for VBMI: out[3v + c] is channel c of
// vector v.
inline HWY_NOINLINE ILLUM_VBMI void LookUpColorBytes(const std::uint8_t* planes, const __m512i* words, int count,
                                                     __m512* out) {
  const ColorBytePlanes lookUp(planes);
  for (int v = 0; v < count; ++v) lookUp(words[v], out + 3 * v);
}
#define ILLUM_TEXELS_AVX512 1
#endif

// The mip level (GL's λ) of a footprint of x base texels a pixel: log2 x where x > 1, else 0 (a NaN
// too). log2 is the exponent plus a degree-7 polynomial in the mantissa (a least-squares fit on
// [1, 2): error below 5e-7, 0 at powers of two, increasing), in separate multiplies and adds, so
// every target and Texture::sample (one lane) give the same bits, without a call per lane.
template <class D, class V = hn::VFromD<D>>
HWY_INLINE V MipLevelLanes(D d, V x) {
  using T = hn::TFromD<D>;
  const hn::RebindToSigned<D> di;
  using TI = hn::TFromD<decltype(di)>;
  constexpr int kMantissaBits = sizeof(T) == 4 ? 23 : 52;
  constexpr TI kBias = sizeof(T) == 4 ? 127 : 1023;
  const V one = hn::Set(d, T(1));
  const auto bits = hn::BitCast(di, hn::IfThenElse(x > one, x, one));
  const auto exponent = hn::ShiftRight<kMantissaBits>(bits) - hn::Set(di, kBias);
  const auto mantissa = hn::Or(hn::And(bits, hn::Set(di, (TI(1) << kMantissaBits) - 1)), hn::BitCast(di, one));
  const V t = hn::BitCast(d, mantissa) - one;  // in [0, 1)
  constexpr T kCoefficients[7] = {T(1.442667841911316), T(-0.7205854654312134), T(0.4735533893108368),
                                  T(-0.32590192556381226), T(0.19429424405097961), T(-0.07955767214298248),
                                  T(0.015529900789260864)};
  V p = hn::Set(d, kCoefficients[6]);
  for (int k = 5; k >= 0; --k) p = p * t + hn::Set(d, kCoefficients[k]);
  return hn::ConvertTo(d, exponent) + p * t;
}

// A texel index k of a row or column of n, at most one texel outside [0, n) ([0, 2n) mirrored),
// brought inside as `wrap` says (texelPair's wrapped, texture.cpp).
template <class DI, class VI = hn::VFromD<DI>>
HWY_INLINE VI WrappedLanes(DI di, VI k, int n, TextureWrap wrap) {
  if (wrap == TextureWrap::ClampToEdge) return hn::Min(hn::Max(k, hn::Zero(di)), hn::Set(di, n - 1));
  const VI span = wrap == TextureWrap::Repeat ? hn::Set(di, n) : hn::Set(di, 2 * n);
  k = hn::IfThenElse(k < hn::Zero(di), k + span, k);
  k = hn::IfThenElse(hn::Not(k < span), k - span, k);
  if (wrap == TextureWrap::Repeat) return k;
  return hn::IfThenElse(k < hn::Set(di, n), k, hn::Set(di, 2 * n - 1) - k);
}

// texelPair (texture.cpp) over lanes: the wrap mode, then GL_LINEAR along one axis of n texels,
// the two texels around c·n − ½ and the second one's weight. (Functions rather than lambdas: a
// lambda is not always inlined, and a call here saves every vector register around it.)
template <class D, class V = hn::VFromD<D>, class VI = hn::VFromD<hn::RebindToSigned<D>>>
HWY_INLINE void TexelPairLanes(D d, V c, int n, TextureWrap wrap, VI& i0, VI& i1, V& weight) {
  const hn::RebindToSigned<D> di;
  const V one = hn::Set(d, Real(1)), two = hn::Set(d, Real(2));
  const V reduced = wrap == TextureWrap::ClampToEdge ? hn::Min(hn::Max(c, hn::Zero(d)), one)
                    : wrap == TextureWrap::Repeat    ? c - hn::Floor(c)
                                                     : c - two * hn::Floor(c / two);
  const V x = reduced * hn::Set(d, Real(n)) - hn::Set(d, Real(0.5));
  const V fx = hn::Floor(x);
  weight = x - fx;
  const VI i = hn::ConvertTo(di, fx);
  i0 = WrappedLanes(di, i, n, wrap);
  i1 = WrappedLanes(di, i + hn::Set(di, 1), n, wrap);
}

// A decode table read by gathering its entries.
template <class D>
struct GatheredTable {
  D d;
  const Real* table;
  template <class VI>
  HWY_INLINE hn::VFromD<D> operator()(VI index) const {
    return hn::GatherIndex(d, table, index);
  }
};

// A texel word's alpha: byte/255 (one division, rounded as the alpha table's entry is), or 1 for an
// opaque texture (whose every alpha byte is 255).
template <class D, class VI>
HWY_INLINE hn::VFromD<D> AlphaLanes(D d, VI word, bool opaque) {
  if (opaque) return hn::Set(d, Real(1));
  return hn::ConvertTo(d, hn::And(hn::ShiftRight<24>(word), hn::Set(hn::DFromV<VI>(), 0xFF))) / hn::Set(d, Real(255));
}

// A texel word's channels as the texture's tables decode them: colour bytes looked up (lookUp: the
// table in registers or gathered) or, linear, byte/255 (one division, rounded as the table's entry
// is); alpha as AlphaLanes.
template <class D, class V = hn::VFromD<D>, class VI, class LookUp>
HWY_INLINE void DecodeTexelLanes(D d, VI word, bool linear, bool opaque, const LookUp& lookUp, V (&t)[4]) {
  const hn::RebindToSigned<D> di;
  const V max = hn::Set(d, Real(255));
  const VI mask = hn::Set(di, 0xFF);
  const VI bytes[4] = {hn::And(word, mask), hn::And(hn::ShiftRight<8>(word), mask), hn::And(hn::ShiftRight<16>(word), mask),
                       hn::And(hn::ShiftRight<24>(word), mask)};
  t[3] = AlphaLanes(d, word, opaque);
  for (int c = 0; c < 3; ++c) t[c] = linear ? hn::ConvertTo(d, bytes[c]) / max : lookUp(bytes[c]);
}

// Texture::sampleLevel of one level in the lanes of `active` (the others read a valid texel and
// are left to the caller).
// With `planes` (a caller compiled for VBMI: ColorBytePlanes), colour bytes are looked up in them.
template <class D, class V = hn::VFromD<D>, class M, class Planes = std::nullptr_t>
HWY_INLINE void SampleLevelLanes(D d, const Texture& texture, int levelIndex, V u, V v, M active, V (&out)[4],
                                 [[maybe_unused]] const Planes* planes = nullptr) {
  const hn::RebindToSigned<D> di;
  const hn::RebindToUnsigned<D> du;
  const Image& level = texture.level(levelIndex);
  const int width = level.width, height = level.height;
  const V one = hn::Set(d, Real(1));
  hn::VFromD<decltype(di)> x0, x1, y0, y1;
  V ax, ay;
  // The wrap modes, then GL_LINEAR: the four texels around (u·w − 0.5, v·h − 0.5).
  TexelPairLanes(d, u, width, texture.wraps().s, x0, x1, ax);
  TexelPairLanes(d, v, height, texture.wraps().t, y0, y1, ay);
  // Texel (x, GL row r) is the image's pixel (x, height − 1 − r); inactive lanes read texel 0.
  const auto activeI = hn::RebindMask(di, active);
  const auto rowStart = [&](auto r) { return (hn::Set(di, height - 1) - r) * hn::Set(di, width); };
  const auto* words = reinterpret_cast<const std::uint32_t*>(level.rgba.data());
  [[maybe_unused]] const Real* color = texture.colorTable();
  const bool linear = texture.encoding() == TexelEncoding::Linear;
  const bool opaque = !texture.hasTransparency();  // every alpha byte 255: 1 exactly
  const auto fetch = [&](auto xi, auto row) {
    return hn::BitCast(di, hn::GatherIndex(du, words, hn::IfThenElseZero(activeI, row + xi)));
  };
  V t00[4], t10[4], t01[4], t11[4];
  const auto r0 = rowStart(y0), r1 = rowStart(y1);
  hn::VFromD<decltype(di)> w00, w10, w01, w11;
#if defined(ILLUM_TEXELS_AVX512)
  // Where every lane's right texel is its left one's neighbour in memory (not across a wrap or a
  // clamped edge), a row's two texels are one eight-byte read.
  if (width > 1 && hn::AllTrue(di, hn::Or(hn::Not(activeI), x1 == x0 + hn::Set(di, 1)))) {
    const auto* signedWords = reinterpret_cast<const std::int32_t*>(words);
    GatherPairs(di, signedWords, hn::IfThenElseZero(activeI, r0 + x0), w00, w10);
    GatherPairs(di, signedWords, hn::IfThenElseZero(activeI, r1 + x0), w01, w11);
  } else
#endif
  {
    w00 = fetch(x0, r0), w10 = fetch(x1, r0), w01 = fetch(x0, r1), w11 = fetch(x1, r1);
  }
#if defined(ILLUM_TEXELS_AVX512)
  if (!std::is_same_v<Planes, std::nullptr_t> || texelByteLookups()) {
    const decltype(w00) words[4] = {w00, w10, w01, w11};
    const __m512i raw[4] = {w00.raw, w10.raw, w01.raw, w11.raw};
    __m512 colors[12];
    if constexpr (!std::is_same_v<Planes, std::nullptr_t>) {
      for (int k = 0; k < 4; ++k) (*planes)(raw[k], colors + 3 * k);
    } else {
      LookUpColorBytes(texture.colorTableBytes(), raw, 4, colors);
    }
    V(*texels[4])[4] = {&t00, &t10, &t01, &t11};
    for (int k = 0; k < 4; ++k) {
      for (int c = 0; c < 3; ++c) (*texels[k])[c] = V{colors[3 * k + c]};
      (*texels[k])[3] = AlphaLanes(d, words[k], opaque);
    }
  } else
#endif
  {
#if defined(ILLUM_TEXELS_AVX512)
    const TableRegisters lookUp(color);
#else
    const GatheredTable<D> lookUp{d, color};
#endif
    DecodeTexelLanes(d, w00, linear, opaque, lookUp, t00);
    DecodeTexelLanes(d, w10, linear, opaque, lookUp, t10);
    DecodeTexelLanes(d, w01, linear, opaque, lookUp, t01);
    DecodeTexelLanes(d, w11, linear, opaque, lookUp, t11);
  }
  const V bx = one - ax, by = one - ay;
  for (int c = 0; c < 4; ++c) out[c] = by * (bx * t00[c] + ax * t10[c]) + ay * (bx * t01[c] + ax * t11[c]);
}

// Texture::sample: each lane's texel at (u, v) for a footprint of `texelsPerPixel` base texels.
template <class D, class V = hn::VFromD<D>, class Planes = std::nullptr_t>
HWY_INLINE void SampleTextureLanes(D d, const Texture& texture, V u, V v, V texelsPerPixel, V (&out)[4],
                                   [[maybe_unused]] const Planes* planes = nullptr) {
  const hn::RebindToSigned<D> di;
  const V one = hn::Set(d, Real(1));
  // Magnified everywhere (no footprint over a texel, or a NaN one): level 0 exactly, as MipLevelLanes
  // gives it, without its polynomial.
  const bool magnified = hn::AllFalse(d, texelsPerPixel > one);
  const V clamped = magnified ? hn::Zero(d)
                              : hn::Min(MipLevelLanes(d, texelsPerPixel), hn::Set(d, Real(texture.levelCount() - 1)));
  const V floorLevel = hn::Floor(clamped);
  const V t = clamped - floorLevel;
  const auto level = hn::ConvertTo(di, floorLevel);
  const auto finite = hn::And(hn::IsFinite(u), hn::IsFinite(v));
  for (int c = 0; c < 4; ++c) out[c] = one;  // a uv that is not finite samples white, as Texture::sample
  // One level (pair) at a time: the lanes of a surface mostly share it.
  auto pending = finite;
  while (!hn::AllFalse(d, pending)) {
    const std::size_t lane = std::size_t(hn::FindFirstTrue(d, pending));
    const int l0 = hn::ExtractLane(level, lane);
    const auto these = hn::And(pending, hn::RebindMask(d, level == hn::Set(di, l0)));
    pending = hn::AndNot(these, pending);
    V s0[4], s1[4];
    SampleLevelLanes(d, texture, l0, u, v, these, s0, planes);
    // Lanes at a level exactly (t = 0: magnified, or at the last level) need no second one.
    const auto exact = t == hn::Zero(d);
    if (hn::AllTrue(d, hn::Or(exact, hn::Not(these)))) {
      for (int c = 0; c < 4; ++c) out[c] = hn::IfThenElse(these, s0[c], out[c]);
      continue;
    }
    SampleLevelLanes(d, texture, std::min(l0 + 1, texture.levelCount() - 1), u, v, these, s1, planes);
    for (int c = 0; c < 4; ++c)
      out[c] = hn::IfThenElse(these, hn::IfThenElse(exact, s0[c], (one - t) * s0[c] + t * s1[c]), out[c]);
  }
}

}  // namespace illum::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#undef ILLUM_TEXELS_AVX512
#undef ILLUM_VBMI

#endif  // ILLUM_IMAGE_TEXTURE_LANES_INL_H_
