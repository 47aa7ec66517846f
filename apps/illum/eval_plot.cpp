// `illum eval --plot FILE.png`: the report as a figure. With a sweep, each term against the swept
// value; always, the specular lobes of Phong (R·V)ⁿ and Blinn-Phong (N·H)ⁿ in polar form for the
// light's angle and the shininess asked, every point evaluated by the same code as the table.
#include <illum/error.h>
#include <illum/output_file.h>

#include "eval.h"
#include <illum/plot.h>
#include "output_format.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace illum::cli {
namespace {

constexpr int kPanelWidth = 560, kPanelHeight = 420;

std::string text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// The sweep's terms against the swept value: the mean of R, G and B of each term not zero throughout.
std::vector<PlotCurve> sweepCurves(const nlohmann::json& rows, const std::string& swept) {
  // The total first, so that the terms it sums are drawn over it where they coincide.
  const std::vector<std::pair<const char*, Vec3>> terms = {{"total", {0.95, 0.95, 0.95}}, {"emission", {0.85, 0.55, 0.95}},
                                                           {"ambient", {0.55, 0.6, 0.7}},  {"diffuse", {0.35, 0.7, 1.0}},
                                                           {"specular", {1.0, 0.75, 0.3}}};
  std::vector<PlotCurve> curves;
  for (const auto& [name, color] : terms) {
    PlotCurve c{name, color, {}};
    bool nonZero = false;
    for (const nlohmann::json& row : rows) {
      const nlohmann::json& t = row.at(name);
      const double mean = (t.at(0).get<double>() + t.at(1).get<double>() + t.at(2).get<double>()) / 3;
      nonZero = nonZero || mean != 0;
      c.points.push_back({Real(row.at(swept).get<double>()), Real(mean)});
    }
    if (nonZero || std::string(name) == "total") curves.push_back(std::move(c));
  }
  return curves;
}

// The specular lobe of `model` for a viewer at every degree across the plane of incidence.
PlotCurve lobe(const std::string& model, const std::string& name, double theta, const std::string& shininess, Vec3 color) {
  PlotCurve c{name, color, {}};
  for (int alpha = -90; alpha <= 90; ++alpha) {
    EvalOptions o;
    o.model = model;
    o.shininess = shininess;
    o.materialSpecular = "1,1,1";
    o.materialAmbient = o.materialDiffuse = "0,0,0";
    o.normal = "0,0,1";
    const double t = theta * M_PI / 180, a = alpha * M_PI / 180;
    o.toLight = text(std::sin(t)) + ",0," + text(std::cos(t));
    o.toViewer = text(std::sin(a)) + ",0," + text(std::cos(a));
    const nlohmann::json report = nlohmann::json::parse(evalJson(o));
    c.points.push_back({Real(alpha), Real(report.at("specular").at(0).get<double>())});
  }
  return c;
}

// The single value of an option that may be a sweep: its first value.
std::string firstValue(const std::string& option) {
  const std::size_t end = option.find_first_of(",:");
  return end == std::string::npos ? option : option.substr(0, end);
}

}  // namespace

void checkEvalPlot(const std::string& path) {
  const OutputFormat format = outputFormatOf(path, "--plot");
  if (format == OutputFormat::Exr || format == OutputFormat::Mp4)
    throw InputError("--plot " + path + ": a plot is one 8-bit picture: expected .png, .jpg, .webp or .gif");
}

void writeEvalPlot(const EvalOptions& o, const std::string& path) {
  checkEvalPlot(path);
  const std::string swept = sweptOptionName(o);
  const bool sweep = !swept.empty();
  Image image = plotCanvas(kPanelWidth * (sweep ? 2 : 1), kPanelHeight);
  if (sweep) {
    const nlohmann::json rows = nlohmann::json::parse(evalJson(o));
    drawLinePlot(image, 0, 0, kPanelWidth, kPanelHeight, o.model + ": the terms against " + swept, swept,
                 "mean of R, G, B", sweepCurves(rows, swept));
  }
  // The lobes for the light's angle (30° unless one angle is given) and the shininess (10 unless given).
  const double theta = o.angleNL.empty() || swept == "angle-nl" ? 30 : std::stod(o.angleNL);
  const std::string n = o.shininess.empty() ? "10" : firstValue(o.shininess);
  const std::vector<PlotCurve> lobes = {lobe("phong", "Phong (R·V)^" + n, theta, n, {1.0, 0.55, 0.3}),
                                        lobe("blinn-phong", "Blinn-Phong (N·H)^" + n, theta, n, {0.35, 0.75, 1.0})};
  drawPolarPlot(image, sweep ? kPanelWidth : 0, 0, kPanelWidth, kPanelHeight,
                "specular lobes: n = " + n + ", L at " + text(theta) + "° from N", lobes,
                {{"N", 0, {0.8, 0.8, 0.8}}, {"L", Real(theta), {1.0, 0.9, 0.4}}, {"R", Real(-theta), {0.9, 0.9, 0.9}}});
  writeOutputFile(path, encodeStill(outputFormatOf(path, "--plot"), image, std::nullopt), OutputOptions{false});
}

}  // namespace illum::cli
