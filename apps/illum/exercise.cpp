// `illum exercise`: problems of the kinds the lecture notes set (one light and material, attenuation
// with distance, a spot's cutoff, a Gouraud-interpolated point, Phong against Blinn-Phong), with
// values drawn from a seed, and an answer key worked step by step. Every figure of the key comes
// from `illum eval`'s own evaluation, and each answer names the `illum eval` command that checks it.
#include <illum/error.h>
#include <illum/output_file.h>

#include "cli_values.h"
#include "commands.h"
#include "eval.h"
#include "named_options.h"

#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace illum::cli {
namespace {

struct ExerciseOptions {
  unsigned seed = 1;
  int count = 5;
  std::string kinds = "all", format, output;
  bool noAnswers = false;
};

// Values from the seed: mt19937's sequence is the same on every platform (the standard fixes it),
// and the picks below use its raw numbers, not a library's distribution.
class Draw {
 public:
  explicit Draw(unsigned seed) : engine_(seed) {}
  template <typename T>
  T pick(const std::vector<T>& values) { return values[engine_() % values.size()]; }
  // A colour of tenths, each channel in [lo, hi] tenths.
  std::array<int, 3> tenths(int lo, int hi) {
    std::array<int, 3> c{};
    for (int& v : c) v = lo + int(engine_() % unsigned(hi - lo + 1));
    return c;
  }

 private:
  std::mt19937 engine_;
};

std::string tenthsText(const std::array<int, 3>& c) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.1f,%.1f,%.1f", c[0] / 10.0, c[1] / 10.0, c[2] / 10.0);
  return buf;
}
std::string tenthsTriple(const std::array<int, 3>& c) { return "(" + tenthsText(c) + ")"; }

std::string fixed(double x, int digits = 4) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*f", digits, x);
  std::string s = buf;
  return s == "-0.0000" ? "0.0000" : s;
}

std::string rgb(const nlohmann::json& v) {
  return fixed(v.at(0).get<double>()) + " " + fixed(v.at(1).get<double>()) + " " + fixed(v.at(2).get<double>());
}

// An `illum eval` the key quotes: its options, and its report (the same evaluation, as JSON).
struct Check {
  std::vector<std::pair<std::string, std::string>> options;  // option (with dashes), value
  nlohmann::json report;
  std::vector<std::string> answers;  // the JSON keys the key states from it
};

Check evaluateCheck(std::vector<std::pair<std::string, std::string>> options, std::vector<std::string> answers) {
  EvalOptions o;
  CLI::App app;
  addEvalOptions(app, o);
  NamedOptions named;
  for (const auto& [name, value] : options) named.push_back({name.substr(2), value});  // without the dashes
  parseNamedOptions(app, "eval", named);
  return {std::move(options), nlohmann::json::parse(evalJson(o)), std::move(answers)};
}

struct Problem {
  std::string title, statement;
  std::vector<std::string> steps;  // the worked answer, a line each
  std::vector<Check> checks;
};

double value(const Check& c, const char* key) { return c.report.at(key).get<double>(); }

