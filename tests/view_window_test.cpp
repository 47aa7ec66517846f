// `illum view` driven as a person drives it: a real window on a virtual X server, real mouse and
// key events, screenshots. What the window shows is asserted against what `illum render` draws.
#include "view_window.h"

#include <cstring>
#include <fstream>
#include <thread>

namespace illum::test {
namespace {

// A small scene, so that each frame is quick: a sphere and a cube under two lights.
const char* kScene = R"({
  "width": 320, "height": 200, "background": [0.1, 0.2, 0.3],
  "camera": {"eye": [0, 0.6, 4], "center": [0, 0, 0], "fovy": 40},
  "lights": [{"position": [2, 3, 4, 1], "diffuse": [1, 0.9, 0.8]}, {"position": [-1, 0.2, 0.5, 0], "diffuse": [0.2, 0.3, 0.5]}],
  "objects": [
    {"mesh": {"type": "sphere", "radius": 0.8, "slices": 32, "stacks": 24}, "transform": [{"translate": [-0.6, 0, 0]}],
     "material": {"diffuse": [0.8, 0.2, 0.1], "specular": [0.6, 0.6, 0.6], "shininess": 40}},
    {"mesh": {"type": "cube", "size": 0.9}, "transform": [{"translate": [0.9, 0, -0.3]}, {"rotate": [30, 0, 1, 0]}],
     "material": {"diffuse": [0.2, 0.5, 0.9]}}
  ]})";

void write(const fs::path& path, const std::string& text) {
  const fs::path temp = path.string() + ".new";
  std::ofstream(temp) << text;
  fs::rename(temp, path);  // at once, as an editor saves
}

// What `illum render ARGS` draws, as the window would show it (RGB, opaque).
Image rendered(const TempDir& dir, const std::string& args) {
  const RunResult r = runIllum("render " + args + " -o " + (dir / "expected.png").string());
  EXPECT_EQ(r.exitCode, 0) << r.err;
  const Image image = readPng(dir / "expected.png");
  return crop(image, image.width, image.height);
}

class ViewWindow : public ::testing::Test {
 protected:
  VirtualDisplay display;
  TempDir dir;
  fs::path scene = dir / "scene.json";
  void SetUp() override { write(scene, kScene); }
  // The picture, with the panels hidden (Tab): the window is then the picture alone.
  std::unique_ptr<Viewer> bare(const std::string& args) {
    auto viewer = std::make_unique<Viewer>(display, dir.path(), args);
    viewer->settled();
    viewer->key("Tab");
    return viewer;
  }
};

TEST_F(ViewWindow, ShowsWhatRenderDrawsAndTurnsWhenDragged) {
  auto v = bare(scene.string());
  const Image expected = rendered(dir, scene.string());
  const Image first = v->waitFor([&](const Image& s) { return crop(s, 320, 200).rgba == expected.rgba; });
  ASSERT_EQ(crop(first, 320, 200).rgba, expected.rgba) << "the window is not the picture `illum render` draws";
  EXPECT_EQ(first.width, 320);  // no panels: the window is the picture
  // A left drag turns the view about the focal point: most of the objects' pixels change.
  v->key("3");
  const Image turned = v->waitFor([&](const Image& s) { return differingPixels(crop(s, 320, 200), expected) > 3000; });
  EXPECT_GT(differingPixels(crop(turned, 320, 200), expected), 3000u);
  // Enter: back to the framing, the very same bytes.
  v->key("Return");
  const Image home = v->waitFor([&](const Image& s) { return crop(s, 320, 200).rgba == expected.rgba; });
  EXPECT_EQ(crop(home, 320, 200).rgba, expected.rgba);
  // The wheel and a right drag zoom: the sphere grows.
  v->drag(160, 100, 160, 40, 3);
  const Image zoomed = v->waitFor([&](const Image& s) { return differingPixels(crop(s, 320, 200), expected) > 3000; });
  EXPECT_GT(differingPixels(crop(zoomed, 320, 200), expected), 3000u);
  EXPECT_EQ(v->quit(), 0);
}

