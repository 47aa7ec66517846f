// GL_POINTS and GL_LINES: the points and segments of point clouds and line sets (Mesh::pointIndices,
// lineIndices), drawn after each pass's triangles (every multisample pass too), depth-tested with
// GL_LESS and writing depth, in the scene's object order.
//
// Shapes as GL rasterizes them: on one sample a point is GL's aliased point, the square of
// pointSize pixels around it (size 1: the pixel it lies in); multisampled it is the disc of that
// diameter (GL §3.4's multisample points). A line is lineWidth pixels wide (wide_segment.h).
// Colours as GL gives them: with the file's normals the lighting equation at each vertex (the
// vertex stage, as Gouraud shading lights it, GL_COLOR_MATERIAL included); without, unlit, the
// vertex colour or else the material's diffuse colour (a physically based one's base colour). Lines are smooth-shaded between their
// ends (perspective-correct), flat shading gives the whole line its second vertex's colour.
#pragma once

#include "raster/tile/framebuffer.h"
#include "raster/frame_context.h"
#include "raster/setup/vertex.h"

#include <vector>

namespace illum {

// Draws every object's points and lines into one of the framebuffer's samples (the pass at
// frame.sample); `vertices` is working memory.
void drawPointsAndLines(Framebuffer& fb, const FrameContext& frame, const Scene& scene,
                        std::vector<ShadedVertex>& vertices, int sample = 0);
// Throws InputError when the points and lines, drawn `passes` times, would cover more pixels than
// scene.maxFill (each segment's clipped length plus its width, times its width; each point's square).
void checkPointAndLineFill(const FrameContext& frame, const Scene& scene, int passes);
// Whether any object has points or lines to draw.
bool hasPointsOrLines(const Scene& scene);

}  // namespace illum