Problem colouredLight(Draw& draw) {
  const int theta = draw.pick<int>({0, 15, 30, 45, 60, 75}), phi = draw.pick<int>({0, 10, 20, 30});
  const int n = draw.pick<int>({1, 2, 4, 8, 10});
  const auto la = draw.tenths(0, 10), ld = draw.tenths(2, 10), ls = draw.tenths(5, 10);
  const auto ka = draw.tenths(0, 10), kd = draw.tenths(0, 10), ks = draw.tenths(0, 10);
  Problem p;
  p.title = "Coloured light (Phong)";
  p.statement = "One light and a surface point P at distance D = 1. The angle between the light vector L and the normal N "
                "is " + std::to_string(theta) + "°; the angle between the reflected ray R and the view vector V is " +
                std::to_string(phi) + "°. The light's ambient (R,G,B) = " + tenthsTriple(la) + ", diffuse " +
                tenthsTriple(ld) + ", specular " + tenthsTriple(ls) + "; the material reflects ambient " +
                tenthsTriple(ka) + ", diffuse " + tenthsTriple(kd) + ", specular " + tenthsTriple(ks) +
                ". The shininess is n = " + std::to_string(n) + ". Find the ambient, diffuse and specular light "
                "reflected from P, channel by channel.";
  Check c = evaluateCheck({{"--model", "phong"}, {"--distance", "1"}, {"--angle-nl", std::to_string(theta)},
                           {"--angle-rv", std::to_string(phi)}, {"--light-ambient", tenthsText(la)},
                           {"--light-diffuse", tenthsText(ld)}, {"--light-specular", tenthsText(ls)},
                           {"--material-ambient", tenthsText(ka)}, {"--material-diffuse", tenthsText(kd)},
                           {"--material-specular", tenthsText(ks)}, {"--shininess", std::to_string(n)}},
                          {"ambient", "diffuse", "specular", "total"});
  p.steps = {"Each channel separately: ambient = k_a · I_a = " + rgb(c.report["ambient"]),
             "cos θ = N·L = cos " + std::to_string(theta) + "° = " + fixed(value(c, "NoL")) +
                 "; diffuse = k_d · I_d · cos θ = " + rgb(c.report["diffuse"]),
             "cos φ = R·V = cos " + std::to_string(phi) + "° = " + fixed(value(c, "RoV")) + "; (cos φ)^" +
                 std::to_string(n) + " = " + fixed(value(c, "lobe")) + "; specular = k_s · I_s · (cos φ)^n = " +
                 rgb(c.report["specular"]),
             "The light reflected is their sum, each channel clamped to 1: " + rgb(c.report["total"])};
  p.checks.push_back(std::move(c));
  return p;
}

Problem attenuation(Draw& draw) {
  const int d = draw.pick<int>({1, 2, 3, 4, 5}), theta = draw.pick<int>({0, 30, 45, 60});
  const std::string kc = draw.pick<std::string>({"1", "0.5", "0"}), kl = draw.pick<std::string>({"0", "0.5", "1"});
  const std::string kq = draw.pick<std::string>({"0.1", "0.25", "1"});
  const auto kd = draw.tenths(2, 10);
  Problem p;
  p.title = "Attenuation with distance";
  p.statement = "A white positional light (diffuse 1,1,1) is " + std::to_string(d) +
                (d == 1 ? " unit" : " units") + " from a point whose normal makes " + std::to_string(theta) + "° with the light vector. The "
                "light's attenuation coefficients are k_c = " + kc + ", k_l = " + kl + ", k_q = " + kq +
                " (OpenGL's 1/(k_c + k_l·d + k_q·d²)). The material's diffuse reflectance is " + tenthsTriple(kd) +
                ". Find the attenuation factor and the diffuse light reflected.";
  Check c = evaluateCheck({{"--model", "lambert"}, {"--distance", std::to_string(d)},
                           {"--attenuation", kc + "," + kl + "," + kq}, {"--angle-nl", std::to_string(theta)},
                           {"--material-diffuse", tenthsText(kd)}, {"--material-ambient", "0,0,0"}},
                          {"attenuation", "diffuse"});
  p.steps = {"attenuation = 1/(" + kc + " + " + kl + "·" + std::to_string(d) + " + " + kq + "·" + std::to_string(d) +
                 "²) = " + fixed(value(c, "attenuation")),
             "cos θ = " + fixed(value(c, "NoL")) + "; diffuse = attenuation · k_d · I_d · cos θ = " + rgb(c.report["diffuse"])};
  p.checks.push_back(std::move(c));
  return p;
}

// A unit vector at `degrees` from -L (the direction from the light to the point), in the plane
// of incidence, where L is `theta` degrees from N = +Z towards +X.
std::string spotAxis(int theta, int degrees) {
  const double a = (180.0 + theta + degrees) * M_PI / 180.0;
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.9f,0,%.9f", std::sin(a), std::cos(a));
  return buf;
}

