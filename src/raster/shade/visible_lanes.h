// What the deferred colours' gather (shade_visible.cpp) and texture loops (visible_texels.cpp)
// share over lanes.
#pragma once

namespace illum {

// Where each lane's pixel falls on the textures (texturePoint): its uv, and how uv changes one
// pixel right (dx) and one up (dy), from the barycentrics moved by the record's steps.
template <class V>
struct UvLanes {
  V uv[2], dx[2], dy[2];
};

}  // namespace illum
