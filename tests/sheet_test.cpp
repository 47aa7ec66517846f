// Comparison sheets as a user makes them: `illum compare` and `illum history`. Every panel is the
// picture `illum render` makes with the same settings, byte for byte; every row and column is
// labelled; bad axes are refused before anything is rendered.
#include "cli_support.h"

#include <illum/image.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <regex>
#include <sstream>

namespace {

namespace fs = std::filesystem;
using illum::Image;
using illum::test::RunResult;
using illum::test::TempDir;

RunResult run(const std::string& args) { return illum::test::runIllum(args); }

struct Panel {
  int row, col, x, y, width, height;
  std::string rowLabel, colLabel, caption;
};

// The panels `-v` lists: "illum: panel R,C (ROW / COL) at X,Y, WxH[: CAPTION]".
std::vector<Panel> panels(const std::string& err) {
  std::vector<Panel> out;
  const std::regex line(R"(illum: panel (\d+),(\d+) \((.*) / (.*)\) at (\d+),(\d+), (\d+)x(\d+)(?:: (.*))?)");
  std::istringstream in(err);
  for (std::string s; std::getline(in, s);) {
    std::smatch m;
    if (std::regex_match(s, m, line))
      out.push_back({std::stoi(m[1]), std::stoi(m[2]), std::stoi(m[5]), std::stoi(m[6]), std::stoi(m[7]), std::stoi(m[8]),
                     m[3], m[4], m[9]});
  }
  return out;
}

Image crop(const Image& sheet, const Panel& p) {
  Image out(p.width, p.height);
  for (int y = 0; y < p.height; ++y)
    std::copy_n(sheet.pixel(p.x, p.y + y), std::size_t(p.width) * 4, out.pixel(0, y));
  return out;
}

// Pixels unlike the sheet's paper in a rectangle: text was drawn there.
int inkIn(const Image& sheet, int x0, int y0, int x1, int y1) {
  int ink = 0;
  for (int y = std::max(0, y0); y < std::min(sheet.height, y1); ++y)
    for (int x = std::max(0, x0); x < std::min(sheet.width, x1); ++x) ink += sheet.pixel(x, y)[0] > 120;
  return ink;
}

TEST(CliCompare, DefaultSheetIsModelsByShadingAndEveryPanelIsTheSingleRender) {
  TempDir dir;
  const RunResult r = run("compare --resolution 160,90 -v -o " + (dir / "sheet.png").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const Image sheet = illum::readPng(dir / "sheet.png");
  const std::vector<Panel> ps = panels(r.err);
  ASSERT_EQ(ps.size(), 12u);  // lambert, phong, blinn-phong, cook-torrance × flat, gouraud, phong
  EXPECT_EQ(ps[0].rowLabel, "lambert");
  EXPECT_EQ(ps[11].rowLabel, "cook-torrance");
  EXPECT_EQ(ps[11].colLabel, "phong");
  for (const Panel& p : ps) {
    ASSERT_EQ(p.width, 160);
    ASSERT_EQ(p.height, 90);
    const fs::path single = dir / "single.png";
    const RunResult one = run("render --resolution 160,90 --model " + p.rowLabel + " --shading " + p.colLabel + " -o " +
                              single.string());
    ASSERT_EQ(one.exitCode, 0) << one.err;
    EXPECT_EQ(crop(sheet, p).rgba, illum::readPng(single).rgba) << p.rowLabel << " / " << p.colLabel;
    // A label left of every row and over every column.
    if (p.col == 0) {
      EXPECT_GT(inkIn(sheet, 0, p.y, p.x, p.y + p.height), 20) << p.rowLabel;
    }
    if (p.row == 0) {
      EXPECT_GT(inkIn(sheet, p.x, p.y - 26, p.x + p.width, p.y), 20) << p.colLabel;
    }
  }
  // The grid's size: the panels and their gaps inside the margins, the labels' column and row.
  EXPECT_GE(sheet.width, 3 * 160 + 2 * 10);
  EXPECT_GE(sheet.height, 4 * 90 + 3 * 10);
  EXPECT_LT(sheet.width, 3 * 160 + 2 * 10 + 250);
}

TEST(CliCompare, SceneKeyAxesEqualTheEditedSceneFile) {
  TempDir dir;
  const auto scene = [&](const std::string& diffuse, int shininess) {
    const fs::path p = dir / ("scene_" + std::to_string(shininess) + "_" + std::to_string(std::hash<std::string>()(diffuse)) + ".json");
    std::ofstream(p) << R"({"width": 96, "height": 64, "lights": [{"position": [1, 2, 3, 1]}, {"position": [-2, 0, 1, 0], "diffuse": [0, 0.5, 0]}],
      "objects": [{"mesh": {"type": "sphere"}, "material": {"diffuse": [)" << diffuse << R"(], "specular": [1, 1, 1], "shininess": )"
                    << shininess << "}}]}";
    return p;
  };
  const fs::path base = scene("1, 0, 0", 10);
  const RunResult r = run("compare " + base.string() + " --rows 'material.diffuse=1,0,0;0,0,1' --cols shininess=10,80 -v -o " +
                          (dir / "sheet.png").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const Image sheet = illum::readPng(dir / "sheet.png");
  const std::vector<Panel> ps = panels(r.err);
  ASSERT_EQ(ps.size(), 4u);
  for (const Panel& p : ps) {
    const fs::path edited = scene(p.row == 0 ? "1, 0, 0" : "0, 0, 1", p.col == 0 ? 10 : 80);
    ASSERT_EQ(run("render " + edited.string() + " -o " + (dir / "one.png").string()).exitCode, 0);
    EXPECT_EQ(crop(sheet, p).rgba, illum::readPng(dir / "one.png").rgba) << p.rowLabel << " / " << p.colLabel;
  }
  // Fewer lights: light-count keeps the first N.
  const RunResult lights = run("compare " + base.string() + " --rows light-count --cols shading=phong -v -o " +
                               (dir / "lights.png").string());
  ASSERT_EQ(lights.exitCode, 0) << lights.err;
  EXPECT_EQ(panels(lights.err).size(), 2u);
}

// A caption is a template over what it describes (captions.h): an axis that moves the light moves
// the caption with it, so that each panel is the scene file with that light, caption and all.
TEST(CliCompare, CaptionsStayTrueUnderAnAxis) {
  TempDir dir;
  const std::string original = illum::test::slurp(fs::path(ILLUM_EXAMPLES_DIR) / "first_light.json");
  ASSERT_NE(original.find("light at {light.0.position}"), std::string::npos);
  const RunResult r = run("compare " + (fs::path(ILLUM_EXAMPLES_DIR) / "first_light.json").string() +
                          " --rows 'light.0.position=1,2,3,1;-2,1,3,1' --cols shading=phong -v -o " + (dir / "sheet.png").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const Image sheet = illum::readPng(dir / "sheet.png");
  const std::vector<Panel> ps = panels(r.err);
  ASSERT_EQ(ps.size(), 2u);
  for (const Panel& p : ps) {
    std::string edited = original;
    edited.replace(edited.find("[1, 2, 3, 1]"), 12, p.row == 0 ? "[1, 2, 3, 1]" : "[-2, 1, 3, 1]");
    std::ofstream(dir / "edited.json") << edited;
    ASSERT_EQ(run("render " + (dir / "edited.json").string() + " --resolution " + std::to_string(p.width) + "," +
                  std::to_string(p.height) + " -o " + (dir / "one.png").string()).exitCode, 0);
    EXPECT_EQ(crop(sheet, p).rgba, illum::readPng(dir / "one.png").rgba) << p.rowLabel;
  }
  // The captions differ: the top rows of the two panels, where the caption is, are not the same.
  const Image a = crop(sheet, ps[0]), b = crop(sheet, ps[1]);
  EXPECT_FALSE(std::equal(a.rgba.begin(), a.rgba.begin() + 40 * a.width * 4, b.rgba.begin()));
}

// A convention is an axis: GL's equation beside a lecture note's, each panel the render with that
// convention, and a difference panel that says by how much they differ.
TEST(CliCompare, PutsALecturesConventionBesideGls) {
  TempDir dir;
  const std::string scene = (fs::path(ILLUM_EXAMPLES_DIR) / "first_light.json").string();
  const RunResult r = run("compare " + scene + " --rows convention=gl,note-shader --cols shading=gouraud "
                          "--diff gl,note-shader -v -o " + (dir / "sheet.png").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const Image sheet = illum::readPng(dir / "sheet.png");
  const std::vector<Panel> ps = panels(r.err);
  ASSERT_GE(ps.size(), 2u);
  for (int row = 0; row < 2; ++row) {
    const Panel& p = ps[std::size_t(row)];
    EXPECT_EQ(p.rowLabel, row == 0 ? "gl" : "note-shader");
    ASSERT_EQ(run("render " + scene + " --shading gouraud --convention " + p.rowLabel + " --resolution " +
                  std::to_string(p.width) + "," + std::to_string(p.height) + " -o " + (dir / "one.png").string()).exitCode, 0);
    EXPECT_EQ(crop(sheet, p).rgba, illum::readPng(dir / "one.png").rgba) << p.rowLabel;
  }
  EXPECT_NE(crop(sheet, ps[0]).rgba, crop(sheet, ps[1]).rgba);
  // The note's ambient is the material's whole ambient (0.2), GL's the global 0.2 × 0.2: 0.16 more
  // wherever neither is clamped, 41 of 255.
  EXPECT_NE(r.err.find("max 41/255"), std::string::npos) << r.err;
  const RunResult bad = run("compare --rows convention=gl,opengl -o " + (dir / "x.png").string());
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_NE(bad.err.find("expected gl, note-shader, note-half-sum or note-world-space"), std::string::npos) << bad.err;
}

// A panel that comes out black says why under it: the floor of attenuation.json has no vertex in a
// spot's cone, so flat and Gouraud shading light nothing (correct GL), and Phong shading does.
// A sheet shows every panel through one display: a path-traced preview's panel takes the sheet's
// sRGB without the ACES tone map its own render would add, so that it compares with the raster's.
TEST(CliCompare, EveryPanelGoesThroughTheSheetsOneDisplay) {
  TempDir dir;
  const std::string duck = "/usr/share/assimp/models/Collada/duck.dae";
  const RunResult r = run("compare " + duck + " --rows renderer=raster,path --cols shading=phong --samples 4"
                          " --resolution 80,60 -v -o " + (dir / "sheet.png").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const Image sheet = illum::readPng(dir / "sheet.png");
  const std::vector<Panel> ps = panels(r.err);
  ASSERT_EQ(ps.size(), 2u);
  const RunResult path = run("render " + duck + " --renderer path --samples 4 --tone-map none --resolution 80,60 -o " +
                             (dir / "path.png").string());
  ASSERT_EQ(path.exitCode, 0) << path.err;
  EXPECT_EQ(crop(sheet, ps[1]).rgba, illum::readPng(dir / "path.png").rgba);
  const RunResult aces = run("render " + duck + " --renderer path --samples 4 --resolution 80,60 -o " +
                             (dir / "aces.png").string());
  ASSERT_EQ(aces.exitCode, 0) << aces.err;
  EXPECT_NE(crop(sheet, ps[1]).rgba, illum::readPng(dir / "aces.png").rgba) << "the render alone is tone-mapped";
  // The corners are background in both panels, the same bytes.
  const Image raster = crop(sheet, ps[0]), traced = crop(sheet, ps[1]);
  for (int c = 0; c < 4; ++c) EXPECT_EQ(raster.pixel(0, 0)[c], traced.pixel(0, 0)[c]);
}

TEST(CliCompare, BlackPanelsSayWhy) {
  TempDir dir;
  const RunResult r = run("compare " + (fs::path(ILLUM_EXAMPLES_DIR) / "attenuation.json").string() +
                          " --rows light-count --cols shading -v -o " + (dir / "sheet.png").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::vector<Panel> ps = panels(r.err);
  ASSERT_EQ(ps.size(), 9u);
  for (const Panel& p : ps) {
    if (p.colLabel == "phong") {
      EXPECT_EQ(p.caption, "") << p.rowLabel;
      continue;
    }
    EXPECT_EQ(p.caption, "black: no vertex lies inside a spot's cone (" + p.colLabel + " shading lights vertices only)");
    const Image sheet = illum::readPng(dir / "sheet.png");
    EXPECT_GT(inkIn(sheet, p.x, p.y + p.height, p.x + p.width, p.y + p.height + 40), 20) << "the caption is drawn";
  }
}

// Captions too small to read once a picture is scaled down (a sheet's panel, a thumbnail) are left
// out; those kept are readable.
TEST(CliCompare, NoCaptionIsShownSmallerThanReadable) {
  TempDir dir;
  for (const char* size : {"400,225", "640,360", "960,540"}) {
    const fs::path saved = dir / "scene.json";
    ASSERT_EQ(run(std::string("render --resolution ") + size + " --save-scene " + saved.string() + " --force -o " +
                  (dir / "x.png").string()).exitCode, 0);
    const nlohmann::json scene = nlohmann::json::parse(illum::test::slurp(saved));
    const nlohmann::json labels = scene.value("labels", nlohmann::json::array());
    for (const nlohmann::json& label : labels) EXPECT_GE(label.at("size").get<double>(), 10) << size;
    EXPECT_EQ(labels.empty(), std::string(size) == "400,225") << size << ": " << labels.size() << " labels";
  }
}

TEST(CliCompare, DiffAddsAPanelWithTheFigures) {
  TempDir dir;
  const RunResult r = run("compare --resolution 120,80 --rows model=phong,blinn-phong --cols shading=gouraud,phong "
                          "--diff gouraud,phong -v -o " + (dir / "sheet.png").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::vector<Panel> ps = panels(r.err);
  ASSERT_EQ(ps.size(), 6u);
  EXPECT_EQ(ps[2].colLabel, "gouraud vs phong");
  const Image sheet = illum::readPng(dir / "sheet.png");
  // The two shadings differ somewhere, so the panel is not all black; the figures are under it.
  const Image diff = crop(sheet, ps[2]);
  int lit = 0;
  for (std::size_t i = 0; i < diff.rgba.size(); i += 4) lit += diff.rgba[i] + diff.rgba[i + 1] + diff.rgba[i + 2] > 0;
  EXPECT_GT(lit, 20);
  EXPECT_GT(inkIn(sheet, ps[2].x, ps[2].y + ps[2].height, ps[2].x + ps[2].width, ps[2].y + ps[2].height + 22), 20);
  // The same setting twice differs nowhere: a row's diff across identical values is refused as
  // meaningless, and values not on an axis are named.
  const RunResult bad = run("compare --rows model=phong --cols shading=gouraud,phong --diff flat,phong -o " +
                            (dir / "x.png").string());
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_NE(bad.err.find("--diff: expected two different values"), std::string::npos) << bad.err;
}

TEST(CliCompare, BadAxesAreRefusedBeforeRendering) {
  TempDir dir;
  const fs::path out = dir / "sheet.png";
  for (const auto& [args, message] : std::vector<std::pair<std::string, std::string>>{
           {"--rows colour", "--rows: expected an axis"},
           {"--rows model=phong,gooch", "--rows model: expected blinn-phong"},
           {"--cols shininess=-1", "--cols shininess"},
           {"--rows shading --cols shading", "two different axes"},
           {"--rows material.glow=1", "expected material."},
           {"--rows light.7.diffuse=1", "the scene has 3 lights"},
           {"--rows 'material.diffuse=1,0;0,0,1'", "material.diffuse"},
       }) {
    const RunResult r = run("compare " + args + " -o " + out.string());
    EXPECT_EQ(r.exitCode, 2) << args;
    EXPECT_NE(r.err.find(message), std::string::npos) << args << ": " << r.err;
    EXPECT_FALSE(fs::exists(out)) << args;
  }
}

}  // namespace

namespace {

TEST(CliHistory, NinePanelsInTheSeedsOrderEachTheModelsOwnRender) {
  TempDir dir;
  const RunResult r = run("history --resolution 120,68 --samples 4 -v -o " + (dir / "history.png").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const Image sheet = illum::readPng(dir / "history.png");
  const std::vector<Panel> ps = panels(r.err);
  ASSERT_EQ(ps.size(), 9u);
  const char* years[] = {"1967", "1970", "1971", "1975", "1977", "1980", "1982", "1983", "1986"};
  for (std::size_t i = 0; i < ps.size(); ++i) {
    const Panel& p = ps[i];
    EXPECT_EQ(p.rowLabel, years[i]);
    // Every panel shows something, and is captioned (two lines under it).
    const Image panel = crop(sheet, p);
    EXPECT_GT(inkIn(panel, 0, 0, panel.width, panel.height), 200) << years[i];
    EXPECT_GT(inkIn(sheet, p.x, p.y + p.height, p.x + p.width, p.y + p.height + 20), 20) << years[i];
    EXPECT_GT(inkIn(sheet, p.x, p.y + p.height + 20, p.x + p.width, p.y + p.height + 40), 20) << years[i];
    // "wylie phong raster": after Wylie's own light, every panel is `illum render` with its settings.
    std::istringstream settings(p.colLabel);
    std::string model, shading, renderer;
    settings >> model >> shading >> renderer;
    if (model == "wylie") continue;
    const fs::path single = dir / "single.png";
    ASSERT_EQ(run("render --resolution 120,68 --samples 4 --model " + model + " --shading " + shading + " --renderer " +
                  renderer + " -o " + single.string()).exitCode, 0);
    EXPECT_EQ(panel.rgba, illum::readPng(single).rgba) << years[i];
  }
  // The settings the sheet chooses are not the user's to override.
  EXPECT_EQ(run("history --model phong -o " + (dir / "x.png").string()).exitCode, 2);
}

}  // namespace