Problem spot(Draw& draw) {
  const int cutoff = draw.pick<int>({15, 20, 30, 45}), off = draw.pick<int>({0, 5, 10, 20, 25, 40, 50});
  const int exponent = draw.pick<int>({0, 1, 2, 8, 16}), theta = draw.pick<int>({0, 30, 45});
  Problem p;
  p.title = "A spot's cutoff";
  p.statement = "A white spot light (diffuse 1,1,1) with a cutoff of " + std::to_string(cutoff) + "° and a spot exponent of " +
                std::to_string(exponent) + " lights a point whose normal makes " + std::to_string(theta) +
                "° with the light vector; the spot's axis is " + std::to_string(off) +
                "° off the direction from the light to the point. The material's diffuse reflectance is (1,1,1). "
                "Find the spot factor and the diffuse light reflected.";
  Check c = evaluateCheck({{"--model", "lambert"}, {"--angle-nl", std::to_string(theta)}, {"--distance", "1"},
                           {"--spot-cutoff", std::to_string(cutoff)}, {"--spot-exponent", std::to_string(exponent)},
                           {"--spot-direction", spotAxis(theta, off)}, {"--material-diffuse", "1,1,1"},
                           {"--material-ambient", "0,0,0"}},
                          {"spot", "diffuse"});
  if (off > cutoff)
    p.steps.push_back(std::to_string(off) + "° > the cutoff of " + std::to_string(cutoff) +
                      "°: the point is outside the cone, spot factor = " + fixed(value(c, "spot")));
  else
    p.steps.push_back(std::to_string(off) + "° ≤ the cutoff of " + std::to_string(cutoff) + "°: spot factor = (cos " +
                      std::to_string(off) + "°)^" + std::to_string(exponent) + " = " + fixed(value(c, "spot")));
  p.steps.push_back("cos θ = " + fixed(value(c, "NoL")) + "; diffuse = spot · k_d · I_d · cos θ = " + rgb(c.report["diffuse"]));
  p.checks.push_back(std::move(c));
  return p;
}

Problem gouraud(Draw& draw) {
  std::array<int, 3> angles{}, weights{};
  for (int& a : angles) a = draw.pick<int>({0, 15, 30, 45, 60, 75, 90});
  weights[0] = draw.pick<int>({1, 2, 3, 4, 5});
  weights[1] = draw.pick<int>({1, 2, 3, 4}) % (10 - weights[0]);
  weights[1] = std::max(weights[1], 1);
  weights[2] = 10 - weights[0] - weights[1];
  const auto kd = draw.tenths(2, 10);
  Problem p;
  p.title = "The colour at a Gouraud-interpolated point";
  p.statement = "A triangle is lit by one white directional light (diffuse 1,1,1); its material's diffuse reflectance is " +
                tenthsTriple(kd) + ". At its three vertices the normal makes " + std::to_string(angles[0]) + "°, " +
                std::to_string(angles[1]) + "° and " + std::to_string(angles[2]) + "° with the light vector. Under "
                "Gouraud shading, what colour is the point with barycentric weights (" + fixed(weights[0] / 10.0, 1) +
                ", " + fixed(weights[1] / 10.0, 1) + ", " + fixed(weights[2] / 10.0, 1) + ")?";
  std::array<double, 3> colour{};
  std::string sum;
  for (int v = 0; v < 3; ++v) {
    Check c = evaluateCheck({{"--model", "lambert"}, {"--angle-nl", std::to_string(angles[std::size_t(v)])},
                             {"--material-diffuse", tenthsText(kd)}, {"--material-ambient", "0,0,0"}},
                            {"diffuse"});
    p.steps.push_back("vertex " + std::to_string(v + 1) + ": diffuse = k_d · cos " + std::to_string(angles[std::size_t(v)]) +
                      "° = " + rgb(c.report["diffuse"]));
    for (int ch = 0; ch < 3; ++ch) colour[std::size_t(ch)] += weights[std::size_t(v)] / 10.0 * c.report["diffuse"][ch].get<double>();
    sum += (v ? " + " : "") + fixed(weights[std::size_t(v)] / 10.0, 1) + " · vertex " + std::to_string(v + 1);
    p.checks.push_back(std::move(c));
  }
  p.steps.push_back("Gouraud interpolates the vertices' colours, not their normals: " + sum + " = " + fixed(colour[0]) +
                    " " + fixed(colour[1]) + " " + fixed(colour[2]));
  return p;
}

