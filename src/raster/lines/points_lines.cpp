#include "raster/lines/points_lines.h"

#include "raster/lines/wide_segment.h"

#include <illum/error.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <span>

namespace illum {
namespace {

constexpr std::size_t kVertexGrain = 4096;  // vertices per parallel task

// Every vertex's clip position and colour (`front`), as the header says.
// `out` holds one slot per vertex of the mesh.
void prepareVertices(const FrameContext& litFrame, const Object& object, std::span<ShadedVertex> out) {
  const Mesh& mesh = *object.mesh;
  const Mat4 clipFromObject = litFrame.clipFromView * litFrame.viewFromWorld * object.worldFromObject;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, out.size(), kVertexGrain), [&](const auto& r) {
    if (!mesh.normals.empty()) {
      runVertexStage(litFrame, object, 0, out, r.begin(), r.end());
      return;
    }
    // A physically based material's colour is its base colour (its GL diffuse is base·(1 − metallic)).
    const Material& m = object.material;
    const Color4 unlit = m.physicallyBased ? Color4(m.physical.baseColor, m.diffuse.a) : m.diffuse;
    for (std::size_t i = r.begin(); i < r.end(); ++i) {
      out[i].clip = clipFromObject * Vec4(mesh.positions[i], 1);
      out[i].front = mesh.colors.empty() ? unlit : mesh.colors[i];
    }
  });
}

// Into `plane`, one of the framebuffer's samples.
void writeFragment(Framebuffer& fb, int plane, const FrameContext& frame, int x, int y, Real z, const Color4& color) {
  fb.clearTile(x, y);  // a tile no triangle touched is cleared now
  if (z < 0 || z > 1 || !fb.depthTest(x, y, z, plane)) return;
  if (frame.blend) fb.blendColor(x, y, color, plane);
  else fb.writeColor(x, y, color, plane);
}

// Rows [rowBegin, rowEnd): the band of tile rows one task draws.
struct Rows {
  int begin, end;
};

void drawPoint(Framebuffer& fb, int plane, const FrameContext& frame, const ShadedVertex& v, Real size, Rows rows) {
  const Vec4& c = v.clip;
  // GL passes a point whose centre is inside the clip volume, whole, and discards any other.
  if (!(c.w > 0) || std::abs(c.x) > c.w || std::abs(c.y) > c.w || std::abs(c.z) > c.w) return;
  const Real cx = (c.x / c.w + 1) * Real(0.5) * Real(frame.width), cy = (c.y / c.w + 1) * Real(0.5) * Real(frame.height);
  const Real z = (c.z / c.w + 1) * Real(0.5), half = size / 2;
  // Samples lie less than half a pixel from pixel centres: pixels beyond these cannot be covered.
  const int x0 = std::max(0, int(std::ceil(cx - half - 1))), x1 = std::min(frame.width - 1, int(std::floor(cx + half)));
  const int y0 = std::max(rows.begin, int(std::ceil(cy - half - 1)));
  const int y1 = std::min(rows.end - 1, int(std::floor(cy + half)));
  const Vec2 sample(Real(frame.sample.x) / 256, Real(frame.sample.y) / 256);
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      const Vec2 d = Vec2(Real(x) + Real(0.5), Real(y) + Real(0.5)) + sample - Vec2(cx, cy);
      // Multisampled, the disc of diameter `size` at this pass's sample position; else the pixels
      // whose centres lie in the square [c − size/2, c + size/2) (size 1: the pixel c is in).
      const bool covered = frame.multisampled ? glm::dot(d, d) <= half * half
                                              : d.x >= -half && d.x < half && d.y >= -half && d.y < half;
      if (covered) writeFragment(fb, plane, frame, x, y, z, v.front);
    }
}

void drawLine(Framebuffer& fb, int plane, const FrameContext& frame, const ShadedVertex& a, const ShadedVertex& b, Real width,
              Rows rows) {
  const auto s = windowSegment(frame, a.clip, b.clip);
  if (!s) return;
  forEachSegmentPixel(frame, *s, width, [&](int x, int y, Real t) {
    Color4 color = b.front;  // flat shading: the provoking (second) vertex's
    if (frame.shading != Shading::Flat) {
      // Perspective-correct: t is along the window-space segment, u along the original one.
      const Real along = (t / s->wB) / ((1 - t) / s->wA + t / s->wB);
      const Real u = s->tA + along * (s->tB - s->tA);
      color = a.front + u * (b.front - a.front);
    }
    writeFragment(fb, plane, frame, x, y, s->a.z + t * (s->b.z - s->a.z), color);
  }, rows.begin, rows.end);
}

}  // namespace

