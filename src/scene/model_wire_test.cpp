#include "scene/model_wire.h"

#include <illum/error.h>

#include <gtest/gtest.h>

#include <unistd.h>
#include <sys/mman.h>
#include <sys/stat.h>

namespace illum {
namespace {

std::vector<std::uint8_t> bytesOf(const ImportedModel& model) {
  const int fd = ::memfd_create("wire-test", 0);
  {
    IsolatedWriter w(fd);
    writeModel(model, w);
    w.flush();
  }
  struct stat st{};
  ::fstat(fd, &st);
  std::vector<std::uint8_t> bytes(std::size_t(st.st_size));
  EXPECT_EQ(::pread(fd, bytes.data(), bytes.size(), 0), ssize_t(bytes.size()));
  ::close(fd);
  return bytes;
}

TEST(ModelWire, RoundTripKeepsSharingAndValues) {
  auto mesh = std::make_shared<Mesh>(makeCube(2));
  mesh->uvs.assign(mesh->positions.size(), Vec2(0.25, 0.75));
  mesh->pointIndices = {0, 5, 7};
  mesh->lineIndices = {1, 2, 3, 4};
  Image image(3, 2);
  for (std::size_t i = 0; i < image.rgba.size(); ++i) image.rgba[i] = std::uint8_t(i * 11);
  auto texture = std::make_shared<const Texture>(image);
  ImportedModel model;
  for (int i = 0; i < 2; ++i) {
    Object o;
    o.mesh = mesh;
    o.worldFromObject[3] = Vec4(Real(i), 2, 3, 1);
    o.material.shininess = Real(10 + i);
    o.diffuseTexture = i == 0 ? texture : nullptr;
    model.objects.push_back(o);
  }
  model.boundsMin = Vec3(-1), model.boundsMax = Vec3(2);
  model.vertexCount = 48, model.triangleCount = 24, model.materialCount = 2, model.textureCount = 1;
  model.pointCount = 6, model.lineCount = 4;
  model.transparencyIgnored = true;
  model.warnings = {"one", "two"};

  const ImportedModel back = readModel(bytesOf(model));
  ASSERT_EQ(back.objects.size(), 2u);
  EXPECT_EQ(back.objects[0].mesh, back.objects[1].mesh);  // shared once, still shared
  EXPECT_EQ(back.objects[0].mesh->positions, mesh->positions);
  EXPECT_EQ(back.objects[0].mesh->indices, mesh->indices);
  EXPECT_EQ(back.objects[0].mesh->uvs, mesh->uvs);
  EXPECT_EQ(back.objects[0].mesh->pointIndices, mesh->pointIndices);
  EXPECT_EQ(back.objects[0].mesh->lineIndices, mesh->lineIndices);
  EXPECT_EQ(back.pointCount, 6u);
  EXPECT_EQ(back.lineCount, 4u);
  EXPECT_EQ(back.objects[1].worldFromObject, model.objects[1].worldFromObject);
  EXPECT_EQ(back.objects[1].material.shininess, Real(11));
  ASSERT_TRUE(back.objects[0].diffuseTexture);
  EXPECT_FALSE(back.objects[1].diffuseTexture);
  EXPECT_EQ(back.objects[0].diffuseTexture->baseImage().rgba, image.rgba);  // texels exactly
  EXPECT_EQ(back.boundsMax, Vec3(2));
  EXPECT_EQ(back.triangleCount, 24u);
  EXPECT_TRUE(back.transparencyIgnored);
  EXPECT_EQ(back.warnings, model.warnings);
}

TEST(ModelWire, TruncatedBytesAreRefused) {
  ImportedModel model;
  Object o;
  o.mesh = std::make_shared<Mesh>(makeCube(1));
  model.objects.push_back(o);
  std::vector<std::uint8_t> bytes = bytesOf(model);
  for (std::size_t cut : {std::size_t(0), std::size_t(7), bytes.size() / 2, bytes.size() - 1}) {
    std::vector<std::uint8_t> part(bytes.begin(), bytes.begin() + std::ptrdiff_t(cut));
    EXPECT_THROW(readModel(part), Error) << cut;
  }
}

}  // namespace
}  // namespace illum