Problem phongBlinn(Draw& draw) {
  const int theta = draw.pick<int>({15, 30, 45, 60}), phi = draw.pick<int>({10, 15, 20, 30, 40});
  const int n = draw.pick<int>({4, 10, 32, 64, 100});
  Problem p;
  p.title = "Phong against Blinn-Phong at the same geometry";
  p.statement = "The light vector L is " + std::to_string(theta) + "° from the normal N; the view vector V lies in the "
                "plane of N and L, " + std::to_string(phi) + "° from the mirror direction R. The material's specular "
                "reflectance is (1,1,1), the light's specular (1,1,1), the shininess n = " + std::to_string(n) +
                ". Compare Phong's (R·V)^n with Blinn-Phong's (N·H)^n.";
  Check phong = evaluateCheck({{"--model", "phong"}, {"--angle-nl", std::to_string(theta)}, {"--angle-rv", std::to_string(phi)},
                               {"--shininess", std::to_string(n)}, {"--material-specular", "1,1,1"}},
                              {"RoV", "lobe", "specular"});
  // H lies halfway between L and V: in the plane of incidence its angle to N is half of R's to V.
  const std::string psi = fixed(phi / 2.0, 1);
  Check blinn = evaluateCheck({{"--model", "blinn-phong"}, {"--angle-nl", std::to_string(theta)}, {"--angle-nh", psi},
                               {"--shininess", std::to_string(n)}, {"--material-specular", "1,1,1"}},
                              {"NoH", "lobe", "specular"});
  p.steps = {"Phong: R·V = cos " + std::to_string(phi) + "° = " + fixed(value(phong, "RoV")) + "; (R·V)^" + std::to_string(n) +
                 " = " + fixed(value(phong, "lobe")),
             "Blinn-Phong: H = (L + V)/|L + V| is " + psi + "° from N (half of φ, as V and L lie in one plane with N); "
                 "N·H = " + fixed(value(blinn, "NoH")) + "; (N·H)^" + std::to_string(n) + " = " + fixed(value(blinn, "lobe")),
             "The same exponent gives Blinn-Phong the wider highlight: to match Phong's, n must be about four times larger."};
  p.checks.push_back(std::move(phong));
  p.checks.push_back(std::move(blinn));
  return p;
}

using Kind = std::function<Problem(Draw&)>;
const std::vector<std::pair<std::string, Kind>> kKinds = {
    {"colour", colouredLight}, {"attenuation", attenuation}, {"spot", spot}, {"gouraud", gouraud}, {"phong-blinn", phongBlinn}};

std::vector<std::string> kindNames() {
  std::vector<std::string> names;
  for (const auto& [name, kind] : kKinds) names.push_back(name);
  return names;
}

std::string checkCommand(const Check& c) {
  std::string command = "illum eval";
  for (const auto& [name, value] : c.options) command += " " + name + " " + value;
  return command;
}

// The sheet as Markdown: the problems, then the key (a check per evaluation, its answers a line each).
std::string markdown(const std::vector<Problem>& problems, const ExerciseOptions& o) {
  std::ostringstream md;
  md << "# Lighting exercises (seed " << o.seed << ")\n\n";
  for (std::size_t i = 0; i < problems.size(); ++i)
    md << "## " << i + 1 << ". " << problems[i].title << "\n\n" << problems[i].statement << "\n\n";
  if (o.noAnswers) return md.str();
  md << "# Answers\n\n";
  for (std::size_t i = 0; i < problems.size(); ++i) {
    md << "## " << i + 1 << ". " << problems[i].title << "\n\n";
    for (const std::string& step : problems[i].steps) md << "- " << step << "\n";
    md << "\n";
    for (const Check& c : problems[i].checks) {
      md << "Check with `" << checkCommand(c) << "`:\n";
      for (const std::string& key : c.answers)
        md << "- " << key << " = " << (c.report[key].is_array() ? rgb(c.report[key]) : fixed(c.report[key].get<double>())) << "\n";
      md << "\n";
    }
  }
  return md.str();
}

std::string escapeHtml(const std::string& text) {
  std::string out;
  for (const char c : text) out += c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '&' ? "&amp;" : std::string(1, c);
  return out;
}

