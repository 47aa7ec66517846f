// Parity against Mesa's llvmpipe: every parity scene × every lighting model × every shading
// frequency, rendered by illum and by Mesa. Bar: ≥ 99.9% of pixels within 2/255 on every
// channel and PSNR ≥ 50 dB. On failure the two images and their difference are written beside
// the test binary, in parity-out/.
#include "mesa_reference.h"

#include <illum/image.h>
#include <illum/render.h>
#include <illum/scene.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <tuple>

#include <glm/gtc/matrix_transform.hpp>
#include <cmath>

namespace illum {
namespace {

namespace fs = std::filesystem;

constexpr int kTolerance = 2;
constexpr double kMinFractionWithin = 0.999;
constexpr double kMinPsnr = 50;

using ParityCase = std::tuple<std::string, LightingModel, Shading>;

std::vector<std::string> parityScenes() {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(fs::path(ILLUM_TEST_SCENES_DIR) / "parity"))
    if (entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

class MesaParity : public testing::TestWithParam<ParityCase> {};

TEST_P(MesaParity, MatchesLlvmpipe) {
  const auto& [name, model, shading] = GetParam();
  Scene scene = loadSceneFile(fs::path(ILLUM_TEST_SCENES_DIR) / "parity" / (name + ".json"));
  scene.model = model;
  scene.shading = shading;

  const Image ours = renderScene(scene);
  const Image mesa = test::renderWithMesa(scene, test::mesaPathFor(scene));
  const ImageDifference d = compareImages(ours, mesa, kTolerance);
  RecordProperty("psnr", std::to_string(d.psnr));
  RecordProperty("fraction_within", std::to_string(d.fractionWithin));
  RecordProperty("max_error", std::to_string(d.maxError));

  const bool pass = d.fractionWithin >= kMinFractionWithin && d.psnr >= kMinPsnr;
  if (!pass) {
    const fs::path out = fs::current_path() / "parity-out";
    fs::create_directories(out);
    const std::string stem = name + "_" + std::string(toString(model)) + "_" + std::string(toString(shading));
    writePng(out / (stem + "_illum.png"), ours);
    writePng(out / (stem + "_mesa.png"), mesa);
    writePng(out / (stem + "_diff.png"), differenceImage(ours, mesa));
    ADD_FAILURE() << "images written to " << (out / stem).string() << "_{illum,mesa,diff}.png";
  }
  EXPECT_GE(d.fractionWithin, kMinFractionWithin) << "max error " << d.maxError << "/255";
  EXPECT_GE(d.psnr, kMinPsnr);
}

std::string caseName(const testing::TestParamInfo<ParityCase>& info) {
  std::string s = std::get<0>(info.param) + "_" + std::string(toString(std::get<1>(info.param))) + "_" +
                  std::string(toString(std::get<2>(info.param)));
  for (char& c : s)
    if (c == '-') c = '_';
  return s;
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, MesaParity,
    testing::Combine(testing::ValuesIn(parityScenes()),
                     testing::Values(LightingModel::BlinnPhong, LightingModel::Phong, LightingModel::Lambert),
                     testing::Values(Shading::Flat, Shading::Gouraud, Shading::Phong)),
    caseName);

// Features the scene files of parity/ do not reach, on GL's fixed-function path (Blinn-Phong, flat
// and Gouraud): textures with GL_MODULATE and mipmaps, vertex colours with GL_COLOR_MATERIAL, and
// alpha blending, built here because the scene format has no textures or vertex colours.
Scene featureScene(const std::string& name) {
  Scene s;
  s.width = 240, s.height = 180;
  s.background = {0.1f, 0.1f, 0.15f, 1};
  s.camera.eye = {0, 2.2f, 5};
  s.camera.center = {0, 0, 0};
  s.camera.fovy = 45;
  s.lights[0].position = {2, 3, 4, 1};
  s.lights[0].attenuation = {1, 0.05f, 0};
  Light fill;
  fill.position = {-1, 0.5f, 0.3f, 0};
  fill.diffuse = {0.3f, 0.3f, 0.5f};
  fill.specular = {0, 0, 0};
  s.lights.push_back(fill);
  Material shiny;
  shiny.specular = {0.5f, 0.5f, 0.5f, 1};
  shiny.shininess = 24;
  const auto sphere = [](Real r) {
    auto m = std::make_shared<Mesh>(makeSphere(r, 32, 16));
    for (const Vec3& p : m->positions) {
      const Vec3 d = glm::normalize(p);
      m->uvs.push_back({std::atan2(d.y, d.x) / Real(2 * M_PI) + Real(0.5), std::acos(glm::clamp(d.z, Real(-1), Real(1))) / Real(M_PI)});
      m->colors.push_back({Real(0.5) + d.x / 2, Real(0.5) + d.y / 2, Real(0.5) + d.z / 2, 1});
    }
    return m;
  };
  if (name == "textured" || name == "wrapped") {
    Image pattern(64, 64);
    for (int y = 0; y < 64; ++y)
      for (int x = 0; x < 64; ++x) {
        std::uint8_t* p = pattern.pixel(x, y);
        p[0] = std::uint8_t(((x / 8 + y / 8) % 2) ? 230 : 40), p[1] = std::uint8_t(x * 4), p[2] = std::uint8_t(y * 4), p[3] = 255;
      }
    // "wrapped": GL_MIRRORED_REPEAT across and GL_CLAMP_TO_EDGE up, the floor's uvs from −1.5 to 2.5.
    const bool wrapped = name == "wrapped";
    auto texture = std::make_shared<const Texture>(
        pattern, TexelEncoding::Linear,
        wrapped ? TextureWraps{TextureWrap::MirroredRepeat, TextureWrap::ClampToEdge} : TextureWraps{});
    // A floor of 16×16 quads with uvs repeating 4 times: far away it needs the smaller mip levels.
    auto floor = std::make_shared<Mesh>();
    for (int j = 0; j <= 16; ++j)
      for (int i = 0; i <= 16; ++i) {
        floor->positions.push_back({Real(i - 8) * Real(0.75), -1, Real(j - 14) * Real(0.75)});
        floor->normals.push_back({0, 1, 0});
        floor->uvs.push_back({Real(i) / 4 - (wrapped ? Real(1.5) : Real(0)), Real(j) / 4 - (wrapped ? Real(1.5) : Real(0))});
      }
    for (std::uint32_t j = 0; j < 16; ++j)
      for (std::uint32_t i = 0; i < 16; ++i) {
        const std::uint32_t a = j * 17 + i;
        floor->indices.insert(floor->indices.end(), {a, a + 17, a + 18, a, a + 18, a + 1});
      }
    Object f;
    f.mesh = floor;
    f.material = shiny;
    f.diffuseTexture = texture;
    s.objects.push_back(f);
    Object ball;
    auto ballMesh = sphere(1);
    ballMesh->colors.clear();
    ball.mesh = ballMesh;
    ball.material = shiny;
    ball.diffuseTexture = texture;
    s.objects.push_back(ball);
  } else if (name == "vertex_colors") {
    Object ball;
    auto ballMesh = sphere(1.2f);
    ballMesh->uvs.clear();
    ball.mesh = ballMesh;
    ball.material = shiny;
    s.objects.push_back(ball);
  } else {  // blended: an opaque cube, then translucent spheres from the farthest to the nearest
    s.blend = true;
    Object cube;
    cube.mesh = std::make_shared<Mesh>(makeCube(1.5f));
    cube.material.diffuse = {0.2f, 0.6f, 0.3f, 1};
    cube.worldFromObject = glm::translate(Mat4(1), Vec3(0, 0, -1.5f));
    s.objects.push_back(cube);
    for (const auto& [x, z, alpha] : {std::tuple{0.8f, -0.5f, 0.4f}, std::tuple{-0.4f, 0.8f, 0.6f}}) {
      Object ball;
      ball.mesh = std::make_shared<Mesh>(makeSphere(0.8f, 24, 12));
      ball.material = shiny;
      ball.material.diffuse = {0.9f, 0.3f, 0.2f, alpha};
      ball.worldFromObject = glm::translate(Mat4(1), Vec3(x, 0, z));
      s.objects.push_back(ball);
    }
  }
  return s;
}

using FeatureCase = std::tuple<std::string, Shading>;
class MesaParityFeatures : public testing::TestWithParam<FeatureCase> {};

TEST_P(MesaParityFeatures, MatchesLlvmpipe) {
  const auto& [name, shading] = GetParam();
  Scene scene = featureScene(name);
  scene.shading = shading;
  const Image ours = renderScene(scene);
  const Image mesa = test::renderWithMesa(scene, test::MesaPath::FixedFunction);
  const ImageDifference d = compareImages(ours, mesa, kTolerance);
  RecordProperty("psnr", std::to_string(d.psnr));
  RecordProperty("fraction_within", std::to_string(d.fractionWithin));
  RecordProperty("max_error", std::to_string(d.maxError));
  if (d.fractionWithin < kMinFractionWithin || d.psnr < kMinPsnr) {
    const fs::path out = fs::current_path() / "parity-out";
    fs::create_directories(out);
    const std::string stem = name + "_" + std::string(toString(shading));
    writePng(out / (stem + "_illum.png"), ours);
    writePng(out / (stem + "_mesa.png"), mesa);
    writePng(out / (stem + "_diff.png"), differenceImage(ours, mesa));
  }
  EXPECT_GE(d.fractionWithin, kMinFractionWithin) << "max error " << d.maxError << "/255";
  EXPECT_GE(d.psnr, kMinPsnr);
}

INSTANTIATE_TEST_SUITE_P(Features, MesaParityFeatures,
                         testing::Combine(testing::Values("textured", "wrapped", "vertex_colors", "blended"),
                                          testing::Values(Shading::Flat, Shading::Gouraud)),
                         [](const testing::TestParamInfo<FeatureCase>& info) {
                           return std::get<0>(info.param) + "_" + std::string(toString(std::get<1>(info.param)));
                         });

}  // namespace
}  // namespace illum
