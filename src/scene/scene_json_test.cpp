// A scene written back as a scene file reads back to the same scene, value for value; and the keys
// that make it possible (a matrix step, a model file's materials part by part, its import keys)
// are checked like every other key.
#include <illum/error.h>
#include <illum/import.h>
#include <illum/scene.h>

#include <gtest/gtest.h>

#include "scene/scene_test_support.h"

namespace illum {
namespace {

using test::errorOf;
using test::parse;

const char* kDuck = "/usr/share/assimp/models/Collada/duck.dae";    // one mesh, textured
const char* kSpider = "/usr/share/assimp/models/OBJ/spider.obj";  // several meshes and materials

void expectSameScene(const Scene& a, const Scene& b) {
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.height, b.height);
  EXPECT_EQ(a.background, b.background);
  EXPECT_EQ(a.model, b.model);
  EXPECT_EQ(a.shading, b.shading);
  EXPECT_EQ(a.renderer, b.renderer);
  EXPECT_EQ(a.multisample, b.multisample);
  EXPECT_EQ(a.camera.eye, b.camera.eye);
  EXPECT_EQ(a.camera.center, b.camera.center);
  EXPECT_EQ(a.camera.up, b.camera.up);
  EXPECT_EQ(a.camera.fovy, b.camera.fovy);
  EXPECT_EQ(a.camera.near, b.camera.near);
  EXPECT_EQ(a.camera.far, b.camera.far);
  EXPECT_EQ(a.lightModel.ambient, b.lightModel.ambient);
  EXPECT_EQ(a.lightModel.twoSided, b.lightModel.twoSided);
  EXPECT_EQ(a.lightModel.localViewer, b.lightModel.localViewer);
  EXPECT_EQ(a.lightModel.convention, b.lightModel.convention);
  EXPECT_EQ(a.rayTracing.environment, b.rayTracing.environment);
  EXPECT_EQ(a.display.encoding, b.display.encoding);
  ASSERT_EQ(a.lights.size(), b.lights.size());
  for (std::size_t i = 0; i < a.lights.size(); ++i) {
    EXPECT_EQ(a.lights[i].position, b.lights[i].position);
    EXPECT_EQ(a.lights[i].diffuse, b.lights[i].diffuse);
    EXPECT_EQ(a.lights[i].specular, b.lights[i].specular);
    EXPECT_EQ(a.lights[i].attenuation, b.lights[i].attenuation);
    EXPECT_EQ(a.lights[i].spotDirection, b.lights[i].spotDirection);
    EXPECT_EQ(a.lights[i].spotCutoff, b.lights[i].spotCutoff);
    EXPECT_EQ(a.lights[i].spotExponent, b.lights[i].spotExponent);
  }
  ASSERT_EQ(a.objects.size(), b.objects.size());
  for (std::size_t i = 0; i < a.objects.size(); ++i) {
    const Object &x = a.objects[i], &y = b.objects[i];
    EXPECT_EQ(x.worldFromObject, y.worldFromObject) << "object " << i;
    EXPECT_EQ(x.material, y.material) << "object " << i;
    EXPECT_EQ(x.optics.reflective, y.optics.reflective) << "object " << i;
    EXPECT_EQ(x.optics.ior, y.optics.ior) << "object " << i;
    EXPECT_EQ(x.mesh->positions, y.mesh->positions) << "object " << i;
    EXPECT_EQ(x.mesh->normals, y.mesh->normals) << "object " << i;
    EXPECT_EQ(x.mesh->indices, y.mesh->indices) << "object " << i;
    EXPECT_EQ(bool(x.diffuseTexture), bool(y.diffuseTexture)) << "object " << i;
  }
  ASSERT_EQ(a.labels.size(), b.labels.size());
  for (std::size_t i = 0; i < a.labels.size(); ++i) {
    EXPECT_EQ(a.labels[i].text, b.labels[i].text);
    EXPECT_EQ(a.labels[i].position, b.labels[i].position);
    EXPECT_EQ(a.labels[i].size, b.labels[i].size);
  }
}

TEST(SceneJson, TheBuiltInSceneReadsBackValueForValue) {
  const Scene scene = defaultScene(LightingModel::Phong, Shading::Gouraud, RendererKind::Whitted);
  const std::string text = sceneJson(scene);
  expectSameScene(scene, parse(text));
  // Written twice, the same text: a saved scene saved again does not drift.
  EXPECT_EQ(sceneJson(parse(text)), text);
  // Readable: numbers as short as they can be and still read back exactly.
  EXPECT_NE(text.find("\"radius\": 0.8,"), std::string::npos);
  EXPECT_NE(text.find("\"fovy\": 40,"), std::string::npos);
}

TEST(SceneJson, ChangedLightsCameraAndMaterialsAreWhatIsWritten) {
  Scene scene = defaultScene();
  scene.camera.eye = {1.25f, -3, 7.1f};
  scene.lights[1].position = {0.3f, -0.2f, 0.9f, 0};
  scene.lights[2].spotCutoff = 12.5f;
  scene.objects[3].material.shininess = 7.75f;
  scene.objects[0].material.emission = {2, 1, 0.5f, 1};  // brighter than white: a colour and a strength
  scene.ambientOcclusion.enabled = true;
  scene.ambientOcclusion.distance = 0.4f;
  scene.lightModel.convention = Convention::NoteHalfSum;  // a lecture note's way, saved by name
  expectSameScene(scene, parse(sceneJson(scene)));
  EXPECT_NE(sceneJson(scene).find("\"convention\": \"note-half-sum\""), std::string::npos);
  EXPECT_EQ(parse(sceneJson(scene)).ambientOcclusion.distance, 0.4f);
}

TEST(SceneJson, AModelFileIsNamedWithOnlyTheMaterialsThatDifferFromItsOwn) {
  const std::string text = std::string(R"({"objects": [{"mesh": {"type": "file", "path": ")") + kSpider + R"("}}]})";
  Scene scene = parse(text);
  ASSERT_GE(scene.objects.size(), 2u);
  const std::string unchanged = sceneJson(scene);
  EXPECT_EQ(unchanged.find("\"materials\""), std::string::npos);
  expectSameScene(scene, parse(unchanged));
  // One part changed: that part's material given, the others null (the file's).
  scene.objects[1].material.diffuse = {0.1f, 0.9f, 0.2f, 1};
  const std::string changed = sceneJson(scene);
  EXPECT_NE(changed.find("\"materials\""), std::string::npos);
  EXPECT_NE(changed.find("null"), std::string::npos);
  const Scene again = parse(changed);
  expectSameScene(scene, again);
  for (std::size_t i = 0; i < scene.objects.size(); ++i)  // textures kept
    EXPECT_EQ(again.objects[i].diffuseTexture != nullptr, scene.objects[i].diffuseTexture != nullptr);
}

TEST(SceneJson, AnObjectNoFileMadeCannotBeWritten) {
  Scene scene = defaultScene();
  scene.objects[2].source = nullptr;
  EXPECT_THROW(sceneJson(scene), Error);
}

TEST(SceneKeys, AMatrixStepIsTheMatrixRowByRow) {
  const Scene s = parse(R"({"objects": [{"transform": [{"matrix": [2, 0, 0, 1,  0, 3, 0, 2,  0, 0, 4, 3,  0, 0, 0, 1]}]}]})");
  const Mat4& m = s.objects[0].worldFromObject;
  EXPECT_EQ(m[0][0], 2);
  EXPECT_EQ(m[1][1], 3);
  EXPECT_EQ(m[2][2], 4);
  EXPECT_EQ(m[3][0], 1);  // the translation: the last column
  EXPECT_EQ(m[3][1], 2);
  EXPECT_EQ(m[3][2], 3);
  // After a step, on the right like the others.
  const Scene t = parse(R"({"objects": [{"transform": [{"translate": [1, 0, 0]},
                                                      {"matrix": [2, 0, 0, 0,  0, 2, 0, 0,  0, 0, 2, 0,  0, 0, 0, 1]}]}]})");
  EXPECT_EQ(t.objects[0].worldFromObject * Vec4(1, 0, 0, 1), Vec4(3, 0, 0, 1));
}

