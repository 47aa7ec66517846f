#include <illum/file_names.h>

#include <gtest/gtest.h>

namespace illum {
namespace {

TEST(FileNames, ExtensionsCompareWithoutCase) {
  EXPECT_EQ(lowerExtension("models/DUCK.DAE"), ".dae");
  EXPECT_EQ(lowerExtension("archive.tar.GZ"), ".gz");
  EXPECT_EQ(lowerExtension("README"), "");
  EXPECT_TRUE(isSceneFileName("scenes/Cornell.JSON"));
  EXPECT_FALSE(isSceneFileName("scenes/cornell.json.bak"));
  EXPECT_EQ(asciiLower("ÄBC"), "Äbc");  // bytes beyond ASCII are left as they are
}

}  // namespace
}  // namespace illum
