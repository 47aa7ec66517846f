// Whitted's and Hall's ray tracers against closed forms: the rasterizer's Phong shading when no
// ray leaves the surface, a shadow's place and size, a mirror's image, a slab's offset (Snell),
// Fresnel reflectance and filter attenuation; and the same bytes on every thread count.
#include <illum/render.h>
#include <illum/scene.h>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <filesystem>

namespace illum {
namespace {

namespace fs = std::filesystem;

// A quad p0 p1 p2 p3, counter-clockwise seen from its front, with its face normal.
std::shared_ptr<const Mesh> quad(Vec3 p0, Vec3 p1, Vec3 p2, Vec3 p3) {
  Mesh m;
  m.positions = {p0, p1, p2, p3};
  const Vec3 n = glm::normalize(glm::cross(p1 - p0, p2 - p0));
  m.normals = {n, n, n, n};
  m.indices = {0, 1, 2, 0, 2, 3};
  return std::make_shared<const Mesh>(std::move(m));
}

Material black() {
  Material m;
  m.ambient = m.diffuse = Color4(0, 0, 0, 1);
  return m;
}

Material glowing(Color3 c) {
  Material m = black();
  m.emission = Color4(c, 1);
  return m;
}

// An orthographic camera on +z looking down −z at a view `height` units tall.
Scene orthographicScene(int size, Real height) {
  Scene s;
  s.width = s.height = size;
  s.camera.eye = {0, 0, 10};
  s.camera.center = {0, 0, 0};
  s.camera.projection = Projection::Orthographic;
  s.camera.viewHeight = height;
  s.camera.near = 1;
  s.camera.far = 30;
  s.background = {0, 0, 0, 1};
  s.lightModel.ambient = Color3(0);
  s.lights.clear();
  s.renderer = RendererKind::Whitted;
  return s;
}

// The pixel that world point (x, y) lands on under orthographicScene's camera.
const std::uint8_t* pixelAt(const Image& image, Real height, Real x, Real y) {
  const Real perUnit = Real(image.width) / height;
  return image.pixel(int(std::floor((x + height / 2) * perUnit)), int(std::floor((height / 2 - y) * perUnit)));
}

std::vector<fs::path> parityScenes() {
  std::vector<fs::path> files;
  for (const fs::path& dir : {fs::path(ILLUM_REPO_DIR) / "tests/scenes/parity", fs::path(ILLUM_REPO_DIR) / "examples"})
    for (const auto& e : fs::directory_iterator(dir))
      if (e.path().extension() == ".json") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

// What the parity scenes do not have: a mipmapped texture on a receding floor, vertex colours,
// and a translucent quad blended over an opaque cube. (A translucent closed mesh would differ: GL
// blends whichever of its back faces were drawn before the front ones, the ray tracer all of them.)
Scene texturedColouredBlended() {
  Scene s;
  s.width = 240, s.height = 180;
  s.camera.eye = {0, 2.2f, 5};
  s.lights[0].position = {2, 3, 4, 1};
  Material shiny;
  shiny.specular = {0.5f, 0.5f, 0.5f, 1};
  shiny.shininess = 24;
  Image pattern(64, 64);
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      std::uint8_t* p = pattern.pixel(x, y);
      p[0] = std::uint8_t(((x / 8 + y / 8) % 2) ? 230 : 40), p[1] = std::uint8_t(x * 4), p[2] = std::uint8_t(y * 4);
      p[3] = 255;
    }
  auto floor = std::make_shared<Mesh>();
  for (int j = 0; j <= 8; ++j)
    for (int i = 0; i <= 8; ++i) {
      floor->positions.push_back({Real(i - 4) * Real(1.5), -1, Real(j - 7) * Real(1.5)});
      floor->normals.push_back({0, 1, 0});
      floor->uvs.push_back({Real(i) / 2, Real(j) / 2});
    }
  for (std::uint32_t j = 0; j < 8; ++j)
    for (std::uint32_t i = 0; i < 8; ++i) {
      const std::uint32_t a = j * 9 + i;
      floor->indices.insert(floor->indices.end(), {a, a + 9, a + 10, a, a + 10, a + 1});
    }
  s.objects.push_back({floor, Mat4(1), shiny, std::make_shared<const Texture>(pattern), {}, {}, {}});
  auto ball = std::make_shared<Mesh>(makeSphere(0.7f, 32, 16));
  for (const Vec3& p : ball->positions) {
    const Vec3 d = glm::normalize(p);
    ball->colors.push_back({Real(0.5) + d.x / 2, Real(0.5) + d.y / 2, Real(0.5) + d.z / 2, 1});
  }
  s.objects.push_back({ball, glm::translate(Mat4(1), Vec3(-1.2f, 0, 0)), shiny, nullptr, {}, {}, {}});
  s.blend = true;
  s.objects.push_back({std::make_shared<const Mesh>(makeCube(1)), glm::translate(Mat4(1), Vec3(1, 0, -1)), shiny, nullptr, {}, {}, {}});
  Material glassy = shiny;
  glassy.diffuse.a = 0.5f;
  s.objects.push_back({quad({0.2f, -0.8f, 0.5f}, {1.8f, -0.8f, 0.5f}, {1.8f, 0.8f, 0.5f}, {0.2f, 0.8f, 0.5f}), Mat4(1),
                       glassy, nullptr, {}, {}, {}});
  return s;
}

TEST(RayTracer, WithoutShadowsMirrorsAndGlassItDrawsTheRasterizersPhongShading) {
  std::vector<std::pair<std::string, Scene>> scenes = {{"built-in", defaultScene()},
                                                       {"textured, coloured, blended", texturedColouredBlended()}};
  for (const fs::path& f : parityScenes()) scenes.push_back({f.filename().string(), loadSceneFile(f)});
  for (auto& [name, scene] : scenes) {
    scene.shading = Shading::Phong;
    for (Object& o : scene.objects) o.optics = SurfaceOptics{};
    scene.labels.clear();  // the captions name the renderer that drew the picture: they differ, truly
    for (LightingModel model : {LightingModel::BlinnPhong, LightingModel::Phong, LightingModel::Lambert}) {
      scene.model = model;
      scene.renderer = RendererKind::Raster;
      const Image raster = renderScene(scene);
      for (RendererKind kind : {RendererKind::Whitted, RendererKind::Hall}) {
        scene.renderer = kind;
        scene.rayTracing.shadows = false;
        scene.rayTracing.samples = 1;  // through the pixel centres, as the rasterizer samples
        const Image traced = renderScene(scene);
        const ImageDifference d = compareImages(traced, raster, 1);
        EXPECT_GE(d.fractionWithin, 0.999) << name << " " << toString(model) << " " << toString(kind)
                                           << ": max error " << d.maxError;
      }
    }
  }
}

TEST(RayTracer, ASpheresShadowUnderADirectionalLightIsWhereAndAsLargeAsGeometrySays) {
  // A sphere of radius r centred h above the floor y = 0, the light 45° from the vertical, the
  // camera looking straight down: the shadow is an ellipse centred h·tan 45° = h to the side,
  // with semi-axes r / cos 45° along the light's azimuth and r across it.
  const Real r = 0.5f, h = 2, view = 8;
  Scene s = orthographicScene(400, view);
  s.camera.eye = {0, 10, 0};
  s.camera.up = {0, 0, -1};
  Material floor = black();
  floor.diffuse = {1, 1, 1, 1};
  s.objects.push_back({quad({-4, 0, 4}, {4, 0, 4}, {4, 0, -4}, {-4, 0, -4}), Mat4(1), floor, nullptr, {}, {}, {}});
  s.objects.push_back({std::make_shared<const Mesh>(makeSphere(r, 256, 128)),
                       glm::translate(Mat4(1), Vec3(0, h, 0)), glowing({0, 0, 1}), nullptr, {}, {}, {}});
  Light sun;
  sun.position = {1, 1, 0, 0};  // towards the light: up and to +x, so the shadow falls to −x
  sun.specular = Color3(0);
  s.lights = {sun};
  const Image image = renderScene(s);
  // The camera looks down −y with up = −z: image x is world x, image up is world −z.
  const auto floorAt = [&](Real x, Real z) { return pixelAt(image, view, x, -z)[0]; };
  const Real a = r / std::cos(glm::radians(Real(45))), cx = -h;
  const int lit = int(std::lround(255 * std::cos(glm::radians(Real(45)))));  // N·L = cos 45°
  EXPECT_EQ(floorAt(cx, 0), 0);
  for (Real f : {0.93f, -0.93f}) {
    EXPECT_EQ(floorAt(cx + f * a, 0), 0) << f;
    EXPECT_EQ(floorAt(cx, f * r), 0) << f;
  }
  for (Real f : {1.07f, -1.07f}) {
    EXPECT_NEAR(floorAt(cx + f * a, 0), lit, 1) << f;
    EXPECT_NEAR(floorAt(cx, f * r), lit, 1) << f;
  }
  EXPECT_NEAR(floorAt(2, 0), lit, 1);  // the other side of the sphere is in the light
}

TEST(RayTracer, AMirrorAt45DegreesShowsTheObjectItFaces) {
  // The mirror y + z = 0 turns the camera's rays (0,0,−1) into (0,1,0): a glowing sphere above it
  // at (1, 5, −0.5) appears at image point (1, 0.5), as large as it is.
  const Real view = 4;
  Scene s = orthographicScene(200, view);
  Material mirror = black();
  SurfaceOptics mirrorOptics;
  mirrorOptics.reflective = Color3(1);
  s.objects.push_back({quad({-2, -2, 2}, {2, -2, 2}, {2, 2, -2}, {-2, 2, -2}), Mat4(1), mirror, nullptr, mirrorOptics, {}, {}});
  s.objects.push_back({std::make_shared<const Mesh>(makeSphere(0.3f, 64, 32)),
                       glm::translate(Mat4(1), Vec3(1, 5, -0.5f)), glowing({1, 0, 0}), nullptr, {}, {}, {}});
  const Image image = renderScene(s);
  EXPECT_EQ(pixelAt(image, view, 1, 0.5f)[0], 255);
  EXPECT_EQ(pixelAt(image, view, 1.25f, 0.5f)[0], 255);
  EXPECT_EQ(pixelAt(image, view, 1, 0.75f)[0], 255);
  EXPECT_EQ(pixelAt(image, view, 1.35f, 0.5f)[0], 0);
  EXPECT_EQ(pixelAt(image, view, 1, 0.85f)[0], 0);
  EXPECT_EQ(pixelAt(image, view, -1, 0.5f)[0], 0);
  // Without the mirror's k_r nothing shows.
  s.objects[0].optics = SurfaceOptics{};
  EXPECT_EQ(pixelAt(renderScene(s), view, 1, 0.5f)[0], 0);
}

TEST(RayTracer, AGlassSlabOffsetsALineBySnellsFormula) {
  // A slab of thickness d and index n, turned θ about the vertical, in front of a thin glowing
  // vertical line at x = 0: rays cross it displaced sideways by d·sin(θ − θ_t)/cos θ_t.
  const Real d = 1, n = 1.5f, theta = glm::radians(Real(40)), view = 4;
  const int size = 800;
  Scene s = orthographicScene(size, view);
  SurfaceOptics glass;
  glass.transmissive = Color3(1);
  glass.ior = n;
  const Mat4 slab = glm::scale(glm::rotate(Mat4(1), theta, Vec3(0, 1, 0)), Vec3(6, 6, d));
  s.objects.push_back({std::make_shared<const Mesh>(makeCube(1)), slab, black(), nullptr, glass, {}, {}});
  const Real lineWidth = 0.02f;
  s.objects.push_back({quad({-lineWidth / 2, -3, -5}, {lineWidth / 2, -3, -5}, {lineWidth / 2, 3, -5}, {-lineWidth / 2, 3, -5}),
                       Mat4(1), glowing({0, 1, 0}), nullptr, {}, {}, {}});
  const Image image = renderScene(s);
  const Real thetaT = std::asin(std::sin(theta) / n);
  const Real expected = d * std::sin(theta - thetaT) / std::cos(thetaT);
  // The line's centre along the middle row, in world units.
  double sum = 0, count = 0;
  for (int x = 0; x < size; ++x)
    if (image.pixel(x, size / 2)[1] > 128) sum += x + 0.5, ++count;
  ASSERT_GT(count, 0);
  const Real centre = Real(sum / count) * view / Real(size) - view / 2;
  const Real pixel = view / Real(size);
  EXPECT_NEAR(std::abs(centre), expected, 1.5f * pixel) << "centre " << centre;
  EXPECT_GT(expected, 10 * pixel);  // a real offset, not a rounding
}

TEST(RayTracer, HallReflectsTheFresnelFractionAtNormalIncidence) {
  // A dielectric mirror seen head-on reflects ((n−1)/(n+1))² of the white background behind the
  // camera: 0.04 for n = 1.5, byte 10. Whitted's mirror reflects k_r whole.
  Scene s = orthographicScene(32, 2);
  s.background = {1, 1, 1, 1};
  SurfaceOptics optics;
  optics.reflective = Color3(1);
  optics.ior = 1.5f;
  s.objects.push_back({quad({-2, -2, 0}, {2, -2, 0}, {2, 2, 0}, {-2, 2, 0}), Mat4(1), black(), nullptr, optics, {}, {}});
  s.renderer = RendererKind::Hall;
  EXPECT_EQ(renderScene(s).pixel(16, 16)[0], 10);
  s.renderer = RendererKind::Whitted;
  EXPECT_EQ(renderScene(s).pixel(16, 16)[0], 255);
}

TEST(RayTracer, HallsFilterAttenuatesByTheDistanceTravelledInside) {
  // A slab 2 units thick of filter 0.5 and index 1 (no refraction, no reflection): T^d = 0.25 of
  // the white background comes through, byte 64; Whitted has no filter.
  Scene s = orthographicScene(32, 2);
  s.background = {1, 1, 1, 1};
  SurfaceOptics optics;
  optics.transmissive = Color3(1);
  optics.ior = 1;
  optics.filter = Color3(0.5f, 0.25f, 1);
  s.objects.push_back({std::make_shared<const Mesh>(makeCube(1)), glm::scale(Mat4(1), Vec3(8, 8, 2)), black(), nullptr, optics, {}, {}});
  s.renderer = RendererKind::Hall;
  const Image hall = renderScene(s);
  EXPECT_EQ(hall.pixel(16, 16)[0], 64);   // 0.5²
  EXPECT_EQ(hall.pixel(16, 16)[1], 16);   // 0.25² = 0.0625 → 15.9
  EXPECT_EQ(hall.pixel(16, 16)[2], 255);
  s.renderer = RendererKind::Whitted;
  EXPECT_EQ(renderScene(s).pixel(16, 16)[0], 255);
}

TEST(RayTracer, TheSameBytesOnEveryThreadCountAndRun) {
  Scene scene = defaultScene();
  scene.width = 320, scene.height = 180;
  scene.objects[0].optics.reflective = Color3(0.5f);
  scene.objects[2].optics.transmissive = Color3(0.8f);
  scene.objects[2].optics.reflective = Color3(0.8f);
  for (RendererKind kind : {RendererKind::Whitted, RendererKind::Hall})
    for (int samples : {1, 4}) {
      scene.renderer = kind;
      scene.rayTracing.samples = samples;
      const Image all = renderScene(scene);
      for (int threads : {1, 3}) {
        const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
        EXPECT_EQ(renderScene(scene).rgba, all.rgba) << toString(kind) << " " << samples << " samples, " << threads;
      }
    }
}

}  // namespace
}  // namespace illum
