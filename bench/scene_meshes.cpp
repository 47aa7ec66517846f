// A scene's triangles as the renderers see them, in world space, for peers that cannot build
// GLUT's solids (the teapot above all) the way illum tessellates them: Blender's Cycles in
// bench/compare_cycles.sh. One JSON object: "objects", in the scene's order, each with flat
// "positions", "normals" (unit, transformed as normals are) and "indices".
//   illum_scene_meshes SCENE.json|builtin OUT.json
#include <illum/error.h>
#include <illum/scene.h>

#include "math/transform.h"

#include <cstdio>
#include <exception>
#include <fstream>
#include <string>
#include <type_traits>
#include <vector>

namespace {

// Floats with the nine digits that give back their bits; indices as the integers they are.
template <class T>
void writeNumbers(std::ofstream& out, const char* key, const std::vector<T>& values) {
  out << '"' << key << "\": [";
  char number[32];
  for (std::size_t i = 0; i < values.size(); ++i) {
    if constexpr (std::is_floating_point_v<T>) std::snprintf(number, sizeof number, "%s%.9g", i ? "," : "", double(values[i]));
    else std::snprintf(number, sizeof number, "%s%u", i ? "," : "", unsigned(values[i]));
    out << number;
  }
  out << ']';
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: illum_scene_meshes SCENE.json|builtin OUT.json\n");
    return 2;
  }
  try {
    const std::string input = argv[1];
    const illum::Scene scene = input == "builtin" ? illum::defaultScene() : illum::loadSceneFile(input);
    std::ofstream out(argv[2]);
    if (!out) throw illum::InputError(std::string(argv[2]) + ": cannot be written");
    out << "{\"objects\": [";
    for (std::size_t o = 0; o < scene.objects.size(); ++o) {
      const illum::Object& object = scene.objects[o];
      const illum::Mesh& mesh = *object.mesh;
      const illum::Mat3 normalFrom = illum::normalMatrix(object.worldFromObject);
      std::vector<float> positions, normals;
      for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        const illum::Vec3 p = illum::Vec3(object.worldFromObject * illum::Vec4(mesh.positions[v], 1));
        positions.insert(positions.end(), {float(p.x), float(p.y), float(p.z)});
        if (v < mesh.normals.size()) {
          const illum::Vec3 n = glm::normalize(normalFrom * mesh.normals[v]);
          normals.insert(normals.end(), {float(n.x), float(n.y), float(n.z)});
        }
      }
      out << (o ? ",\n" : "\n") << '{';
      writeNumbers(out, "positions", positions);
      out << ", ";
      writeNumbers(out, "normals", normals);
      out << ", ";
      writeNumbers(out, "indices", mesh.indices);
      out << '}';
    }
    out << "\n]}\n";
    if (!out) throw illum::InputError(std::string(argv[2]) + ": could not be written whole");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "illum_scene_meshes: %s\n", e.what());
    return 2;
  }
}
