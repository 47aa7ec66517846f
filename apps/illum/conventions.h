// The lecture notes' own ways of computing what OpenGL computes, by name, so that `illum eval
// --convention NAME` can follow a note beside GL and show where and by how much the two differ.
//
//   note-shader    seed 001's Blinn-Phong shader: pixel = mat.ambient + (mat.diffuse + specular) ×
//                  light strength, the strength Ld·max(N·L, 0): the specular term scaled by N·L too,
//                  and the ambient the material's alone (no light or global ambient)
//   note-half-sum  seed 001's H = (L + V) / 2 before it is normalised: N·H smaller than GL's, so
//                  (N·H)ⁿ falls off faster
#pragma once

#include <illum/lighting.h>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace illum::cli {

enum class Convention { NoteShader, NoteHalfSum };

std::optional<Convention> parseConvention(std::string_view name);
std::vector<std::string> conventionNames();

struct ConventionTerms {
  std::string name, formula;
  Color3 emission{0}, ambient{0}, diffuse{0}, specular{0}, total{0};
  Real NoH = 0;  // note-half-sum: N·H with the unnormalised H
};

// The terms at the point `d` describes (GL's evaluation of one light, its share of `gl`, the whole
// of GL's terms there), as the note computes them.
ConventionTerms underConvention(Convention c, const LightingTerms& gl, const EyeLight& light, const Material& m,
                                LightingModel model, const LightDetail& d, const Vec3& N, const Vec3& V);

}  // namespace illum::cli