TEST_F(ViewWindow, KeysToggleWhatTheOptionsToggle) {
  auto v = bare(scene.string());
  const Image plain = rendered(dir, scene.string());
  const Image edges = rendered(dir, scene.string() + " --edges");
  ASSERT_EQ(crop(v->waitFor([&](const Image& s) { return crop(s, 320, 200).rgba == plain.rgba; }), 320, 200).rgba, plain.rgba);
  // E: the triangles' edges, as --edges draws them; E again: without.
  v->key("e");
  EXPECT_EQ(crop(v->waitFor([&](const Image& s) { return crop(s, 320, 200).rgba == edges.rgba; }), 320, 200).rgba, edges.rgba);
  v->key("e");
  EXPECT_EQ(crop(v->waitFor([&](const Image& s) { return crop(s, 320, 200).rgba == plain.rgba; }), 320, 200).rgba, plain.rgba);
  // F: environment lighting, as --environment studio draws it (the scene has no map of its own).
  const Image studio = rendered(dir, scene.string() + " --environment studio");
  ASSERT_NE(studio.rgba, plain.rgba);
  v->key("f");
  EXPECT_EQ(crop(v->waitFor([&](const Image& s) { return crop(s, 320, 200).rgba == studio.rgba; }), 320, 200).rgba, studio.rgba);
  v->key("f");
  EXPECT_EQ(crop(v->waitFor([&](const Image& s) { return crop(s, 320, 200).rgba == plain.rgba; }), 320, 200).rgba, plain.rgba);
  // A: 8 samples, as --samples 8.
  const Image smooth = rendered(dir, scene.string() + " --samples 8");
  v->key("a");
  EXPECT_EQ(crop(v->waitFor([&](const Image& s) { return crop(s, 320, 200).rgba == smooth.rgba; }), 320, 200).rgba, smooth.rgba);
  EXPECT_EQ(v->quit(), 0);
}

