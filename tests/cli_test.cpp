// The CLI as a user runs it: exit codes, messages, output files.
#include "cli_support.h"

#include <illum/image.h>
#include <illum/real.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>
#include <sys/wait.h>

namespace {

namespace fs = std::filesystem;
using illum::test::RunResult;
using illum::test::slurp;
using illum::test::TempDir;

RunResult run(const std::string& args) { return illum::test::runIllum(args); }

const char* kSeedExercise =
    "eval --model phong --distance 1 --angle-nl 30 --angle-rv 0 --light-ambient 0.4,0.9,0.2 "
    "--light-diffuse 0.3,1,1 --light-specular 1,1,1 --material-ambient 0.9,0.9,0.1 "
    "--material-diffuse 0.8,1,0.8 --material-specular 0,1,0.6 --shininess 2";

TEST(CliEval, AnswersTheSeedExercise) {
  const RunResult r = run(kSeedExercise);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("Emission      0.0000    0.0000    0.0000"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Ambient       0.3600    0.8100    0.0200"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Diffuse       0.2078    0.8660    0.6928"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Specular      0.0000    1.0000    0.6000"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Total         0.5678    1.0000    1.0000"), std::string::npos) << r.out;
}

TEST(CliEval, JsonTermsUnclampedTotalClamped) {
  const RunResult r = run(std::string(kSeedExercise) + " --json");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["diffuse"][1].get<double>(), std::sqrt(3.0) / 2, 1e-5);
  EXPECT_NEAR(j["specular"][2].get<double>(), 0.6, 1e-6);
  EXPECT_NEAR(j["total"][0].get<double>(), 0.36 + 0.24 * std::sqrt(3.0) / 2, 1e-5);
  EXPECT_EQ(j["total"][1].get<double>(), 1.0);
}

TEST(CliEval, BlinnPhongAnglesAndAttenuation) {
  // N·H at 0° puts the highlight at its peak; 1/(0 + 0·2 + 1·2²) = 1/4.
  const RunResult r = run("eval --angle-nl 60 --angle-nh 0 --material-specular 1,1,1 --shininess 10 "
                          "--material-ambient 0,0,0 --distance 2 --attenuation 0,0,1 --json");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["specular"][0].get<double>(), 0.25, 1e-6);
  EXPECT_NEAR(j["diffuse"][0].get<double>(), 0.8 * 0.5 * 0.25, 1e-6);
}

TEST(CliEval, VectorsAreNormalized) {
  const RunResult r = run("eval --model lambert --normal 0,0,2 --to-light 0,3,3 --to-viewer 0,0,5 --json");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NEAR(nlohmann::json::parse(r.out)["diffuse"][0].get<double>(), 0.8 * std::sqrt(0.5), 1e-6);
}

TEST(CliEval, LightOppositeViewerIsDefined) {
  const RunResult r = run("eval --normal 0,0,1 --to-light 1,0,1 --to-viewer -1,0,-1 --material-specular 1,1,1 "
                          "--shininess 5 --json");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.out.find("nan"), std::string::npos);
  EXPECT_EQ(nlohmann::json::parse(r.out)["specular"][0].get<double>(), 0.0);
}

// Cook-Torrance at normal incidence worked by hand: N = L = V, so D = 1/(πα²), V = 1/4, F = f0,
// diffuse (1 − f0)·base = 0.48 and specular π·D·V·F = f0/(4α²) = 0.0244 for α = 0.8² = 0.64.
TEST(CliEval, CookTorranceAtNormalIncidence) {
  const RunResult r = run("eval --model cook-torrance --base-color 0.5,0.5,0.5 --roughness 0.8 --f0 0.04,0.04,0.04 --json");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["diffuse"][0].get<double>(), 0.48, 1e-6);
  EXPECT_NEAR(j["specular"][0].get<double>(), 0.04 / (4 * 0.64 * 0.64), 1e-6);
  EXPECT_NEAR(j["D"].get<double>(), 1 / (3.14159265358979 * 0.64 * 0.64), 1e-5);
  EXPECT_NEAR(j["Vis"].get<double>(), 0.25, 1e-6);
  EXPECT_EQ(run("eval --model cook-torrance --base-color 0.5,0.5,0.5 --material-diffuse 1,1,1").exitCode, 2);
  EXPECT_EQ(run("eval --model cook-torrance --distribution phong").exitCode, 2);
}

// eval teaches: each factor's formula with its numbers, and why a term is zero where it is.
TEST(CliEval, ExplainsItsFactorsAndWhyATermIsZero) {
  const RunResult behind = run("eval --angle-nl 100 --shininess 10");
  ASSERT_EQ(behind.exitCode, 0) << behind.err;
  EXPECT_NE(behind.out.find("the light is behind the surface (N·L = -0.1736 ≤ 0)"), std::string::npos) << behind.out;
  EXPECT_NE(behind.out.find("(N·H)^10 would be 0.0120"), std::string::npos) << behind.out;  // 0.6428^10
  const RunResult attenuated = run("eval --distance 2 --attenuation 1,0.5,0.25");
  ASSERT_EQ(attenuated.exitCode, 0) << attenuated.err;
  EXPECT_NE(attenuated.out.find("attenuation = 1/(k_c + k_l·d + k_q·d²) = 1/(1 + 0.5·2.0000 + 0.25·2.0000²) = 0.3333"),
            std::string::npos)
      << attenuated.out;
  const RunResult outside = run("eval --angle-nl 40 --spot-cutoff 30 --spot-direction 0,0,-1");
  ASSERT_EQ(outside.exitCode, 0) << outside.err;
  EXPECT_NE(outside.out.find("40.00° off the spot's axis, outside its cutoff of 30°"), std::string::npos) << outside.out;
}

// A sweep: the terms against one angle, distance or shininess, a row each (or a JSON array).
TEST(CliEval, SweepsOneValueAsATable) {
  const RunResult r = run("eval --angle-nl 0:90:30");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  std::istringstream lines(r.out);
  std::string header, line;
  std::getline(lines, header);
  EXPECT_EQ(header.rfind("angle-nl", 0), 0u) << header;
  int rows = 0;
  for (const double theta : {0.0, 30.0, 60.0, 90.0}) {
    ASSERT_TRUE(std::getline(lines, line));
    ++rows;
    // Lambert: the diffuse term is 0.8·cos θ (the default material and light).
    char expected[32];
    std::snprintf(expected, sizeof expected, "%.4f", 0.8 * std::cos(theta * 3.14159265358979 / 180) + 0.0);
    EXPECT_NE(line.find(std::string("| ") + (theta == 90.0 ? "0.0000" : expected)), std::string::npos) << line;
  }
  EXPECT_FALSE(std::getline(lines, line)) << line;
  EXPECT_EQ(rows, 4);
  const auto json = nlohmann::json::parse(run("eval --json --distance 1,2,4 --attenuation 0,0,1").out);
  ASSERT_EQ(json.size(), 3u);
  EXPECT_NEAR(json[2]["diffuse"][0].get<double>(), 0.8 / 16, 1e-6);  // 1/d² at d = 4
  const RunResult two = run("eval --angle-nl 0:90:5 --shininess 1,2");
  EXPECT_EQ(two.exitCode, 2);
  EXPECT_NE(two.err.find("a sweep varies one of them at a time"), std::string::npos) << two.err;
  const RunResult many = run("eval --angle-nl 0:90:0.01");
  EXPECT_EQ(many.exitCode, 2);
  EXPECT_NE(many.err.find("9001 values; expected at most 1000"), std::string::npos) << many.err;
}