// The same sheet as one HTML page: headings, paragraphs, lists and code, from the Markdown above.
std::string html(const std::string& md) {
  std::ostringstream page;
  page << "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>Lighting exercises</title>\n"
          "<style>body{font-family:sans-serif;max-width:46em;margin:2em auto;line-height:1.5}code{background:#eee}</style>"
          "</head><body>\n";
  std::istringstream in(md);
  bool list = false;
  for (std::string line; std::getline(in, line);) {
    if (list && line.rfind("- ", 0) != 0) page << "</ul>\n", list = false;
    std::string text = escapeHtml(line);
    for (std::size_t at; (at = text.find('`')) != std::string::npos;) {
      const std::size_t end = text.find('`', at + 1);
      if (end == std::string::npos) break;
      text = text.substr(0, at) + "<code>" + text.substr(at + 1, end - at - 1) + "</code>" + text.substr(end + 1);
    }
    if (line.rfind("## ", 0) == 0) page << "<h2>" << text.substr(3) << "</h2>\n";
    else if (line.rfind("# ", 0) == 0) page << "<h1>" << text.substr(2) << "</h1>\n";
    else if (line.rfind("- ", 0) == 0) page << (list ? "" : "<ul>\n") << "<li>" << text.substr(2) << "</li>\n", list = true;
    else if (!line.empty()) page << "<p>" << text << "</p>\n";
  }
  if (list) page << "</ul>\n";
  page << "</body></html>\n";
  return page.str();
}

int runExercise(const ExerciseOptions& o) {
  std::vector<const Kind*> kinds;
  std::stringstream list(o.kinds);
  for (std::string name; std::getline(list, name, ',');) {
    if (name == "all") {
      for (const auto& [n, kind] : kKinds) kinds.push_back(&kind);
      continue;
    }
    const auto found = std::find_if(kKinds.begin(), kKinds.end(), [&](const auto& k) { return k.first == name; });
    if (found == kKinds.end()) badChoice("--kinds", name, [] {
      std::vector<std::string> names = kindNames();
      names.push_back("all");
      return names;
    }());
    kinds.push_back(&found->second);
  }
  if (kinds.empty()) throw InputError("--kinds: expected one or more of colour, attenuation, spot, gouraud, phong-blinn, got none");
  std::string format = o.format;
  if (format.empty()) format = o.output.size() > 5 && o.output.substr(o.output.size() - 5) == ".html" ? "html" : "md";
  if (format != "md" && format != "html") badChoice("--format", format, {"md", "html"});
  Draw draw(o.seed);
  std::vector<Problem> problems;
  for (int i = 0; i < o.count; ++i) problems.push_back((*kinds[std::size_t(i) % kinds.size()])(draw));
  std::string md = markdown(problems, o);
  while (md.size() > 1 && md.ends_with("\n\n")) md.pop_back();  // one newline at the end
  const std::string text = format == "html" ? html(md) : md;
  if (o.output.empty() || o.output == "-") std::fwrite(text.data(), 1, text.size(), stdout);
  else writeOutputFile(o.output, std::vector<std::uint8_t>(text.begin(), text.end()), OutputOptions{false});
  return 0;
}

}  // namespace

Command addExerciseCommand(CLI::App& app) {
  auto o = std::make_shared<ExerciseOptions>();
  CLI::App* cmd = app.add_subcommand(
      "exercise", "Write lighting problems of the lecture notes' kinds with random, reproducible values, and their answer key");
  cmd->footer(
      "Kinds: colour (one light and material, term by term), attenuation, spot, gouraud (a point inside a triangle),\n"
      "phong-blinn (the two specular lobes at one geometry). Every answer names the `illum eval` that checks it.\n"
      "Example: illum exercise --seed 7 --count 5 -o exercises.html");
  cmd->add_option("--seed", o->seed, "The values' seed: the same seed gives the same sheet")->capture_default_str();
  cmd->add_option("--count", o->count, "How many problems")->check(wholeRange(1, 100))->capture_default_str();
  cmd->add_option("--kinds", o->kinds, "Comma-separated kinds, in turn: colour, attenuation, spot, gouraud, phong-blinn, all")
      ->capture_default_str();
  cmd->add_option("--format", o->format, "md or html [from -o's extension, else md]");
  cmd->add_option("-o,--output", o->output, "The sheet's file [standard output]");
  cmd->add_flag("--no-answers", o->noAnswers, "Leave out the answer key");
  return [o] { return runExercise(*o); };
}

}  // namespace illum::cli
