#include "scene/model_format.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <unistd.h>

namespace illum {
namespace {

namespace fs = std::filesystem;
const fs::path kModels = "/usr/share/assimp/models";

// Every format the content is told by, on Debian's assimp-testmodels.
TEST(ModelFormat, TheContentSaysTheFormat) {
  const std::pair<const char*, const char*> cases[] = {
      {"glTF2/BoxTextured-glTF-Binary/BoxTextured.glb", ".glb"},
      {"glTF2/BoxTextured-glTF/BoxTextured.gltf", ".gltf"},
      {"PLY/cube.ply", ".ply"},
      {"PLY/cube_binary.ply", ".ply"},
      {"STL/Spider_ascii.stl", ".stl"},
      {"STL/Spider_binary.stl", ".stl"},
      {"OBJ/spider.obj", ".obj"},
      {"FBX/box.fbx", ".fbx"},
      {"3DS/fels.3ds", ".3ds"},
      {"Collada/duck.dae", ".dae"},
  };
  for (const auto& [file, format] : cases) {
    ASSERT_TRUE(fs::exists(kModels / file)) << file;
    EXPECT_EQ(sniffModelFormat(kModels / file), format) << file;
    EXPECT_EQ(modelFormatOf(kModels / file), format) << file;
  }
  EXPECT_EQ(sniffModelFormat(kModels / "Collada/duckCM.tga"), "");  // a texture is no model
}

// The name's extension wins where the content agrees or says nothing sure; the content where it
// disagrees or the name has none.
TEST(ModelFormat, TheNameYieldsOnlyToTheContent) {
  const fs::path dir = fs::temp_directory_path() / ("illum_format_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  fs::copy_file(kModels / "Collada/duck.dae", dir / "duck.stl", fs::copy_options::overwrite_existing);
  fs::copy_file(kModels / "glTF2/BoxTextured-glTF-Binary/BoxTextured.glb", dir / "box", fs::copy_options::overwrite_existing);
  fs::copy_file(kModels / "OBJ/spider.obj", dir / "spider", fs::copy_options::overwrite_existing);
  fs::copy_file(kModels / "OBJ/spider.obj", dir / "spider.ply", fs::copy_options::overwrite_existing);
  EXPECT_EQ(modelFormatOf(dir / "duck.stl"), ".dae");
  EXPECT_EQ(modelFormatOf(dir / "box"), ".glb");
  EXPECT_EQ(modelFormatOf(dir / "spider"), ".obj");
  EXPECT_EQ(modelFormatOf(dir / "spider.ply"), ".ply");  // OBJ's text guess yields to a known name
  fs::remove_all(dir);
}

}  // namespace
}  // namespace illum