TEST(SceneRejects, BadMatricesModelKeysAndMaterialLists) {
  EXPECT_EQ(errorOf(R"({"objects": [{"transform": [{"matrix": [1, 0, 0]}]}]})"),
            "scene.json: /objects/0/transform/0/matrix: expected 16 numbers, got 3");
  EXPECT_EQ(errorOf(R"({"objects": [{"transform": [{"matrix": [1,0,0,0, 0,0,0,0, 0,0,1,0, 0,0,0,1]}]}]})"),
            "scene.json: /objects/0/transform/0/matrix: expected an invertible upper 3×3 (a flat object has no normals)");
  EXPECT_EQ(errorOf(R"({"objects": [{"mesh": {"type": "cube"}, "materials": [null]}]})"),
            "scene.json: /objects/0/materials: expected \"materials\" only for a model file mesh (one material per mesh of the file)");
  const std::string duck = std::string(R"({"type": "file", "path": ")") + kDuck + "\"";
  EXPECT_EQ(errorOf(R"({"objects": [{"mesh": )" + duck + R"(, "normals": "soft"}}]})"),
            "scene.json: /objects/0/mesh/normals: expected \"auto\", \"flat\", \"smooth\" or \"file\", got \"soft\"");
  EXPECT_EQ(errorOf(R"({"objects": [{"mesh": )" + duck + R"(, "colour_textures": "gamma"}}]})"),
            "scene.json: /objects/0/mesh/colour_textures: expected \"linear\" or \"srgb\", got \"gamma\"");
  const std::string spider = std::string(R"({"type": "file", "path": ")") + kSpider + "\"";
  const std::string wrongCount = errorOf(R"({"objects": [{"mesh": )" + spider + R"(}, "materials": [null]}]})");
  EXPECT_EQ(wrongCount.rfind("scene.json: /objects/0/materials: expected ", 0), 0u) << wrongCount;
  EXPECT_NE(wrongCount.find("one per mesh of the file, got 1"), std::string::npos) << wrongCount;
  EXPECT_EQ(errorOf(R"({"objects": [{"mesh": )" + duck + R"(}, "material": {}, "materials": [null, null]}]})"),
            "scene.json: /objects/0/materials: expected \"material\" or \"materials\", not both");
}

