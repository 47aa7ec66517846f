// Setup stage: one clipped triangle → window coordinates, and the triangle as coverage reads it
// (coverage/triangle.h): fixed-point edge functions with 8 sub-pixel bits, the top-left fill rule,
// facing, and the pixel bounding box.
#pragma once

#include "raster/coverage/triangle.h"
#include "raster/setup/vertex.h"

namespace illum {

// Perspective division and the viewport transform of one clip-space position (glViewport(0,0,w,h),
// glDepthRange(0,1)), x and y rounded to the sub-pixel grid. Only for positions inside the clip
// volume (clip.h), where every value fits.
WindowPosition toWindow(const Vec4& clip, int width, int height);

// Returns false for triangles that cover no pixel centre's neighbourhood (zero area or off-screen).
// Window coordinates are GL's: origin at the bottom-left, pixel centres at +0.5. A multisample
// pass moves the triangle by −`sample` (sub-pixel units), so that the rasterizer's pixel centres
// test coverage and depth at centre + sample. With a `reach` (multisampling in one pass), the
// pixel bounds take in every pixel whose samples, that far from its centre, the triangle may cover.
bool setupTriangle(const ShadedVertex& v0, const ShadedVertex& v1, const ShadedVertex& v2, int width, int height,
                   TriangleSetup& out, SubpixelOffset sample = {}, const FrameContext::SampleReach& reach = {});

}  // namespace illum
