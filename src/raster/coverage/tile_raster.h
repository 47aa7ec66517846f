// Rasterize stage, SIMD: the depth pass of one triangle over one 64×64 tile. Pixels are visited
// a row at a time, as many as the CPU's widest double vector holds; the fixed-point edge functions
// are evaluated exactly in double lanes (|E| < 2^53), so coverage, barycentrics and depth come out
// bit for bit as the scalar rasterizer (rasterize.h) computes them.
#pragma once

#include "raster/tile/framebuffer.h"
#include "raster/coverage/rasterize.h"
#include "raster/coverage/tiny_fragment.h"

#include <illum/lighting.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>

namespace illum {

constexpr std::uint32_t kNoWinner = 0xFFFFFFFF;

// GL_LESS against the tile's depths (kTileSize² of them, the tile's bottom-left pixel first); where
// a fragment passes, its depth is stored and `slot` written to `winners` (the same layout), so that
// afterwards each pixel names the triangle it shows. `tile` is the tile's rectangle, clipped to the
// viewport; where it passes, the visible surface's owner (SurfaceTile), unless null, is cleared.
// Returns the number of fragments that passed.
std::size_t rasterizeDepth(const TriangleSetup& t, const PixelRect& tile, Real* depth, std::uint32_t slot,
                           std::uint32_t* winners, std::uint32_t* owner = nullptr);

// A tiny triangle (isTiny: bounds of a few pixels) is worked out as soon as it is set up, without
// a record, in each tile its bounds overlap (forEachTilePiece): coverTiny* write its covered pixels
// in one tile (`t`'s bounds inside it) to `out` (room for kTinyRoom) for that tile (bin.h), to be
// depth-tested later, each tagged with `recordsBefore`: with depths and RGBA8 colours exactly as
// rasterizeFlat (`packed`) or rasterizeGouraud would write them, or with the visible surface as
// rasterizeSurface would keep it (coverTinySurface, for a triangle without vertex colours). They
// return how many they wrote (at most kTinyPixels), in rows from the bottom. Float channels only.
constexpr std::size_t kTinyRoom = kTinyPixels;
inline bool isTiny(const TriangleSetup& t) { return (t.maxX - t.minX + 1) * (t.maxY - t.minY + 1) <= kTinyPixels; }
inline bool inOneTile(const TriangleSetup& t) {
  return t.minX / kTileSize == t.maxX / kTileSize && t.minY / kTileSize == t.maxY / kTileSize;
}
// f(piece) for each tile that t's bounds overlap (one, two or four for a tiny triangle), bottom
// row first: `piece` is t with its bounds cut to the tile. The edge functions are t's, so each
// pixel is tested and interpolated as in t.
template <class F>
void forEachTilePiece(const TriangleSetup& t, F&& f) {
  if (inOneTile(t)) {
    f(t);
    return;
  }
  TriangleSetup piece = t;
  for (int ty = t.minY / kTileSize; ty <= t.maxY / kTileSize; ++ty)
    for (int tx = t.minX / kTileSize; tx <= t.maxX / kTileSize; ++tx) {
      piece.minX = std::max(t.minX, tx * kTileSize), piece.maxX = std::min(t.maxX, tx * kTileSize + kTileSize - 1);
      piece.minY = std::max(t.minY, ty * kTileSize), piece.maxY = std::min(t.maxY, ty * kTileSize + kTileSize - 1);
      f(std::as_const(piece));
    }
}

// Multisampling in one pass: a tile's depths, RGBA8 words and the records its pixels show, each
// pixel's `count` samples side by side (sample s of pixel i at i·count + s, framebuffer.h), and
// where each sample lies from the pixel centre.
struct SamplePlanes {
  int count = 0;
  const SubpixelOffset* offsets = nullptr;
  // The samples' offsets in sixteenths of a pixel, lane by lane: lane k holds sample k mod count
  // (FrameContext::sampleLanes).
  const std::int32_t* laneX = nullptr;
  const std::int32_t* laneY = nullptr;
  Real* depth = nullptr;
  std::uint32_t* color = nullptr;
  std::uint32_t* winners = nullptr;
};

// The depth pass of a triangle set up at the pixel centres (with the samples' reach) at every
// sample of its pixels in `tile`: coverage and depth at each sample exactly as a pass at that
// sample finds them (rasterizeDepth of atSample(t, offset)), the depth stored per sample, and
// where a sample passes, its winner set to `slot`. Returns the samples that passed.
std::size_t rasterizeSamples(const TriangleSetup& t, const PixelRect& tile, const SamplePlanes& planes,
                             std::uint32_t slot);
// The same, and the pixels (tile indices) where some sample passed appended to `listed`, in row
// order, each once: how many in `listedCount`. `listed` has room for listedRoom(t, tile) words.
// (Some of them may show another record by the tile's end: the shade hand-off keeps those that
// still show this one, keepShown.)
std::size_t rasterizeSamples(const TriangleSetup& t, const PixelRect& tile, const SamplePlanes& planes,
                             std::uint32_t slot, std::uint32_t* listed, std::size_t& listedCount);
// The room rasterizeSamples' list needs: t's bounds' pixels in `tile`, and a vector past them.
inline std::size_t listedRoom(const TriangleSetup& t, const PixelRect& tile) {
  const int w = std::min(t.maxX, tile.maxX) - std::max(t.minX, tile.minX) + 1;
  const int h = std::min(t.maxY, tile.maxY) - std::max(t.minY, tile.minY) + 1;
  return (w > 0 && h > 0 ? std::size_t(w) * std::size_t(h) : 0) + 16;
}

#if !ILLUM_USE_DOUBLE
// The same for flat (`lit` null: the colour `packed`) and Gouraud (the vertex colours `lit`) drawing,
// the colour worked out once per pixel at its centre and written to every sample that passed
// (and, with `clearWinners`, the winner there cleared).
std::size_t rasterizeSamplesColored(const TriangleSetup& t, const PixelRect& tile, const SamplePlanes& planes,
                                    const Color4* lit, std::uint32_t packed, bool clearWinners);

// Flat and Gouraud drawing in the same pass, for float colour channels (ILLUM_DOUBLE=OFF): where
// the depth test passes, the pixel of `color` (the tile's RGBA8 pixels as 32-bit words, same
// layout) gets the flat colour `packed`, or the three vertex colours `lit` (counter-clockwise
// order) blended perspective-correctly, converted as Framebuffer::writeColor converts; and unless
// `winners` is null, the pixel's winner is cleared (kNoWinner).
std::size_t rasterizeFlat(const TriangleSetup& t, const PixelRect& tile, Real* depth, std::uint32_t* color,
                          std::uint32_t* winners, std::uint32_t packed);
std::size_t rasterizeGouraud(const TriangleSetup& t, const PixelRect& tile, Real* depth, std::uint32_t* color,
                             std::uint32_t* winners, const Color4* lit);

std::size_t coverTinyFlat(const TriangleSetup& t, std::uint32_t packed, std::uint32_t recordsBefore, TinyFragment* out);
std::size_t coverTinyGouraud(const TriangleSetup& t, const Color4* lit, std::uint32_t recordsBefore, TinyFragment* out);

// Phong shading's first pass: the visible surface of one tile, kept as planes in the tile's
// layout (kTileBlock values each), to be lit once per pixel afterwards (shadeSurfaces).
struct SurfaceTile {
  Real* position[3];
  Real* normal[3];
  Real* color[4];          // written only for triangles with vertex colours
  std::uint32_t* owner;    // the object shown (kNoWinner: nothing drawn this pass)
};

// What a triangle's pixels interpolate, in its counter-clockwise order.
struct SurfaceVertices {
  std::array<Vec3, 3> position, normal;
  std::array<Color4, 3> color;
  bool colors = false;     // vertex colours (GL_COLOR_MATERIAL)
  bool negate = false;     // two-sided lighting of a back face: light with −N
  std::uint32_t owner = 0;
};

// Where the depth test passes: the perspective-correct position, the renormalized normal and the
// colour (exactly as phongSurface in fragment.h computes them) and the owner; `winners`, unless
// null, cleared there.
std::size_t rasterizeSurface(const TriangleSetup& t, const PixelRect& tile, Real* depth, const SurfaceVertices& v,
                             const SurfaceTile& out, std::uint32_t* winners = nullptr);
std::size_t coverTinySurface(const TriangleSetup& t, const SurfaceVertices& v, std::uint32_t recordsBefore,
                             TinySurface* out);
#endif  // !ILLUM_USE_DOUBLE

}  // namespace illum