TEST(SceneKeys, AModelFileMeshReadAsAPreviewReadsIt) {
  const std::string duck = std::string(R"({"type": "file", "path": ")") + kDuck + "\"";
  const Scene plain = parse(R"({"objects": [{"mesh": )" + duck + "}}]}");
  const Scene srgb = parse(R"({"objects": [{"mesh": )" + duck + R"(, "colour_textures": "srgb"}}]})");
  const Scene bare = parse(R"({"objects": [{"mesh": )" + duck + R"(, "file_colours": false}}]})");
  const Scene flat = parse(R"({"objects": [{"mesh": )" + duck + R"(, "normals": "flat"}}]})");
  bool textured = false;
  for (std::size_t i = 0; i < plain.objects.size(); ++i) {
    if (!plain.objects[i].diffuseTexture) continue;
    textured = true;
    EXPECT_EQ(plain.objects[i].diffuseTexture->encoding(), TexelEncoding::Linear);
    EXPECT_EQ(srgb.objects[i].diffuseTexture->encoding(), TexelEncoding::Srgb);
    EXPECT_FALSE(bare.objects[i].diffuseTexture);
  }
  EXPECT_TRUE(textured);
  // Flat normals: every vertex its own, so more vertices than the smooth mesh shares.
  EXPECT_GT(flat.objects[0].mesh->positions.size(), plain.objects[0].mesh->positions.size());
}

}  // namespace
}  // namespace illum