// --plot: the terms against the swept value beside the lobes, or the lobes alone; a name that is no
// still picture is refused before anything is evaluated.
TEST(CliEval, PlotsASweepAndTheLobes) {
  TempDir dir;
  const RunResult sweep = run("eval --model phong --angle-nl 0:90:5 --material-specular 1,1,1 --shininess 10 --plot " +
                              (dir / "sweep.png").string());
  ASSERT_EQ(sweep.exitCode, 0) << sweep.err;
  EXPECT_EQ(sweep.out, run("eval --model phong --angle-nl 0:90:5 --material-specular 1,1,1 --shininess 10").out);
  const illum::Image both = illum::readPng(dir / "sweep.png");
  EXPECT_EQ(both.width, 1120);
  EXPECT_EQ(both.height, 420);
  ASSERT_EQ(run("eval --angle-nl 30 --shininess 32 --plot " + (dir / "lobes.png").string()).exitCode, 0);
  const illum::Image lobes = illum::readPng(dir / "lobes.png");
  EXPECT_EQ(lobes.width, 560);
  // Both lobes are drawn: Phong's orange and Blinn-Phong's blue.
  int orange = 0, blue = 0;
  for (int y = 0; y < lobes.height; ++y)
    for (int x = 0; x < lobes.width; ++x) {
      const std::uint8_t* p = lobes.pixel(x, y);
      orange += p[0] == 255 && p[1] == 140 && p[2] == 77;
      blue += p[0] == 89 && p[1] == 191 && p[2] == 255;
    }
  EXPECT_GT(orange, 200);
  EXPECT_GT(blue, 200);
  const RunResult exr = run("eval --angle-nl 30 --plot " + (dir / "p.exr").string());
  EXPECT_EQ(exr.exitCode, 2);
  EXPECT_EQ(exr.out, "");
  EXPECT_NE(exr.err.find("--plot"), std::string::npos) << exr.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "p.exr"));
}

// The notes' own conventions beside GL's (seed 001): its shader scales the specular by N·L too and
// takes the material's ambient alone; its H = (L + V)/2 is not normalised. Closed forms.
TEST(CliEval, FollowsANotesConventionBesideGls) {
  const double pi = 3.14159265358979;
  // L 45° from N, V at 2·10° − 45° = −25°: H's angle to N is 10°, |L + V|/2 = cos 35°.
  const auto half = nlohmann::json::parse(run("eval --json --model blinn-phong --angle-nl 45 --angle-nh 10 --shininess 20 "
                                              "--material-specular 1,1,1 --convention note-half-sum").out);
  const double noh = std::cos(35 * pi / 180) * std::cos(10 * pi / 180);
  EXPECT_NEAR(half["convention"]["NoH"].get<double>(), noh, 1e-5);
  EXPECT_NEAR(half["convention"]["specular"][0].get<double>(), std::pow(noh, 20), 1e-5);
  EXPECT_NEAR(half["specular"][0].get<double>(), std::pow(std::cos(10 * pi / 180), 20), 1e-5);  // GL's
  EXPECT_EQ(half["convention"]["diffuse"], half["diffuse"]);
  const auto shader = nlohmann::json::parse(run("eval --json --model blinn-phong --angle-nl 60 --angle-nh 10 --shininess 20 "
                                                "--material-specular 1,1,1 --convention note-shader").out);
  EXPECT_NEAR(shader["convention"]["specular"][0].get<double>(), std::pow(std::cos(10 * pi / 180), 20) * 0.5, 1e-5);
  EXPECT_NEAR(shader["convention"]["ambient"][0].get<double>(), 0.2, 1e-6);  // the material's ambient alone
  EXPECT_NEAR(shader["convention"]["diffuse"][0].get<double>(), 0.4, 1e-5);  // 0.8 · cos 60°
  const RunResult table = run("eval --model blinn-phong --angle-nl 60 --angle-nh 10 --shininess 20 --material-specular 1,1,1 "
                              "--convention note-shader");
  EXPECT_NE(table.out.find("convention note-shader (seed 001's shader"), std::string::npos) << table.out;
  EXPECT_NE(table.out.find("Specular      0.3681    0.3681    0.3681   -0.3681 -0.3681 -0.3681"), std::string::npos) << table.out;
  const RunResult bad = run("eval --convention note-shadr");
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_NE(bad.err.find("did you mean note-shader?"), std::string::npos) << bad.err;
}

