#include "scene/texture_lookup.h"

#include <gtest/gtest.h>

#include <fstream>
#include <unistd.h>

namespace illum {
namespace {

namespace fs = std::filesystem;

class TextureLookupTest : public testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("illum_texlookup_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "maps" / "deep");
    for (const char* f : {"IMAGE1.jpg", "maps/Wood.PNG", "maps/deep/hidden.png"}) std::ofstream(dir_ / f) << "x";
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(TextureLookupTest, StoredPathFirst) {
  EXPECT_EQ(findTextureFile("maps/Wood.PNG", dir_).found, dir_ / "maps" / "Wood.PNG");
  EXPECT_EQ(findTextureFile((dir_ / "IMAGE1.jpg").string(), "/nowhere").found, dir_ / "IMAGE1.jpg");
}

TEST_F(TextureLookupTest, CaseIsIgnoredWhenTheExactNameIsMissing) {
  // 3DS/test1.3ds asks for IMAGE1.JPG next to IMAGE1.jpg.
  EXPECT_EQ(findTextureFile("IMAGE1.JPG", dir_).found, dir_ / "IMAGE1.jpg");
  EXPECT_EQ(findTextureFile("MAPS/wood.png", dir_).found, dir_ / "maps" / "Wood.PNG");
}

TEST_F(TextureLookupTest, BackslashesAreSeparators) {
  EXPECT_EQ(findTextureFile("maps\\Wood.PNG", dir_).found, dir_ / "maps" / "Wood.PNG");
  // Rooted on the author's drive but meant from the model's folder.
  EXPECT_EQ(findTextureFile("\\maps\\wood.png", dir_).found, dir_ / "maps" / "Wood.PNG");
}

TEST_F(TextureLookupTest, WindowsAndForeignAbsolutePathsFallBackToTheFileName) {
  EXPECT_EQ(findTextureFile("D:\\projects\\models\\wood.png", dir_).found, dir_ / "maps" / "Wood.PNG");
  EXPECT_EQ(findTextureFile("/home/author/image1.jpg", dir_).found, dir_ / "IMAGE1.jpg");
}

TEST_F(TextureLookupTest, OnlyOneLevelOfSubfoldersIsSearched) {
  const TextureLookup r = findTextureFile("C:\\hidden.png", dir_);
  EXPECT_FALSE(r.found);
  ASSERT_FALSE(r.tried.empty());
  EXPECT_NE(r.tried.back().find("hidden.png in " + dir_.string()), std::string::npos) << r.tried.back();
}

}  // namespace
}  // namespace illum
