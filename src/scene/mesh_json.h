// A scene file's "mesh" value made into a mesh, for scenes built in code that say their meshes as
// a scene file would (the built-in scene), so that they can be written out as one (sceneJson).
#pragma once

#include <illum/mesh.h>

#include <string>

namespace illum {

// GLUT's solids and "triangles" (a model file is a scene file's to read: refused here). Throws
// InputError as the scene reader would.
Mesh meshFromJson(const std::string& json);

}  // namespace illum