// The renderer follows a note's convention too, by the same equation as eval: a square facing the
// viewer, lit by a directional light 60° from its normal (N·L = 1/2, GL's N·H = cos 30°, the note's
// (L + V)/2 gives N·H = 3/4), drawn by the rasterizer under every shading and by the ray tracer.
TEST(CliRender, FollowsALectureNotesConvention) {
  TempDir dir;
  std::ofstream(dir / "square.json") << R"({"width": 64, "height": 64,
    "lights": [{"position": [0.8660254037844386, 0, 0.5, 0]}],
    "objects": [{"mesh": {"type": "triangles", "positions": [-3,-3,0, 3,-3,0, 3,3,0, -3,3,0],
                          "normals": [0,0,1, 0,0,1, 0,0,1, 0,0,1], "indices": [0,1,2, 0,2,3]},
                 "material": {"ambient": [0.2,0.2,0.2,1], "diffuse": [0.8,0.8,0.8,1], "specular": [1,1,1,1], "shininess": 20}}]})";
  const double lobe = std::pow(std::cos(30 * 3.14159265358979 / 180), 20);
  const struct {
    const char* convention;
    double value;
  } expected[] = {{"gl", 0.2 * 0.2 + 0.8 * 0.5 + lobe},                 // global ambient + diffuse + specular
                  {"note-shader", 0.2 + (0.8 + lobe) * 0.5},            // mat.ambient + (kd + ks·lobe)·N·L
                  {"note-half-sum", 0.2 * 0.2 + 0.8 * 0.5 + std::pow(0.75, 20)}};
  for (const auto& [convention, value] : expected)
    for (const std::string how : {"--shading flat", "--shading gouraud", "--shading phong", "--renderer whitted"}) {
      const RunResult r = run("render " + (dir / "square.json").string() + " " + how + " --convention " + convention +
                              " -o " + (dir / "out.png").string());
      ASSERT_EQ(r.exitCode, 0) << r.err;
      const int byte = illum::readPng(dir / "out.png").pixel(32, 32)[0];
      EXPECT_NEAR(byte, value * 255, 0.51) << convention << " " << how;
    }
  // The scene file's key says the same as the option.
  std::string text = slurp(dir / "square.json");
  text.insert(1, R"("light_model": {"convention": "note-shader"}, )");
  std::ofstream(dir / "shader.json") << text;
  ASSERT_EQ(run("render " + (dir / "shader.json").string() + " -o " + (dir / "key.png").string()).exitCode, 0);
  ASSERT_EQ(run("render " + (dir / "square.json").string() + " --convention note-shader -o " + (dir / "option.png").string()).exitCode, 0);
  EXPECT_EQ(illum::readPng(dir / "key.png").rgba, illum::readPng(dir / "option.png").rgba);
  // Seed 004's world space: V towards the camera, GL's local viewer, byte for byte; not GL's default.
  std::string local = slurp(dir / "square.json");
  local.insert(1, R"("light_model": {"local_viewer": true}, )");
  std::ofstream(dir / "local.json") << local;
  ASSERT_EQ(run("render " + (dir / "local.json").string() + " -o " + (dir / "local.png").string()).exitCode, 0);
  ASSERT_EQ(run("render " + (dir / "square.json").string() + " --convention note-world-space -o " + (dir / "world.png").string()).exitCode, 0);
  ASSERT_EQ(run("render " + (dir / "square.json").string() + " -o " + (dir / "gl.png").string()).exitCode, 0);
  EXPECT_EQ(illum::readPng(dir / "world.png").rgba, illum::readPng(dir / "local.png").rgba);
  EXPECT_NE(illum::readPng(dir / "world.png").rgba, illum::readPng(dir / "gl.png").rgba);
  // --debug-pixel shows the note's terms, by name.
  const RunResult probe = run("render " + (dir / "shader.json").string() + " --debug-pixel 32,32 -o " + (dir / "p.png").string());
  EXPECT_NE(probe.out.find("convention note-shader"), std::string::npos) << probe.out;
  EXPECT_NE(probe.out.find("material ambient"), std::string::npos) << probe.out;
  // A name that is none is refused with the closest one, as a scene key by its JSON path.
  const RunResult bad = run("render " + (dir / "square.json").string() + " --convention note-sader -o " + (dir / "x.png").string());
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_NE(bad.err.find("did you mean note-shader?"), std::string::npos) << bad.err;
  text.replace(text.find("note-shader"), 11, "opengl");
  std::ofstream(dir / "bad.json") << text;
  const RunResult badKey = run("render " + (dir / "bad.json").string() + " -o " + (dir / "x.png").string());
  EXPECT_EQ(badKey.exitCode, 2);
  EXPECT_NE(badKey.err.find("/light_model/convention: expected \"gl\", \"note-shader\", \"note-half-sum\" or \"note-world-space\", got \"opengl\""),
            std::string::npos) << badKey.err;
  EXPECT_FALSE(fs::exists(dir / "x.png"));
  // The path tracer's light is physical: it says so rather than pretend.
  const RunResult path = run("render " + (dir / "square.json").string() +
                             " --renderer path --samples 1 --convention note-shader -o " + (dir / "path.png").string());
  EXPECT_EQ(path.exitCode, 0) << path.err;
  EXPECT_NE(path.err.find("no lecture note's convention"), std::string::npos) << path.err;
}

// Highway's start-up timer measurement (3.6 ms a process with Debian's libhwy 1.0.3) is the CLI's
// no-op: the dynamic linker binds libhwy's call to the executable's definition (hwy_startup.cpp).
TEST(CliStart, HighwaysTimerMeasurementIsSkipped) {
  const RunResult r = illum::test::runShell("LD_DEBUG=bindings " + std::string(ILLUM_CLI) + " --version");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  std::istringstream lines(r.err);  // the dynamic linker's report
  bool bound = false;
  for (std::string line; std::getline(lines, line);)
    if (line.find("libhwy") != std::string::npos && line.find("_ZN3hwy8platform15TimerResolutionEv") != std::string::npos)
      bound = line.find("to " + std::string(ILLUM_CLI) + " ") != std::string::npos;
  EXPECT_TRUE(bound) << r.err.substr(0, 2000);
}

TEST(CliEval, BadInputIsRefusedClearly) {
  const RunResult zero = run("eval --normal 0,0,0");
  EXPECT_EQ(zero.exitCode, 2);
  EXPECT_EQ(zero.err, "illum: error: --normal: expected a non-zero vector, got \"0,0,0\"\n");
  const RunResult wrongAngle = run("eval --model phong --angle-nh 10");
  EXPECT_EQ(wrongAngle.exitCode, 2);
  EXPECT_NE(wrongAngle.err.find("--angle-nh"), std::string::npos);
  const RunResult impossible = run("eval --angle-nl 10 --angle-nh 120");
  EXPECT_EQ(impossible.exitCode, 2);
  EXPECT_NE(impossible.err.find("no viewer above the surface"), std::string::npos);
  const RunResult colour = run("eval --light-diffuse 1,1");
  EXPECT_EQ(colour.exitCode, 2);
  EXPECT_NE(colour.err.find("--light-diffuse: expected a colour R,G,B"), std::string::npos);
  const RunResult mixed = run("eval --angle-nl 10 --normal 0,0,1");
  EXPECT_EQ(mixed.exitCode, 2);
  const RunResult unknown = run("eval --frobnicate");
  EXPECT_EQ(unknown.exitCode, 2);
  EXPECT_EQ(unknown.err.rfind("illum: error: ", 0), 0u);
}

