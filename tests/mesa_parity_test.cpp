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

}  // namespace
}  // namespace illum
