// Triangle meshes: geometry only, structure of arrays, counter-clockwise front faces.
#pragma once

#include <illum/real.h>

#include <cstdint>
#include <vector>

namespace illum {

struct Mesh {
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;  // one per position, unit length
  std::vector<std::uint32_t> indices;  // three per triangle; the LAST is GL's provoking vertex

  std::size_t triangleCount() const { return indices.size() / 3; }
};

// GLUT's solids (freeglut's vertex layout and parameters), centred at the origin.
Mesh makeSphere(Real radius, int slices, int stacks);
Mesh makeCube(Real size);
Mesh makeTorus(Real innerRadius, Real outerRadius, int sides, int rings);
Mesh makeCone(Real base, Real height, int slices, int stacks);
Mesh makeTeapot(Real size);

// Smooth vertex normals: the angle-weighted mean of the faces around each vertex.
// Vertices whose faces cancel out get the normal of their first face.
std::vector<Vec3> generateSmoothNormals(const std::vector<Vec3>& positions,
                                        const std::vector<std::uint32_t>& indices);

}  // namespace illum
