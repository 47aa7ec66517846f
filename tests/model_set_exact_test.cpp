// The model set of bench/compare_models.sh (Debian's assimp-testmodels: textured, physically
// based, normal-mapped, vertex-coloured, translucent) previewed as `illum render MODEL` frames and
// lights it, drawn by the binned pipeline and by the reference driver, at 1, 4 and 8 samples: the
// same bytes (issue 31's "still exact" on the model set, not only on scene files).
#include "cli_support.h"
#include "render/reference_render.h"

#include <illum/render.h>
#include <illum/scene.h>

#include <gtest/gtest.h>

namespace illum {
namespace {

using test::runIllum;
using test::TempDir;
namespace fs = std::filesystem;

const fs::path kModels = "/usr/share/assimp/models";

class ModelSet : public testing::TestWithParam<std::string> {};

TEST_P(ModelSet, BinnedPipelineDrawsTheReferencesBytes) {
  const fs::path model = kModels / GetParam();
  if (!fs::exists(model)) GTEST_SKIP() << model << " is not installed (assimp-testmodels)";
  TempDir dir;
  // The preview as the command builds it (camera, light rig, materials, studio environment,
  // sRGB), saved as a scene file and read back in this process.
  const auto r = runIllum("render " + model.string() + " --resolution 320,192 -o " + (dir / "preview.png").string() +
                          " --save-scene " + (dir / "preview.json").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  Scene scene = loadSceneFile(dir / "preview.json");
  for (int samples : {1, 4, 8}) {
    scene.multisample = samples;
    RenderStats stats, refStats;
    const Image drawn = renderScene(scene, &stats);
    const Image reference = renderSceneReference(scene, &refStats);
    EXPECT_EQ(drawn.rgba, reference.rgba) << GetParam() << " at " << samples << " samples";
    EXPECT_EQ(stats.fragmentsShaded, refStats.fragmentsShaded) << GetParam() << " at " << samples << " samples";
  }
}

INSTANTIATE_TEST_SUITE_P(AssimpTestModels, ModelSet,
                         testing::Values("glTF2/BoxTextured-glTF-Binary/BoxTextured.glb",
                                         "glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb", "Collada/duck.dae",
                                         "OBJ/spider.obj", "STL/Spider_binary.stl", "PLY/Wuson.ply",
                                         "Collada/kwxport_test_vcolors.dae", "glTF2/ClearCoat-glTF/ClearCoatTest.gltf"),
                         [](const testing::TestParamInfo<std::string>& info) {
                           std::string name = fs::path(info.param).stem().string();
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

}  // namespace
}  // namespace illum
