// `illum eval`'s options and its report as JSON, which the library's evaluate() returns too.
#pragma once

#include <CLI/CLI.hpp>

#include <string>

namespace illum::cli {

struct EvalOptions {
  std::string model = "blinn-phong";
  std::string lightAmbient, lightDiffuse, lightSpecular;
  std::string materialAmbient, materialDiffuse, materialSpecular, materialEmission;
  std::string shininess, globalAmbient, distance, attenuation;
  std::string angleNL, angleRV, angleNH;
  std::string normal, toLight, toViewer;
  std::string spotDirection, spotExponent, spotCutoff;
  std::string baseColor, metallic, roughness, f0, distribution;  // a physically based material
  bool json = false, quiet = false;
  std::string plot;        // --plot FILE.png
  std::string convention;  // --convention NAME: a lecture note's way beside GL's (LightModel::convention)
};

// The options of `illum eval`, on `cmd`.
void addEvalOptions(CLI::App& cmd, EvalOptions& o);

// The terms as JSON (`illum eval --json`): one object, or with a sweep an array of them, each with
// the swept value under the option's name. Throws InputError for values it refuses.
std::string evalJson(const EvalOptions& o);

// The option a sweep varies, without its dashes ("angle-nl"), or empty.
std::string sweptOptionName(const EvalOptions& o);

// `--plot FILE`: refuses a name that is not a still picture (before anything is evaluated), and
// writes the figure: each term against the swept value (with a sweep) and the specular lobes.
void checkEvalPlot(const std::string& path);
void writeEvalPlot(const EvalOptions& o, const std::string& path);

}  // namespace illum::cli
