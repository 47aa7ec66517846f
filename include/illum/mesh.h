// Meshes: geometry only, structure of arrays. Triangles (counter-clockwise front faces), and the
// points and line segments of point clouds and line sets, which the rasterizer draws as GL_POINTS
// and GL_LINES (raster/points_lines.h).
#pragma once

#include <illum/real.h>

#include <cstdint>
#include <vector>

namespace illum {

struct Mesh {
  std::vector<Vec3> positions;
  // One per position, unit length. Empty only in a mesh without triangles whose file gave none:
  // its points and lines are then drawn unlit.
  std::vector<Vec3> normals;
  std::vector<std::uint32_t> indices;  // three per triangle; the LAST is GL's provoking vertex
  std::vector<std::uint32_t> pointIndices;  // one per point (GL_POINTS)
  std::vector<std::uint32_t> lineIndices;   // two per segment (GL_LINES)
  std::vector<Vec2> uvs;       // optional: texture coordinates, one per position (GL: v up)
  std::vector<Vec4> colors;    // optional: vertex colours, one per position (GL_COLOR_MATERIAL)

  std::size_t triangleCount() const { return indices.size() / 3; }
  std::size_t pointCount() const { return pointIndices.size(); }
  std::size_t lineCount() const { return lineIndices.size() / 2; }
  bool hasPointsOrLines() const { return !pointIndices.empty() || !lineIndices.empty(); }
};

// GLUT's solids (freeglut's vertex layout and parameters), centred at the origin.
Mesh makeSphere(Real radius, int slices, int stacks);
Mesh makeCube(Real size);
Mesh makeTorus(Real innerRadius, Real outerRadius, int sides, int rings);
Mesh makeCone(Real base, Real height, int slices, int stacks);
Mesh makeTeapot(Real size);

// How an importer chooses normals.
enum class NormalMode { Auto, Flat, Smooth, File };

// Replaces the normals: each corner gets the angle-weighted mean of the faces around its position
// (vertices are welded by position) whose normals lie within `creaseAngleDegrees` of its own face,
// so edges sharper than the crease angle stay sharp. Vertices are split where needed;
// uvs and colours travel with them. A crease angle of 180 smooths everything.
void generateCreaseNormals(Mesh& mesh, Real creaseAngleDegrees);
// Replaces the normals by face normals: every triangle gets its own three vertices.
void generateFlatNormals(Mesh& mesh);

// Smooth vertex normals: the angle-weighted mean of the faces around each vertex.
// Vertices whose faces cancel out get the normal of their first face.
std::vector<Vec3> generateSmoothNormals(const std::vector<Vec3>& positions,
                                        const std::vector<std::uint32_t>& indices);

}  // namespace illum