TEST_F(ViewWindow, AClickPrintsThePixelsReport) {
  auto v = bare(scene.string());
  v->settled();
  v->click(110, 95);  // on the sphere
  // The report comes once its frame is drawn: the --debug-pixel report of the same pixel.
  const RunResult r = runIllum("render " + scene.string() + " --debug-pixel 110,95 -o " + (dir / "probe.png").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::string report = r.out.substr(r.out.find('\n') + 1);  // after the line naming the picture
  for (int i = 0; i < 100 && v->out().size() < report.size(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  EXPECT_EQ(v->out(), report);
  EXPECT_NE(report.find("pixel (110, 95): object 0"), std::string::npos) << report;
  EXPECT_EQ(v->quit(), 0);
}

TEST_F(ViewWindow, ASavedSceneRendersToTheSavedPictureByteForByte) {
  auto v = bare(scene.string());
  v->settled();
  v->drag(100, 100, 150, 80);  // somewhere else than the file's own view
  v->key("e");
  v->settled();
  v->key("F12");
  for (int i = 0; i < 100 && !fs::exists(dir / "illum_view_1.json"); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  ASSERT_TRUE(fs::exists(dir / "illum_view_1.png")) << v->err();
  ASSERT_TRUE(fs::exists(dir / "illum_view_1.json")) << v->err();
  EXPECT_NE(v->err().find("saved ./illum_view_1.png and ./illum_view_1.json"), std::string::npos) << v->err();
  const RunResult r = runIllum("render " + (dir / "illum_view_1.json").string() + " -o " + (dir / "again.png").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(slurp(dir / "illum_view_1.png"), slurp(dir / "again.png"));
  // ... and it is what the window shows.
  const Image saved = readPng(dir / "illum_view_1.png");
  EXPECT_EQ(crop(v->settled(), 320, 200).rgba, crop(saved, 320, 200).rgba);
  EXPECT_NE(slurp(dir / "illum_view_1.json").find("\"edges\": true"), std::string::npos);
  EXPECT_EQ(v->quit(), 0);
}

TEST_F(ViewWindow, AFileChangedOnDiskIsReadAgainAndABrokenOneKeepsThePicture) {
  auto v = bare(scene.string());
  const Image before = v->settled();
  std::string changed = kScene;
  changed.replace(changed.find("[0.1, 0.2, 0.3]"), 15, "[0.9, 0.5, 0.1]");
  write(scene, changed);
  const Image expected = rendered(dir, scene.string());
  const Image after = v->waitFor([&](const Image& s) { return crop(s, 320, 200).rgba == expected.rgba; });
  EXPECT_EQ(crop(after, 320, 200).rgba, expected.rgba);
  EXPECT_EQ(int(after.pixel(2, 2)[0]), 229);  // the new background: 0.9 of 255, as GL rounds it
  // A broken version: a clear message, the last good picture kept.
  write(scene, "{\"width\": 320,");
  for (int i = 0; i < 50 && v->err().find("invalid JSON") == std::string::npos; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  EXPECT_NE(v->err().find("scene.json: line 1, column 15: invalid JSON"), std::string::npos) << v->err();
  EXPECT_EQ(crop(v->settled(), 320, 200).rgba, crop(after, 320, 200).rgba);
  EXPECT_NE(before.rgba, after.rgba);
  EXPECT_EQ(v->quit(), 0);
}

TEST_F(ViewWindow, PageDownStepsToTheNextFile) {
  const fs::path second = dir / "second.json";
  std::string other = kScene;
  other.replace(other.find("[0.8, 0.2, 0.1]"), 15, "[0.1, 0.8, 0.2]");
  write(second, other);
  auto v = bare(scene.string() + " " + second.string());
  const Image expected = rendered(dir, second.string());
  v->settled();
  v->key("Next");
  EXPECT_EQ(crop(v->waitFor([&](const Image& s) { return crop(s, 320, 200).rgba == expected.rgba; }), 320, 200).rgba,
            expected.rgba);
  EXPECT_EQ(v->quit(), 0);
}

// A model file, framed and lit as `illum render` frames it; the panels beside it. The screenshot
// is the README's.
TEST_F(ViewWindow, AModelIsFramedAsRenderFramesItWithThePanelsBeside) {
  const std::string duck = "/usr/share/assimp/models/Collada/duck.dae";
  auto v = bare(duck + " --resolution 640,400");
  const Image expected = rendered(dir, duck + " --resolution 640,400");
  const Image shot = v->waitFor([&](const Image& s) { return crop(s, 640, 400).rgba == expected.rgba; });
  EXPECT_EQ(crop(shot, 640, 400).rgba, expected.rgba);
  // The panels stand beside the picture (Tab again), with the lights' handles over it.
  v->key("Tab");
  const Image panels = v->waitFor([](const Image& s) { return s.width > 640; });
  EXPECT_EQ(panels.width, 640 + 460);
  // Below the widgets, the strip's opaque fill: ImGui's dark window colour (0.06 at alpha 0.94)
  // over black, the bytes ImGui's own blended background gave.
  const std::size_t below = (std::size_t(390) * std::size_t(panels.width) + 640 + 230) * 4;
  EXPECT_EQ(std::vector<std::uint8_t>(panels.rgba.begin() + long(below), panels.rgba.begin() + long(below) + 3),
            (std::vector<std::uint8_t>{14, 14, 14}));
  v->click(330, 210);  // the duck's middle: its report in the panel
  const Image withReport = v->waitFor([&](const Image& s) { return differingPixels(s, panels) > 1000; });
  EXPECT_GT(differingPixels(withReport, panels), 1000u);
#ifdef ILLUM_SCREENSHOT
  writePng(ILLUM_SCREENSHOT, withReport);
#endif
  EXPECT_EQ(v->quit(), 0);
}

TEST_F(ViewWindow, ThePanelsStayAsDrawnWhileTheViewTurnsAndFollowAKey) {
  // The panels' strip is drawn again only when what it shows changes: an axis view (key 3) turns
  // the picture and leaves the strip's pixels as they were; Q checks a box there (ambient
  // occlusion, near the top, where the short window shows it), and Q again brings back the very
  // strip the turn kept.
  auto v = std::make_unique<Viewer>(display, dir.path(), scene.string());
  const auto strip = [](const Image& s) {
    Image out(s.width - 320, s.height);
    for (int y = 0; y < s.height; ++y) std::memcpy(out.pixel(0, y), s.pixel(320, y), std::size_t(out.width) * 4);
    return out;
  };
  const Image before = v->settled();
  ASSERT_EQ(before.width, 320 + 460);
  v->key("3");
  const Image turned = v->waitFor([&](const Image& s) { return differingPixels(crop(s, 320, 200), crop(before, 320, 200)) > 3000; });
  EXPECT_GT(differingPixels(crop(turned, 320, 200), crop(before, 320, 200)), 3000u);
  EXPECT_EQ(strip(turned).rgba, strip(before).rgba);
  v->key("q");
  const Image checked = v->waitFor([&](const Image& s) { return strip(s).rgba != strip(before).rgba; });
  EXPECT_NE(strip(checked).rgba, strip(before).rgba);
  v->key("q");
  const Image back = v->waitFor([&](const Image& s) { return strip(s).rgba == strip(before).rgba; });
  EXPECT_EQ(strip(back).rgba, strip(before).rgba);
  EXPECT_EQ(v->quit(), 0);
}

TEST(ViewWithoutDisplay, ExitsWithOneSentence) {
  const RunResult r = runShell("env -u DISPLAY -u WAYLAND_DISPLAY " + std::string(ILLUM_CLI) + " view");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_EQ(r.err, "illum: error: no display: illum view needs a window; use illum render\n");
}

}  // namespace
}  // namespace illum::test
