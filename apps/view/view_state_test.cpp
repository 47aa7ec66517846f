// The viewer's state without a window: the trackball's closed forms, f3d's keys, stepping
// through files, a model preview's rig turning with the camera, and the frames the worker draws
// equal what `illum render` draws of the same scene.
#include "key_map.h"
#include "save_view.h"
#include "render_worker.h"
#include "trackball.h"
#include "view_state.h"

#include <illum/error.h>
#include <illum/render.h>

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <cmath>
#include <thread>

#include <unistd.h>

namespace illum::view {
namespace {

const char* kModels = "/usr/share/assimp/models";

Camera lookingDown(Real distance) {
  Camera c;
  c.eye = {0, 0, distance};
  c.center = {0, 0, 0};
  c.up = {0, 1, 0};
  return c;
}

TEST(Trackball, OrbitTurnsAboutTheFocalPointAtTheSameDistance) {
  Trackball t(lookingDown(5), {{0, 0, 0}, 1}, {0, 1, 0});
  // A drag across half the window's height (100 of 200 pixels): 100° about the view-up.
  t.orbit(-100, 0, 200);
  const Camera& c = t.camera();
  EXPECT_NEAR(glm::length(c.eye - c.center), 5, 1e-4);
  EXPECT_NEAR(glm::degrees(std::atan2(c.eye.x, c.eye.z)), 100, 1e-3);
  EXPECT_NEAR(c.eye.y, 0, 1e-5);
  // Upwards: elevation about the right axis, the view-up kept orthogonal to the view.
  t.orbit(0, 20, 200);
  EXPECT_NEAR(glm::length(t.camera().eye), 5, 1e-4);
  EXPECT_NEAR(glm::dot(glm::normalize(t.camera().up), glm::normalize(t.camera().eye - t.camera().center)), 0, 1e-5);
}

TEST(Trackball, ZoomPanResetAndAxisViews) {
  Trackball t(lookingDown(5), {{0, 0, 0}, 1}, {0, 1, 0});
  t.zoom(2);
  EXPECT_NEAR(t.camera().eye.z, 2.5, 1e-5);
  EXPECT_LT(t.camera().near, Real(1.5));  // the bounds stay in front of the near plane
  // A drag right moves the world right under the pointer: eye and focal point move left.
  t.pan(10, 0, 100);
  EXPECT_LT(t.camera().center.x, 0);
  EXPECT_NEAR(t.camera().center.x - t.camera().eye.x, 0, 1e-5);
  t.reset();
  EXPECT_EQ(t.camera().eye, Vec3(0, 0, 5));
  EXPECT_EQ(t.camera().center, Vec3(0, 0, 0));
  // Key 7 (top) for a Y-up model: looking down −Y at the same distance.
  t.look(AxisView::Top);
  EXPECT_NEAR(t.camera().eye.y, 5, 1e-5);
  t.look(AxisView::Right);
  EXPECT_NEAR(t.camera().eye.x, 5, 1e-5);
  // Z-up (an STL): the front looks along +Y from −Y.
  Trackball z(lookingDown(5), {{0, 0, 0}, 1}, {0, 0, 1});
  z.look(AxisView::Front);
  EXPECT_NEAR(z.camera().eye.y, -5, 1e-5);
}

TEST(KeyMap, F3dsKeys) {
  EXPECT_EQ(actionFor(SDLK_ESCAPE, 0), Action::Quit);
  EXPECT_EQ(actionFor(SDLK_RETURN, 0), Action::Reset);
  EXPECT_EQ(actionFor(SDLK_e, 0), Action::Edges);
  EXPECT_EQ(actionFor(SDLK_x, 0), Action::Axes);
  EXPECT_EQ(actionFor(SDLK_g, 0), Action::Grid);
  EXPECT_EQ(actionFor(SDLK_z, 0), Action::FrameRate);
  EXPECT_EQ(actionFor(SDLK_a, 0), Action::AntiAliasing);
  EXPECT_EQ(actionFor(SDLK_q, 0), Action::Occlusion);
  EXPECT_EQ(actionFor(SDLK_h, 0), Action::Help);
  EXPECT_EQ(actionFor(SDLK_SLASH, KMOD_SHIFT), Action::Help);
  EXPECT_EQ(actionFor(SDLK_1, 0), Action::Front);
  EXPECT_EQ(actionFor(SDLK_1, KMOD_LCTRL), Action::Back);
  EXPECT_EQ(actionFor(SDLK_7, KMOD_RCTRL), Action::Bottom);
  EXPECT_EQ(actionFor(SDLK_PAGEDOWN, 0), Action::Next);
  EXPECT_EQ(actionFor(SDLK_LEFT, 0), Action::Previous);
  EXPECT_EQ(actionFor(SDLK_F12, 0), Action::Save);
  EXPECT_EQ(actionFor(SDLK_s, KMOD_LCTRL), Action::Save);
  EXPECT_FALSE(actionFor(SDLK_s, 0));
  EXPECT_FALSE(keyHelp().empty());
}

cli::SceneOptions viewOptions(int width, int height) {
  cli::SceneOptions o;
  o.width = width, o.height = height;
  return o;
}

TEST(ViewState, TogglesAndEveryChangeIsANewVersion) {
  ViewState s({}, viewOptions(160, 120));
  s.load();
  EXPECT_EQ(s.scene().width, 160);
  std::uint64_t v = s.version();
  s.toggleEdges();
  EXPECT_TRUE(s.scene().overlays.edges);
  EXPECT_GT(s.version(), v);
  s.toggleAntiAliasing();
  EXPECT_EQ(s.scene().multisample, 8);
  s.toggleAntiAliasing();
  EXPECT_EQ(s.scene().multisample, 1);
  v = s.version();
  s.resize(200, 100);
  EXPECT_EQ(s.scene().width, 200);
  EXPECT_GT(s.version(), v);
  s.watch(10, 20);
  ASSERT_TRUE(s.probe());
  EXPECT_EQ(s.probe()->first, 10);
  s.watch(500, 20);  // outside the picture: no change of the watched pixel
  EXPECT_EQ(s.probe()->first, 10);
}

// F: the studio lights every material (an STL has no map of its own), then nothing; the picture
// changes and comes back; the toggle outlives the file.
TEST(ViewState, FTurnsEnvironmentLightingOnAndOff) {
  const std::string duck = std::string(kModels) + "/Collada/duck.dae", spider = std::string(kModels) + "/STL/Spider_binary.stl";
  ViewState s({spider, duck}, viewOptions(96, 64));
  s.load();
  EXPECT_EQ(s.scene().environment.lighting, EnvironmentLighting::None);
  EXPECT_EQ(s.scene().display.toneMap, ToneMap::None);
  const Image before = renderScene(s.drawn());
  const std::uint64_t v = s.version();
  s.toggleEnvironment();
  EXPECT_GT(s.version(), v);
  EXPECT_EQ(s.scene().environment.lighting, EnvironmentLighting::All);
  EXPECT_EQ(s.scene().rayTracing.environmentMap, studioEnvironment());
  EXPECT_EQ(s.scene().display.toneMap, ToneMap::Aces);  // as `illum render --environment studio` shows a preview
  EXPECT_NE(renderScene(s.drawn()).rgba, before.rgba);
  EXPECT_TRUE(s.step(1));
  EXPECT_EQ(s.scene().environment.lighting, EnvironmentLighting::All);
  EXPECT_TRUE(s.step(1));
  s.toggleEnvironment();
  EXPECT_EQ(s.scene().environment.lighting, EnvironmentLighting::None);
  EXPECT_EQ(s.scene().display.toneMap, ToneMap::None);
  EXPECT_EQ(renderScene(s.drawn()).rgba, before.rgba);
  // The path tracer's preview goes through ACES, the rasterizer's back to GL's clamp.
  s.setRenderer(RendererKind::Path);
  EXPECT_EQ(s.scene().display.toneMap, ToneMap::Aces);
  s.setRenderer(RendererKind::Raster);
  EXPECT_EQ(s.scene().display.toneMap, ToneMap::None);
}

TEST(ViewState, StepsThroughFilesAndKeepsToggles) {
  const std::string duck = std::string(kModels) + "/Collada/duck.dae", spider = std::string(kModels) + "/STL/Spider_binary.stl";
  ViewState s({duck, spider}, viewOptions(160, 120));
  s.load();
  EXPECT_TRUE(s.isModel());
  s.toggleEdges();
  EXPECT_TRUE(s.step(1));
  EXPECT_EQ(s.current(), spider);
  EXPECT_TRUE(s.scene().overlays.edges);  // the person's toggle outlives the file
  EXPECT_TRUE(s.step(1));
  EXPECT_EQ(s.current(), duck);  // wraps
  // A file that cannot be drawn leaves the state as it was.
  EXPECT_THROW(s.open("/nonexistent/model.ply"), InputError);
  EXPECT_EQ(s.current(), duck);
  EXPECT_EQ(s.files().size(), 2u);
  // A dropped file opens after the current one.
  const std::string box = std::string(kModels) + "/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb";
  s.open(box);
  EXPECT_EQ(s.current(), box);
  EXPECT_EQ(s.index(), 1u);
  EXPECT_EQ(s.files().size(), 3u);
  EXPECT_EQ(s.files()[2], spider);
}

TEST(ViewState, APreviewsRigTurnsWithTheCamera) {
  ViewState s({std::string(kModels) + "/STL/Spider_binary.stl"}, viewOptions(160, 120));
  s.load();
  const Vec3 before(s.scene().lights[0].position);
  const Vec3 toEye = glm::normalize(s.scene().camera.eye - s.scene().camera.center);
  const Real along = glm::dot(before, toEye);
  s.trackball().orbit(60, 0, 120);
  s.cameraMoved();
  const Vec3 after(s.scene().lights[0].position);
  EXPECT_GT(glm::length(after - before), 0.1);
  // The key light keeps its place relative to the viewer.
  const Vec3 toEyeNow = glm::normalize(s.scene().camera.eye - s.scene().camera.center);
  EXPECT_NEAR(glm::dot(after, toEyeNow), along, 1e-4);
  // Placed by the person, the lights stay where they are.
  s.setLightsFollow(false);
  s.trackball().orbit(60, 0, 120);
  s.cameraMoved();
  EXPECT_EQ(Vec3(s.scene().lights[0].position), after);
}

// A term switched off is zero in the scene's own keys; all on is the scene untouched.
TEST(ViewState, TermsAreTheScenesKeysAtZero) {
  ViewState s({}, viewOptions(160, 120));
  s.load();
  s.edit().objects[0].material.emission = {0.3f, 0.2f, 0.1f, 1};
  const Scene all = s.drawn();
  EXPECT_EQ(all.lights[0].diffuse, s.scene().lights[0].diffuse);
  Terms t;
  t.diffuse = false;
  t.emission = false;
  s.setTerms(t);
  const Scene d = s.drawn();
  for (const Light& l : d.lights) {
    EXPECT_EQ(l.diffuse, Color3(0));
    EXPECT_NE(l.specular, Color3(0));
  }
  EXPECT_EQ(Color3(d.objects[0].material.emission), Color3(0));
  EXPECT_EQ(d.lightModel.ambient, s.scene().lightModel.ambient);
  // The person's values are kept: switched on again, the scene is as it was.
  s.setTerms(Terms{});
  EXPECT_EQ(s.drawn().lights[0].diffuse, all.lights[0].diffuse);
  EXPECT_EQ(s.drawn().objects[0].material.emission, all.objects[0].material.emission);
  // Without diffuse and specular, what is left of a pixel is its emission and ambient terms.
  t = Terms{};
  t.diffuse = t.specular = false;
  s.setTerms(t);
  // (the built-in scene's lights have no ambient colour: e + a_global·k_a).
  PixelProbe probe;
  probe.x = 80, probe.y = 60;
  Image picture;
  Renderer().render(s.drawn(), picture, nullptr, &probe);
  ASSERT_TRUE(probe.hit);
  const Color3 expected = Color3(probe.material.emission) + s.scene().lightModel.ambient * Color3(probe.material.ambient);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(probe.lit[c], expected[c], 1e-6);
}

// A light's handle sits where the light projects (at the picture's edge when it is beside it);
// dragged, the light follows the pointer at its depth.
TEST(ViewState, LightHandlesFollowTheirLightsAndMoveThem) {
  ViewState s({}, viewOptions(320, 180));
  s.load();
  const Handle key = s.handle(0);  // the built-in scene's positional key light, beside the camera
  ASSERT_TRUE(key.inFront);
  EXPECT_FALSE(key.inside);
  EXPECT_TRUE(key.shown.x >= 12 && key.shown.x <= 308 && key.shown.y >= 12 && key.shown.y <= 168);
  s.dragLight(0, 40, 10);
  const Handle moved = s.handle(0);
  EXPECT_NEAR(moved.pixel.x, key.pixel.x + 40, 0.05);
  EXPECT_NEAR(moved.pixel.y, key.pixel.y + 10, 0.05);
  EXPECT_NEAR(moved.depth, key.depth, 1e-4);
  EXPECT_EQ(s.scene().lights[0].position.w, 1);
  // A directional light keeps unit length and its handle follows too.
  const Handle fill = s.handle(1);
  ASSERT_TRUE(fill.inside);
  s.dragLight(1, -30, 0);
  EXPECT_EQ(s.scene().lights[1].position.w, 0);
  EXPECT_NEAR(glm::length(Vec3(s.scene().lights[1].position)), 1, 1e-5);
  EXPECT_NEAR(s.handle(1).pixel.x, fill.pixel.x - 30, 1);
}

// The worker's frame of a scene is what renderScene draws of it; the tracers refine up to it.
TEST(RenderWorker, FramesAreTheRenderersPictures) {
  ViewState s({}, viewOptions(96, 64));
  s.load();
  RenderWorker worker;
  const auto waitFor = [&](Frame& f, bool final) {
    for (int i = 0; i < 2000; ++i) {
      if (worker.take(f) && (!final || f.final)) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return false;
  };
  worker.request(std::make_shared<Scene>(s.scene()), s.version(), std::pair(40, 30));
  Frame f;
  ASSERT_TRUE(waitFor(f, true));
  EXPECT_EQ(f.image.rgba, renderScene(s.scene()).rgba);
  ASSERT_TRUE(f.probe);
  EXPECT_NE(f.report.find("pixel (40, 30)"), std::string::npos) << f.report;
  Scene traced = s.scene();
  traced.renderer = RendererKind::Whitted;
  traced.rayTracing.samples = 16;
  worker.request(std::make_shared<Scene>(traced), s.version() + 1, std::nullopt);
  ASSERT_TRUE(waitFor(f, true));
  EXPECT_EQ(f.samples, 16);
  EXPECT_EQ(f.image.rgba, renderScene(traced).rgba);
  // Each take hands the last picture back to be drawn into: a frame drawn over the traced one's
  // memory is still the renderer's picture, nothing of the old one left.
  Scene turned = s.scene();
  turned.camera.eye = turned.camera.eye + Vec3(0.5, 0.25, 0);
  worker.request(std::make_shared<Scene>(turned), s.version() + 2, std::nullopt);
  ASSERT_TRUE(waitFor(f, true));
  EXPECT_EQ(f.image.rgba, renderScene(turned).rgba);
}

// Saving: a picture and a scene file under the first free names, never over a file; the scene
// reads back to the scene shown; OpenEXR holds the linear values.
TEST(SaveView, PictureAndSceneUnderFreeNames) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("illum_save_view_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  ViewState s({}, viewOptions(96, 64));
  s.load();
  Frame f;
  f.scene = std::make_shared<Scene>(s.drawn());
  f.image = renderScene(*f.scene);
  const Saved png = saveView(f, false, dir);
  EXPECT_EQ(png.picture, dir / "illum_view_1.png");
  EXPECT_EQ(readPng(png.picture).rgba, f.image.rgba);
  EXPECT_EQ(renderScene(loadSceneFile(png.scene)).rgba, f.image.rgba);
  const Saved exr = saveView(f, true, dir);
  EXPECT_EQ(exr.picture, dir / "illum_view_2.exr");
  const FloatImage linear = readExr(exr.picture);
  EXPECT_EQ(linear.width, 96);
  // A scene no file made cannot be saved, and then nothing is written.
  Scene made = *f.scene;
  made.objects[0].source = nullptr;
  f.scene = std::make_shared<Scene>(made);
  EXPECT_THROW(saveView(f, false, dir), Error);
  EXPECT_FALSE(fs::exists(dir / "illum_view_3.png"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace illum::view