TEST(CliRender, DefaultSceneWritesAPng) {
  TempDir dir;
  const RunResult r = run("render -o " + (dir / "out.png").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const illum::Image img = illum::readPng(dir / "out.png");
  EXPECT_EQ(img.width, 960);
  EXPECT_EQ(img.height, 540);
  EXPECT_EQ(dir.fileCount(), 1u);  // no temporary file left behind
}

TEST(CliRender, OverridesApply) {
  TempDir dir;
  const RunResult r = run("render --width 64 --height 32 --model lambert --shading flat --background 1,0,0 -o " +
                          (dir / "small.png").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const illum::Image img = illum::readPng(dir / "small.png");
  EXPECT_EQ(img.width, 64);
  EXPECT_EQ(img.height, 32);
  EXPECT_EQ(img.pixel(0, 0)[0], 255);  // the red background in the top-left corner
}

TEST(CliRender, BadSceneFailsCleanlyAndKeepsTheOldOutput) {
  TempDir dir;
  std::ofstream(dir / "bad.json") << R"({"lights": [{}, {}, {"attenuation": [1, 0]}]})";
  std::ofstream(dir / "out.png") << "previous picture";
  const RunResult r = run("render " + (dir / "bad.json").string() + " -o " + (dir / "out.png").string());
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_EQ(r.err, "illum: error: " + (dir / "bad.json").string() + ": /lights/2/attenuation: expected 3 numbers, got 2\n");
  EXPECT_EQ(slurp(dir / "out.png"), "previous picture");
  EXPECT_EQ(dir.fileCount(), 2u);
}

TEST(CliRender, MissingSceneFails) {
  TempDir dir;
  const RunResult r = run("render " + (dir / "nope.json").string() + " -o " + (dir / "out.png").string());
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("nope.json: no such scene file"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out.png"));
}

TEST(CliRender, UnwritableOutputFailsCleanly) {
  TempDir dir;
  const RunResult r = run("render --width 8 --height 8 -o " + (dir / "no/such/folder/out.png").string());
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("does not exist"), std::string::npos) << r.err;
  const RunResult d = run("render --width 8 --height 8 -o " + (dir / "").string());
  EXPECT_EQ(d.exitCode, 1);
  EXPECT_EQ(dir.fileCount(), 0u);
}

// --save-scene: the scene drawn as a file that draws the same bytes, with what was changed on the
// command line in it; it refuses batches and inputs.
TEST(CliRender, SavedSceneDrawsTheSameBytes) {
  TempDir dir;
  const RunResult r = run("render --model phong --shading gouraud --samples 4 --edges -o " + (dir / "a.png").string() +
                          " --save-scene " + (dir / "a.json").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::string text = slurp(dir / "a.json");
  EXPECT_NE(text.find("\"model\": \"phong\""), std::string::npos) << text;
  EXPECT_NE(text.find("\"multisample\": 4"), std::string::npos) << text;
  const RunResult again = run("render " + (dir / "a.json").string() + " -o " + (dir / "b.png").string());
  ASSERT_EQ(again.exitCode, 0) << again.err;
  EXPECT_EQ(slurp(dir / "a.png"), slurp(dir / "b.png"));
  // Never over an input, never for a batch.
  const RunResult over = run("render " + (dir / "a.json").string() + " -o " + (dir / "c.png").string() +
                             " --save-scene " + (dir / "a.json").string());
  EXPECT_EQ(over.exitCode, 2);
  EXPECT_EQ(slurp(dir / "a.json"), text);
  const RunResult batch = run("render " + (dir / "a.json").string() + " " + (dir / "a.json").string() +
                              " --output-dir " + dir.path().string() + " --save-scene " + (dir / "d.json").string());
  EXPECT_EQ(batch.exitCode, 2);
  EXPECT_NE(batch.err.find("--save-scene: writes the scene of one picture, not of a batch"), std::string::npos) << batch.err;
  EXPECT_FALSE(fs::exists(dir / "d.json"));
}

TEST(CliRender, DebugPixelExplainsThePixel) {
  TempDir dir;
  const RunResult r = run("render --debug-pixel 180,200 -o " + (dir / "out.png").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("pixel (180, 200): object 0"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("light 2 specular"), std::string::npos) << r.out;
  // Per-pixel shading: the report's total is what was written, and the bytes are the image's.
  const auto total = r.out.find("total (clamped)");
  const auto bytes = r.out.find("= bytes ");
  ASSERT_NE(total, std::string::npos);
  ASSERT_NE(bytes, std::string::npos);
  int b[4] = {0, 0, 0, 0};
  ASSERT_EQ(std::sscanf(r.out.c_str() + bytes, "= bytes %d %d %d %d", &b[0], &b[1], &b[2], &b[3]), 4);
  const illum::Image img = illum::readPng(dir / "out.png");
  for (int c = 0; c < 4; ++c) EXPECT_EQ(img.pixel(180, 200)[c], b[c]);
  double t[3], w[3];
  ASSERT_EQ(std::sscanf(r.out.c_str() + total, "total (clamped) %lf %lf %lf", &t[0], &t[1], &t[2]), 3);
  ASSERT_EQ(std::sscanf(r.out.c_str() + r.out.find("fragment: "), "fragment: %lf %lf %lf", &w[0], &w[1], &w[2]), 3);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(t[c], w[c], 1e-4);
  const RunResult bg = run("render --debug-pixel 5,5 -o " + (dir / "out.png").string());
  EXPECT_NE(bg.out.find("background"), std::string::npos);
  EXPECT_EQ(run("render --debug-pixel 5000,5 -o " + (dir / "out.png").string()).exitCode, 2);
}

TEST(CliRender, PngToStandardOutput) {
  const RunResult r = run("render --width 16 --height 8 -o -");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  ASSERT_GT(r.out.size(), 8u);
  EXPECT_EQ(r.out.substr(1, 3), "PNG");
}

TEST(CliRender, SameBytesEveryRun) {
  TempDir dir;
  ASSERT_EQ(run("render -o " + (dir / "a.png").string()).exitCode, 0);
  ASSERT_EQ(run("render -o " + (dir / "b.png").string()).exitCode, 0);
  EXPECT_EQ(slurp(dir / "a.png"), slurp(dir / "b.png"));
}

}  // namespace

TEST(CliOutput, ReadOnlyTargetRefusedUnlessForced) {
  TempDir dir;
  const fs::path out = dir / "ro.png";
  { std::ofstream(out) << "keep"; }
  fs::permissions(out, fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
  const RunResult r = run("render --width 16 --height 16 -o " + out.string());
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("read-only"), std::string::npos) << r.err;
  EXPECT_EQ(slurp(out), "keep");
  const RunResult f = run("render --width 16 --height 16 --force -o " + out.string());
  ASSERT_EQ(f.exitCode, 0) << f.err;
  EXPECT_EQ(slurp(out).substr(1, 3), "PNG");
  EXPECT_EQ(fs::status(out).permissions(), fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
}

TEST(CliOutput, DevStdoutCarriesOnlyThePng) {
  const RunResult r = run("render --width 16 --height 16 -o /dev/stdout");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  ASSERT_GT(r.out.size(), 8u);
  EXPECT_EQ(r.out.substr(1, 3), "PNG");
  EXPECT_EQ(r.out.substr(r.out.size() - 8, 4), "IEND");  // nothing printed after the image
}

// An output's extension says its format, for one picture, a batch's pictures and a sheet alike;
// a format illum does not write is refused before anything is drawn.
TEST(CliOutput, EveryOutputNameMeansItsFormat) {
  TempDir dir;
  const auto render = [&](const std::string& name, const std::string& options = "") {
    const RunResult r = run("render --resolution 64,48 -o " + (dir / name).string() + " " + options);
    EXPECT_EQ(r.exitCode, 0) << name << ": " << r.err;
    return slurp(dir / name);
  };
  const std::string png = render("a.png"), jpg = render("a.jpg"), jpeg = render("a.JPEG"), webp = render("a.webp"),
                    lossy = render("lossy.webp", "--quality 80"), gif = render("a.gif"), exr = render("a.exr");
  EXPECT_EQ(png.substr(1, 3), "PNG");
  EXPECT_EQ(jpg.substr(0, 3), "\xFF\xD8\xFF");
  EXPECT_EQ(jpeg.substr(0, 3), "\xFF\xD8\xFF");
  EXPECT_EQ(webp.substr(0, 4) + webp.substr(8, 8), "RIFFWEBPVP8L");  // lossless
  EXPECT_EQ(lossy.substr(8, 8), "WEBPVP8 ");                          // lossy, with --quality
  EXPECT_EQ(gif.substr(0, 6), "GIF89a");
  EXPECT_EQ(exr.substr(0, 4), "\x76\x2F\x31\x01");
  // The JPEG is the picture (within its compression); the GIF keeps the background's exact colour.
  const illum::Image picture = illum::readPng(dir / "a.png"), fromJpeg = illum::readPng(dir / "a.jpg");
  const illum::Image fromGif = illum::readPng(dir / "a.gif");
  double difference = 0;
  for (std::size_t i = 0; i < picture.rgba.size(); i += 4)
    for (std::size_t c = 0; c < 3; ++c) difference += std::abs(int(picture.rgba[i + c]) - int(fromJpeg.rgba[i + c]));
  EXPECT_LT(difference / double(picture.rgba.size() / 4 * 3), 4.0);
  EXPECT_EQ(std::vector<std::uint8_t>(fromGif.pixel(0, 0), fromGif.pixel(0, 0) + 4),
            std::vector<std::uint8_t>(picture.pixel(0, 0), picture.pixel(0, 0) + 4));
  // A turntable's GIF too, frame by frame.
  const RunResult turntable = run("render --resolution 64,48 --turntable 3 -o " + (dir / "turn.gif").string());
  ASSERT_EQ(turntable.exitCode, 0) << turntable.err;
  const illum::Image firstFrame = illum::readPng(dir / "turn.gif");
  EXPECT_EQ(std::vector<std::uint8_t>(firstFrame.pixel(0, 0), firstFrame.pixel(0, 0) + 4),
            std::vector<std::uint8_t>(picture.pixel(0, 0), picture.pixel(0, 0) + 4));
  // Sheets too.
  const RunResult sheet = run("compare --resolution 64,48 --cols shininess=1,8 -o " + (dir / "sheet.jpg").string());
  ASSERT_EQ(sheet.exitCode, 0) << sheet.err;
  EXPECT_EQ(slurp(dir / "sheet.jpg").substr(0, 3), "\xFF\xD8\xFF");
}

TEST(CliOutput, FormatsIllumDoesNotWriteAreRefusedBeforeDrawing) {
  TempDir dir;
  for (const std::string name : {"still.tif", "still.bmp", "still.TGA"}) {
    const RunResult r = run("render --resolution 64,48 -o " + (dir / name).string());
    EXPECT_EQ(r.exitCode, 2) << name;
    EXPECT_NE(r.err.find("illum does not write"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(".png, .jpg"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / name));
  }
  const RunResult batch = run("render examples/first_light.json examples/shininess.json -o '" + (dir / "{stem}.bmp").string() + "'");
  EXPECT_EQ(batch.exitCode, 2) << batch.err;
  EXPECT_EQ(dir.fileCount(), 0u);
  const RunResult quality = run("render --resolution 64,48 --quality 50 -o " + (dir / "a.png").string());
  EXPECT_EQ(quality.exitCode, 2);
  EXPECT_NE(quality.err.find("--quality: only .jpg and .webp"), std::string::npos) << quality.err;
  const RunResult video = run("render --resolution 64,48 -o " + (dir / "a.mp4").string());
  EXPECT_EQ(video.exitCode, 2);
  EXPECT_NE(video.err.find("--turntable"), std::string::npos) << video.err;
  const RunResult sheet = run("history -o " + (dir / "sheet.exr").string());
  EXPECT_EQ(sheet.exitCode, 2);
  EXPECT_NE(sheet.err.find("a sheet is one 8-bit picture"), std::string::npos) << sheet.err;
  EXPECT_EQ(dir.fileCount(), 0u);
}

// Mistyped commands, options and values name what was meant, in illum's words, and never render.
TEST(CliErrors, TyposNameTheClosestValidName) {
  TempDir dir;
  const auto refused = [&](const std::string& args, const std::string& expected) {
    const RunResult in = illum::test::runShell("cd '" + dir.path().string() + "' && " + std::string(ILLUM_CLI) + " " + args);
    EXPECT_EQ(in.exitCode, 2) << args << ": " << in.err;
    EXPECT_NE(in.err.find(expected), std::string::npos) << args << ": " << in.err;
    EXPECT_EQ(in.err.find("Run 'illum --help'"), std::string::npos) << in.err;  // CLI11's own tail is gone
    EXPECT_EQ(dir.fileCount(), 0u) << args << " wrote something";
  };
  refused("rendr /usr/share/assimp/models/Collada/duck.dae", "rendr: no such command or file; did you mean render?");
  refused("veiw", "did you mean view?");
  refused("render --size 800,600", "--size: not an option of illum render; did you mean --resolution?");
  refused("render --azimuth 30", "did you mean --camera-azimuth-angle?");
  refused("render --resolutoin 10,10", "did you mean --resolution?");
  refused("render --shading phongg", "--shading: expected flat, gouraud or phong, got \"phongg\"; did you mean phong?");
  refused("render --model blin", "did you mean blinn-phong?");
  refused("render --renderer pathh", "did you mean path?");
  refused("compare --rows modle=phong", "did you mean model?");
  refused("render --width abc", "--width: expected a whole number in [1, 16384], got \"abc\"");
  refused("render --samples 0", "--samples: expected a whole number in [1, 16384], got");
  refused("render --width 5 --width 6", "--width: given 2 times; expected once");
  refused("eval --angle-nl 30 extra", "\"extra\": not expected here");
}

TEST(CliOutput, QuietPrintsNothing) {
  TempDir dir;
  const RunResult r = run("render --width 16 --height 16 --quiet -o " + (dir / "a.png").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_TRUE(fs::exists(dir / "a.png"));
}

namespace {

nlohmann::json evalJson(const std::string& args) {
  const RunResult r = run("eval --json " + args);
  EXPECT_EQ(r.exitCode, 0) << args << ": " << r.err;
  return r.exitCode == 0 ? nlohmann::json::parse(r.out) : nlohmann::json::object();
}

}  // namespace

TEST(CliEvalGeometry, PhongAndBlinnPhongShareOnePlane) {
  // θ = 30°: phong's φ = 20° and blinn-phong's ψ = 10° name the same viewer (α = −10°).
  const auto phong = evalJson("--model phong --angle-nl 30 --angle-rv 20");
  const auto blinn = evalJson("--model blinn-phong --angle-nl 30 --angle-nh 10");
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(phong["V"][i].get<double>(), blinn["V"][i].get<double>(), 1e-6) << i;
  EXPECT_EQ(phong["V"][1].get<double>(), 0.0);
  EXPECT_NEAR(phong["RoV"].get<double>(), std::cos(20 * M_PI / 180), 1e-6);
  EXPECT_NEAR(blinn["NoH"].get<double>(), std::cos(10 * M_PI / 180), 1e-6);
}

TEST(CliEvalGeometry, ViewerIsNeverBelowTheSurface) {
  for (int theta = 0; theta <= 90; theta += 15)
    for (int angle = 0; angle <= 180; angle += 15) {
      for (const std::string model : {"phong", "blinn-phong"}) {
        const std::string option = model == "phong" ? "--angle-rv " : "--angle-nh ";
        const RunResult r = run("eval --json --model " + model + " --angle-nl " + std::to_string(theta) + " " + option +
                                std::to_string(angle));
        if (r.exitCode != 0) {
          EXPECT_EQ(r.exitCode, 2);
          EXPECT_TRUE(r.err.find("no viewer above the surface") != std::string::npos ||
                      r.err.find("is undefined") != std::string::npos) << r.err;
          continue;
        }
        const auto j = nlohmann::json::parse(r.out);
        EXPECT_GE(j["V"][2].get<double>(), -1e-6) << model << " θ=" << theta << " angle=" << angle;
        // The angle asked for is the angle computed.
        const double c = model == "phong" ? j["RoV"].get<double>() : j["NoH"].get<double>();
        EXPECT_NEAR(std::acos(std::clamp(c, -1.0, 1.0)) * 180 / M_PI, angle, 1e-3) << model << " θ=" << theta;
      }
    }
}

TEST(CliEvalGeometry, SpotFactorAndAttenuationArePrinted) {
  // The spot axis 20° off the line to the point: cos(20°)^4 inside a 30° cone, 0 outside a 10° one.
  const auto inside = evalJson("--distance 2 --attenuation 1,0,1 --spot-cutoff 30 --spot-exponent 4 "
                               "--normal 0,0,1 --to-light 0,0,1 --spot-direction 0,0.3639702,-1");
  EXPECT_NEAR(inside["spot"].get<double>(), std::pow(std::cos(20 * M_PI / 180), 4), 1e-5);
  EXPECT_NEAR(inside["attenuation"].get<double>(), 1.0 / 5, 1e-6);
  const auto outside = evalJson("--distance 2 --spot-cutoff 10 --to-light 0,0,1 --spot-direction 0,0.3639702,-1");
  EXPECT_EQ(outside["spot"].get<double>(), 0.0);
  EXPECT_EQ(outside["diffuse"][0].get<double>(), 0.0);
  const RunResult text = run("eval --distance 2 --spot-cutoff 30");
  EXPECT_NE(text.out.find("spot factor 1.0000"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("H = ("), std::string::npos) << text.out;
  EXPECT_EQ(run("eval --spot-exponent 2").exitCode, 2);
  EXPECT_EQ(run("eval --spot-cutoff 120").exitCode, 2);
}

TEST(CliValues, OneSetOfRules) {
  TempDir dir;
  const std::string out = " -o " + (dir / "a.png").string();
  const auto refused = [&](const std::string& args, const std::string& message) {
    const RunResult r = run(args + (args.rfind("eval", 0) == 0 ? "" : out));
    EXPECT_EQ(r.exitCode, 2) << args << ": " << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << args << ": " << r.err;
  };
  // Conflicting options.
  refused("render --resolution 100,100 --width 50", "--resolution: give the size either");
  refused("render --no-background --background 1,0,0", "--no-background:");
  refused("render --orthographic --camera-view-angle 20", "--camera-view-angle: an orthographic camera");
  // Numbers: whole pixels, and finite in the renderer's precision.
  refused("render --debug-pixel 10.5,3", "--debug-pixel: expected a whole number, got \"10.5\"");
  const std::string tooBig = sizeof(illum::Real) == 4 ? "1e39" : "1e309";  // beyond the renderer's precision
  refused("render --camera-position=" + tooBig + ",0,0", "--camera-position:");
  refused("render --camera-view-angle 1e-40", "--camera-view-angle: expected a view angle in [0.01, 179.99]");
  // The error names the option that is wrong.
  refused("render --camera-focal-point 0,0,5 --camera-position 0,0,5", "--camera-position with --camera-focal-point:");
  refused("render --camera-view-up 0,0,0", "--camera-view-up: expected a non-zero up direction");
  EXPECT_FALSE(fs::exists(dir / "a.png"));
  // eval: light colours may exceed 1 (as glLight allows); material colours may not; JSON stays JSON.
  EXPECT_EQ(run("eval --light-diffuse 2,2,2 --json").exitCode, 0);
  refused("eval --material-diffuse 1.5,0,0", "--material-diffuse: expected a colour R,G,B with each channel a number in [0, 1]");
  refused("eval --light-diffuse=" + tooBig + ",1,1 --json", "--light-diffuse:");
  const RunResult big = run("eval --light-diffuse 1e30,1,1 --material-diffuse 1,1,1 --shininess 1e6 --json");
  ASSERT_EQ(big.exitCode, 0) << big.err;
  EXPECT_TRUE(nlohmann::json::accept(big.out)) << big.out;
}

TEST(CliValues, ModelCameraOptionsAreValidatedLikeSceneCameras) {
  TempDir dir;
  const std::string model = "/usr/share/assimp/models/STL/Spider_binary.stl";
  const RunResult zero = run("render " + model + " --camera-view-up 0,0,0 -o " + (dir / "a.png").string());
  EXPECT_EQ(zero.exitCode, 2);
  EXPECT_NE(zero.err.find("--camera-view-up: expected a non-zero up direction"), std::string::npos) << zero.err;
  const RunResult parallel =
      run("render " + model + " --up=+Y --camera-view-up 0,1,0 --camera-elevation-angle 90 -o " + (dir / "a.png").string());
  EXPECT_EQ(parallel.exitCode, 2);
  EXPECT_NE(parallel.err.find("--camera-view-up: expected an up direction not parallel"), std::string::npos) << parallel.err;
  EXPECT_FALSE(fs::exists(dir / "a.png"));
}

TEST(CliBench, PrintsOneJsonObjectWithTheFigures) {
  TempDir dir;
  std::ofstream(dir / "one.json") << R"({"width": 64, "height": 48, "objects": [{"mesh": {"type": "sphere", "slices": 10, "stacks": 5}}]})";
  const RunResult r = run("bench " + (dir / "one.json").string() + " --frames 3 --threads 1");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key : {"ms_per_frame", "ms_min", "encode_ms", "triangles", "fragments", "pixels", "threads"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["triangles"].get<int>(), 80);  // GLUT's sphere: two caps of fans, quads between: 2·slices·(stacks − 1)
  EXPECT_EQ(j["pixels"].get<int>(), 64 * 48);
  EXPECT_EQ(j["threads"].get<int>(), 1);
  EXPECT_GT(j["fragments"].get<int>(), 0);
  EXPECT_LE(j["ms_min"].get<double>(), j["ms_per_frame"].get<double>());
  EXPECT_EQ(run("bench --frames 0").exitCode, 2);
}

TEST(CliRayTracing, RendererOptionsApplyAndBadValuesAreRefused) {
  TempDir dir;
  const std::string out = (dir / "out.png").string();
  // The built-in scene ray traced: its caption says so, and shadows fall where the rasterizer has
  // none (under the red sphere, on the floor).
  const RunResult traced = run("render --renderer whitted --width 480 --height 270 -o " + out);
  ASSERT_EQ(traced.exitCode, 0) << traced.err;
  const illum::Image whitted = illum::readPng(out);
  ASSERT_EQ(run("render --renderer whitted --no-shadows --width 480 --height 270 -o " + out).exitCode, 0);
  const illum::Image unshadowed = illum::readPng(out);
  EXPECT_NE(whitted.rgba, unshadowed.rgba);
  ASSERT_EQ(run("render --renderer hall --samples 4 --max-depth 2 --width 96 --height 54 -o " + out).exitCode, 0);
  EXPECT_EQ(illum::readPng(out).width, 96);
  const RunResult bad = run("render --renderer pathtracer -o " + out);
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_NE(bad.err.find("--renderer: expected raster, whitted, hall or path"), std::string::npos) << bad.err;
  EXPECT_EQ(run("render --renderer whitted --samples 0 -o " + out).exitCode, 2);
  EXPECT_EQ(run("render --renderer whitted --max-depth 17 -o " + out).exitCode, 2);
  // --seed: another picture of the same samples' noise, the same bytes for the same seed; the
  // rasterizer, which takes no random samples, refuses it.
  const auto jittered = [&](const std::string& seed) {
    const RunResult r = run("render --renderer whitted --samples 4 --width 96 --height 54" + seed + " -o " + out);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    return illum::readPng(out).rgba;
  };
  EXPECT_EQ(jittered(""), jittered(" --seed 0"));
  EXPECT_EQ(jittered(" --seed 9"), jittered(" --seed 9"));
  EXPECT_NE(jittered(" --seed 9"), jittered(""));
  const RunResult raster = run("render --seed 3 -o " + out);
  EXPECT_EQ(raster.exitCode, 2);
  EXPECT_NE(raster.err.find("--seed: the ray tracers'"), std::string::npos) << raster.err;
}

TEST(CliRayTracing, DebugPixelReportsShadowsAndTheTracedColour) {
  TempDir dir;
  const RunResult r = run("render " + std::string(ILLUM_EXAMPLES_DIR) + "/whitted.json --debug-pixel 200,330 -o " +
                          (dir / "out.png").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("ray traced (whitted)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("light 0: in shadow"), std::string::npos) << r.out;  // the glass sphere's shadow
  int b[4] = {0, 0, 0, 0};
  const auto bytes = r.out.find("= bytes ");
  ASSERT_NE(bytes, std::string::npos);
  ASSERT_EQ(std::sscanf(r.out.c_str() + bytes, "= bytes %d %d %d %d", &b[0], &b[1], &b[2], &b[3]), 4);
  const illum::Image img = illum::readPng(dir / "out.png");
  for (int c = 0; c < 4; ++c) EXPECT_EQ(img.pixel(200, 330)[c], b[c]);
}

TEST(CliRayTracing, BenchCountsRays) {
  TempDir dir;
  std::ofstream(dir / "one.json") << R"({"width": 64, "height": 48, "renderer": "whitted",
    "objects": [{"mesh": {"type": "sphere", "slices": 10, "stacks": 5}, "material": {"reflective": [0.5, 0.5, 0.5]}}]})";
  const RunResult r = run("bench " + (dir / "one.json").string() + " --frames 2 --threads 1");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["renderer"], "whitted");
  EXPECT_EQ(j["primary_rays"].get<int>(), 64 * 48);
  EXPECT_GT(j["shadow_rays"].get<int>(), 0);
  EXPECT_GT(j["secondary_rays"].get<int>(), 0);
  EXPECT_GT(j["primary_rays_per_core_second"].get<double>(), 0);
}

TEST(CliPathTracing, RendersToPngAndToLinearOpenExr) {
  // A glowing quad of radiance 5 seen head-on, and a white Lambertian sphere under a sky of 0.5:
  // the PNG clamps the glow to 255, the EXR keeps 5, and the furnace sphere is 0.5 in both.
  TempDir dir;
  std::ofstream(dir / "glow.json") << R"({"width": 40, "height": 20, "renderer": "path", "samples": 4,
    "environment": [0.5, 0.5, 0.5], "lights": [],
    "camera": {"eye": [0, 0, 5], "projection": "orthographic", "view_height": 2},
    "objects": [
      {"mesh": {"type": "triangles", "positions": [-2,-1,0, -0.2,-1,0, -0.2,1,0, -2,1,0], "indices": [0,1,2, 0,2,3]},
       "material": {"diffuse": [0,0,0], "ambient": [0,0,0], "emission": [1,1,1], "emission_strength": 5}},
      {"mesh": {"type": "sphere", "radius": 0.8, "slices": 32, "stacks": 16},
       "transform": [{"translate": [1, 0, 0]}], "material": {"diffuse": [1,1,1], "ambient": [1,1,1]}}]})";
  ASSERT_EQ(run("render " + (dir / "glow.json").string() + " -o " + (dir / "glow.png").string()).exitCode, 0);
  ASSERT_EQ(run("render " + (dir / "glow.json").string() + " -o " + (dir / "glow.exr").string()).exitCode, 0);
  const illum::Image png = illum::readPng(dir / "glow.png");
  const illum::FloatImage exr = illum::readExr(dir / "glow.exr");
  ASSERT_EQ(exr.width, 40);
  ASSERT_EQ(exr.height, 20);
  EXPECT_EQ(png.pixel(5, 10)[0], 255);
  EXPECT_FLOAT_EQ(exr.pixel(5, 10)[0], 5);
  EXPECT_EQ(png.pixel(30, 10)[0], 128);
  EXPECT_NEAR(exr.pixel(30, 10)[0], 0.5, 1e-5);
  EXPECT_EQ(exr.pixel(30, 10)[3], 1);
}

TEST(CliOutput, PngEncodingIsDeterministicAndDecodes) {
  TempDir dir;
  ASSERT_EQ(run("render --width 200 --height 100 -o " + (dir / "a.png").string()).exitCode, 0);
  ASSERT_EQ(run("render --width 200 --height 100 -o " + (dir / "b.png").string()).exitCode, 0);
  EXPECT_EQ(slurp(dir / "a.png"), slurp(dir / "b.png"));
  const illum::Image img = illum::readPng(dir / "a.png");
  EXPECT_EQ(img.width, 200);
  EXPECT_EQ(img.height, 100);
}

namespace {

// A Radiance .hdr of 16×8 texels of radiance 0.5 (RGBE 128,128,128,128: 128·2^(128−136)), flat.
void writeHalfGreyHdr(const fs::path& path) {
  std::ofstream out(path, std::ios::binary);
  out << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 8 +X 16\n";
  for (int i = 0; i < 16 * 8; ++i) out << char(128) << char(128) << char(128) << char(128);
}

}  // namespace

// --environment: a map lights every renderer and is shown behind the scene; the saved scene draws
// the same bytes; the studio is a value too; bad values are refused before anything is written.
TEST(CliRender, AnEnvironmentLightsTheSceneAndIsShownBehindIt) {
  TempDir dir;
  writeHalfGreyHdr(dir / "grey.hdr");
  const std::string env = " --environment " + (dir / "grey.hdr").string();
  const RunResult r = run("render --resolution 64,48" + env + " -o " + (dir / "a.png").string() + " --save-scene " +
                          (dir / "a.json").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const illum::Image a = illum::readPng(dir / "a.png");
  EXPECT_EQ(a.pixel(0, 0)[0], 128);  // the map's 0.5 behind the scene, as the built-in scene's linear bytes
  EXPECT_EQ(a.pixel(0, 0)[3], 255);
  const std::string text = slurp(dir / "a.json");
  EXPECT_NE(text.find("\"environment_lighting\": \"all\""), std::string::npos) << text;
  EXPECT_NE(text.find("\"environment_background\": \"sharp\""), std::string::npos) << text;
  const RunResult again = run("render " + (dir / "a.json").string() + " -o " + (dir / "b.png").string());
  ASSERT_EQ(again.exitCode, 0) << again.err;
  EXPECT_EQ(slurp(dir / "a.png"), slurp(dir / "b.png"));
  // Lit by it: brighter than the built-in scene's own ambient of 0.15 where only ambient reaches.
  const RunResult plain = run("render --resolution 64,48 -o " + (dir / "p.png").string());
  ASSERT_EQ(plain.exitCode, 0) << plain.err;
  EXPECT_NE(slurp(dir / "p.png"), slurp(dir / "a.png"));
  const RunResult turned = run("render --resolution 64,48" + env + " --environment-rotation 90 --environment-background blurred"
                               " --environment-intensity 2 -o " + (dir / "t.png").string());
  ASSERT_EQ(turned.exitCode, 0) << turned.err;
  EXPECT_EQ(illum::readPng(dir / "t.png").pixel(0, 0)[0], 255);  // 2 × 0.5, clamped as GL clamps
  const RunResult studio = run("render --resolution 64,48 --environment studio -o " + (dir / "s.png").string() +
                               " --save-scene " + (dir / "s.json").string());
  ASSERT_EQ(studio.exitCode, 0) << studio.err;
  EXPECT_NE(slurp(dir / "s.json").find("\"studio_environment\": true"), std::string::npos);
  const RunResult studioAgain = run("render " + (dir / "s.json").string() + " -o " + (dir / "s2.png").string());
  ASSERT_EQ(studioAgain.exitCode, 0) << studioAgain.err;
  EXPECT_EQ(slurp(dir / "s.png"), slurp(dir / "s2.png"));

  // The same sky as an OpenEXR map draws the same bytes.
  {
    illum::FloatImage sky{16, 8, std::vector<float>(16 * 8 * 4, 0.5f), {}};
    const std::vector<std::uint8_t> exr = illum::encodeExr(sky);
    std::ofstream(dir / "grey.exr", std::ios::binary).write(reinterpret_cast<const char*>(exr.data()), std::streamsize(exr.size()));
  }
  const RunResult fromExr = run("render --resolution 64,48 --environment " + (dir / "grey.exr").string() + " -o " +
                                (dir / "e.png").string());
  ASSERT_EQ(fromExr.exitCode, 0) << fromExr.err;
  EXPECT_EQ(slurp(dir / "e.png"), slurp(dir / "a.png"));
  {
    std::ofstream(dir / "cut.exr", std::ios::binary) << slurp(dir / "grey.exr").substr(0, 40);
  }
  const RunResult cut = run("render --environment " + (dir / "cut.exr").string() + " -o " + (dir / "m.png").string());
  EXPECT_EQ(cut.exitCode, 2);
  EXPECT_NE(cut.err.find("cut.exr: not a readable OpenEXR image"), std::string::npos) << cut.err;
  // Neither format's first bytes (an image of another kind, named .exr): refused as neither.
  std::filesystem::copy_file(dir / "a.png", dir / "png.exr");
  const RunResult neither = run("render --environment " + (dir / "png.exr").string() + " -o " + (dir / "m.png").string());
  EXPECT_EQ(neither.exitCode, 2);
  EXPECT_NE(neither.err.find("png.exr: neither an OpenEXR image (whose first four bytes are 76 2f 31 01) nor a Radiance .hdr one"),
            std::string::npos)
      << neither.err;

  const RunResult missing = run("render --environment " + (dir / "none.hdr").string() + " -o " + (dir / "m.png").string());
  EXPECT_EQ(missing.exitCode, 2);
  EXPECT_NE(missing.err.find("--environment: expected a readable Radiance .hdr or OpenEXR .exr image"), std::string::npos) << missing.err;
  const RunResult badBackground = run("render" + env + " --environment-background blury -o " + (dir / "m.png").string());
  EXPECT_EQ(badBackground.exitCode, 2);
  EXPECT_NE(badBackground.err.find("blurred"), std::string::npos) << badBackground.err;
  const RunResult badRotation = run("render" + env + " --environment-rotation 400 -o " + (dir / "m.png").string());
  EXPECT_EQ(badRotation.exitCode, 2);
  EXPECT_FALSE(fs::exists(dir / "m.png"));
}