void checkPointAndLineFill(const FrameContext& frame, const Scene& scene, int passes) {
  const double screen = double(frame.width) * double(frame.height);
  double fill = 0;
  for (const Object& object : scene.objects) {
    const Mesh& mesh = *object.mesh;
    if (!mesh.hasPointsOrLines()) continue;
    const Mat4 clipFromObject = frame.clipFromView * frame.viewFromWorld * object.worldFromObject;
    const auto clip = [&](std::uint32_t i) { return clipFromObject * Vec4(mesh.positions[i], 1); };
    const double w = double(scene.lineWidth) + 2;
    for (std::size_t i = 0; i + 1 < mesh.lineIndices.size(); i += 2)
      if (const auto s = windowSegment(frame, clip(mesh.lineIndices[i]), clip(mesh.lineIndices[i + 1])))
        fill += std::min(screen, (double(glm::length(Vec2(s->b - s->a))) + w) * w);
    const double point = double(scene.pointSize) + 2;
    fill += double(mesh.pointIndices.size()) * std::min(screen, point * point);
  }
  fill *= std::max(1, passes);
  if (fill > double(scene.maxFill))
    throw InputError("the points and lines would cover about " + withThousands(std::uint64_t(fill)) +
                     " pixels over " + std::to_string(std::max(1, passes)) + " passes, more than the limit of " +
                     withThousands(scene.maxFill) + " (narrower --line-width or --point-size, fewer --samples, or raise it "
                     "with --max-fill)");
}

bool hasPointsOrLines(const Scene& scene) {
  return std::any_of(scene.objects.begin(), scene.objects.end(),
                     [](const Object& o) { return o.mesh->hasPointsOrLines(); });
}

void drawPointsAndLines(Framebuffer& fb, const FrameContext& frame, const Scene& scene,
                        std::vector<ShadedVertex>& vertices, int sample) {
  // The vertex stage lights vertices for flat and Gouraud shading: points and lines have no pixels
  // to light in between, so Phong shading lights them at their vertices too.
  FrameContext litFrame = frame;
  if (frame.shading == Shading::Phong) litFrame.shading = Shading::Gouraud;
  litFrame.occlusion = nullptr;  // points and lines have no surface to occlude
  // Every object's vertices first (one after another in `vertices`), then the primitives in
  // their order, by bands of tile rows in parallel: a pixel belongs to one band, so it sees the
  // same fragments in the same order as if drawn by one thread, and each tile is cleared by one.
  std::vector<std::pair<const Object*, std::size_t>> drawn;  // objects with primitives, where their vertices start
  std::size_t total = 0;
  for (const Object& object : scene.objects)
    if (object.mesh->hasPointsOrLines()) drawn.push_back({&object, total}), total += object.mesh->positions.size();
  if (drawn.empty()) return;
  vertices.resize(total);
  for (const auto& [object, first] : drawn)
    prepareVertices(litFrame, *object, std::span<ShadedVertex>(vertices).subspan(first, object->mesh->positions.size()));
  const int bands = (frame.height + kTileSize - 1) / kTileSize;
  tbb::parallel_for(0, bands, [&](int band) {
    const Rows rows{band * kTileSize, std::min(frame.height, (band + 1) * kTileSize)};
    for (const auto& [object, first] : drawn) {
      const Mesh& mesh = *object->mesh;
      const ShadedVertex* v = vertices.data() + first;
      for (std::size_t i = 0; i + 1 < mesh.lineIndices.size(); i += 2)
        drawLine(fb, sample, frame, v[mesh.lineIndices[i]], v[mesh.lineIndices[i + 1]], scene.lineWidth, rows);
      for (std::uint32_t i : mesh.pointIndices) drawPoint(fb, sample, frame, v[i], scene.pointSize, rows);
    }
  });
}

}  // namespace illum
