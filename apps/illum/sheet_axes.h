// The axes of a comparison sheet (`illum compare --rows/--cols`): what varies from one row or
// column to the next, and how a value changes the scene. An axis is NAME or NAME=v1,v2,... (values
// that hold commas themselves, such as colours, are separated by ';'):
//   model, shading, convention, renderer, samples, max-depth, tone-map, encoding, normals, crease-angle,
//   azimuth, elevation, zoom, light-intensity, view-angle   — what `illum render`'s options set;
//   shininess, light-count, material.KEY, light.N.KEY          — what a scene file's keys set.
#pragma once

#include <illum/scene.h>

#include "scene_options.h"

#include <string>
#include <vector>

namespace illum::cli {

struct SheetAxis {
  std::string name;
  std::vector<std::string> values;
};

// Parses `spec` (from `option`, for messages), filling in the axis's default values when none are
// given; a scene's light count sets light-count's. Throws InputError naming the option and value.
SheetAxis parseSheetAxis(const std::string& option, const std::string& spec, std::size_t lightCount);

// Applies one value: to the options (axes that are `illum render` options), or to the scene made
// from them (axes that are scene keys). Each does nothing for the other kind of axis.
void applyToOptions(const SheetAxis& axis, const std::string& value, SceneOptions& o);
void applyToScene(const SheetAxis& axis, const std::string& value, Scene& scene);

}  // namespace illum::cli
