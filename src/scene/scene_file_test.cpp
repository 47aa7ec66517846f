// The scene file contract: every default, and every kind of rejection with its JSON path.
#include <illum/error.h>
#include <illum/scene.h>

#include <gtest/gtest.h>

#include "scene/scene_test_support.h"

#include <cmath>
#include <filesystem>
#include <fstream>

#include <unistd.h>

namespace illum {
namespace {

using test::errorOf;
using test::parse;

TEST(SceneDefaults, EmptyObjectIsTheDocumentedScene) {
  const Scene s = parse("{}");
  EXPECT_EQ(s.width, 640);
  EXPECT_EQ(s.height, 480);
  EXPECT_EQ(s.background, Color4(0, 0, 0, 1));
  EXPECT_EQ(s.model, LightingModel::BlinnPhong);
  EXPECT_EQ(s.shading, Shading::Phong);
  EXPECT_EQ(s.camera.eye, Vec3(0, 0, 5));
  EXPECT_EQ(s.camera.center, Vec3(0, 0, 0));
  EXPECT_EQ(s.camera.up, Vec3(0, 1, 0));
  EXPECT_EQ(s.camera.fovy, 45);
  EXPECT_FLOAT_EQ(s.camera.near, 0.1f);
  EXPECT_EQ(s.camera.far, 100);
  EXPECT_EQ(s.camera.projection, Projection::Perspective);
  EXPECT_FLOAT_EQ(s.lightModel.ambient.r, 0.2f);
  EXPECT_FALSE(s.lightModel.localViewer);
  EXPECT_FALSE(s.lightModel.twoSided);
  ASSERT_EQ(s.lights.size(), 1u);
  EXPECT_TRUE(s.objects.empty());
}

TEST(SceneDefaults, EveryLightGetsGlLight0Defaults) {
  const Scene s = parse(R"({"lights": [{}, {}]})");
  ASSERT_EQ(s.lights.size(), 2u);
  for (const Light& l : s.lights) {
    EXPECT_EQ(l.position, Vec4(0, 0, 1, 0));
    EXPECT_EQ(l.ambient, Color3(0));
    EXPECT_EQ(l.diffuse, Color3(1));
    EXPECT_EQ(l.specular, Color3(1));
    EXPECT_EQ(l.attenuation, Vec3(1, 0, 0));
    EXPECT_EQ(l.spotDirection, Vec3(0, 0, -1));
    EXPECT_EQ(l.spotExponent, 0);
    EXPECT_EQ(l.spotCutoff, 180);
  }
  EXPECT_TRUE(parse(R"({"lights": []})").lights.empty());
}

TEST(SceneDefaults, MaterialIsGlMaterialDefaults) {
  const Scene s = parse(R"({"objects": [{"mesh": {"type": "cube"}}]})");
  const Material& m = s.objects.at(0).material;
  EXPECT_FLOAT_EQ(m.ambient.r, 0.2f);
  EXPECT_FLOAT_EQ(m.diffuse.g, 0.8f);
  EXPECT_EQ(m.specular, Color4(0, 0, 0, 1));
  EXPECT_EQ(m.emission, Color4(0, 0, 0, 1));
  EXPECT_EQ(m.shininess, 0);
  EXPECT_EQ(s.objects[0].worldFromObject, Mat4(1));
}

TEST(SceneDefaults, MeshParametersAreGlutDefaults) {
  const Scene s = parse(R"({"objects": [{"mesh": {"type": "sphere"}}, {"mesh": {"type": "torus"}},
                                        {"mesh": {"type": "cone"}}, {"mesh": {"type": "cube"}}, {}]})");
  EXPECT_EQ(s.objects[0].mesh->positions.size(), std::size_t(20 * 15 + 2));  // slices 20, stacks 16
  EXPECT_EQ(s.objects[1].mesh->positions.size(), std::size_t(17 * 33));      // sides 16, rings 32
  EXPECT_EQ(s.objects[2].mesh->positions.size(), std::size_t(1 + 20 + 20 * 9));  // slices 20, stacks 8
  EXPECT_EQ(s.objects[3].mesh->positions.size(), 24u);
  EXPECT_FLOAT_EQ(s.objects[3].mesh->positions[0].x, 0.5f);  // size 1
  EXPECT_EQ(s.objects[4].mesh->positions.size(), std::size_t(20 * 15 + 2));  // no mesh: the default sphere
}

TEST(SceneFile, ReadsEveryKey) {
  const Scene s = parse(R"({
    "version": 1, "width": 32, "height": 16, "background": [0.1, 0.2, 0.3, 0.5],
    "model": "phong", "shading": "gouraud",
    "camera": {"eye": [1, 2, 3], "center": [0, 1, 0], "up": [0, 0, 1], "fovy": 30, "near": 0.5, "far": 9,
               "projection": "orthographic", "view_height": 4},
    "light_model": {"ambient": [0.1, 0.1, 0.1], "local_viewer": true, "two_sided": true},
    "lights": [{"position": [1, 2, 3, 1], "ambient": [0.1, 0, 0], "diffuse": [0, 0.5, 0], "specular": [0, 0, 0.5],
                "attenuation": [1, 0.5, 0.25], "spot_direction": [0, -1, 0], "spot_exponent": 3, "spot_cutoff": 45}],
    "objects": [{"mesh": {"type": "triangles", "positions": [0,0,0, 1,0,0, 0,1,0], "indices": [0, 1, 2]},
                 "transform": [{"translate": [1, 0, 0]}, {"scale": [2, 2, 2]}],
                 "material": {"ambient": [0.1, 0.1, 0.1], "diffuse": [0.5, 0.5, 0.5, 0.5], "specular": [1, 1, 1, 1],
                              "emission": [0, 0, 0.1, 1], "shininess": 200}}]})");
  EXPECT_EQ(s.width, 32);
  EXPECT_EQ(s.background.a, 0.5f);
  EXPECT_EQ(s.model, LightingModel::Phong);
  EXPECT_EQ(s.shading, Shading::Gouraud);
  EXPECT_EQ(s.camera.projection, Projection::Orthographic);
  EXPECT_EQ(s.camera.viewHeight, 4);
  EXPECT_TRUE(s.lightModel.localViewer);
  EXPECT_TRUE(s.lightModel.twoSided);
  EXPECT_EQ(s.lights[0].spotCutoff, 45);
  EXPECT_EQ(s.lights[0].attenuation, Vec3(1, 0.5, 0.25));
  EXPECT_EQ(s.objects[0].material.shininess, 200);  // not capped at 128
  EXPECT_EQ(s.objects[0].material.ambient.a, 1);    // RGB colours get alpha 1
  // Translate then scale, like glTranslate; glScale: the scale applies first to the vertex.
  const Vec4 p = s.objects[0].worldFromObject * Vec4(1, 0, 0, 1);
  EXPECT_EQ(p, Vec4(3, 0, 0, 1));
  // Normals were left out: generated, facing +Z for this counter-clockwise triangle.
  EXPECT_EQ(s.objects[0].mesh->normals[0], Vec3(0, 0, 1));
}

TEST(SceneRejects, WrongArrayLengthWithPath) {
  EXPECT_EQ(errorOf(R"({"lights": [{}, {}, {"attenuation": [1, 0]}]})"),
            "scene.json: /lights/2/attenuation: expected 3 numbers, got 2");
  EXPECT_EQ(errorOf(R"({"camera": {"eye": [1, 2, 3, 4]}})"), "scene.json: /camera/eye: expected 3 numbers, got 4");
  EXPECT_EQ(errorOf(R"({"background": [1, 1]})"), "scene.json: /background: expected 3 or 4 numbers, got 2");
}

TEST(SceneRejects, UnknownKeys) {
  EXPECT_EQ(errorOf(R"({"widht": 3})").rfind("scene.json: /widht: unknown key \"widht\"", 0), 0u);
  EXPECT_NE(errorOf(R"({"lights": [{"colour": [1, 1, 1]}]})").find("/lights/0/colour: unknown key"), std::string::npos);
  EXPECT_NE(errorOf(R"({"objects": [{"mesh": {"type": "sphere", "radus": 2}}]})").find("/objects/0/mesh/radus: unknown key"),
            std::string::npos);
}

TEST(SceneRejects, WrongTypes) {
  EXPECT_EQ(errorOf(R"({"width": "640"})"), "scene.json: /width: expected an integer, got a string");
  EXPECT_EQ(errorOf(R"({"width": 64.5})"), "scene.json: /width: expected an integer, got 64.5");
  EXPECT_EQ(errorOf(R"({"light_model": {"two_sided": 1}})"),
            "scene.json: /light_model/two_sided: expected true or false, got a number");
  EXPECT_EQ(errorOf(R"({"lights": {}})"), "scene.json: /lights: expected an array, got an object");
  EXPECT_EQ(errorOf(R"([])"), "scene.json: /: expected an object, got an array of 0");
  EXPECT_EQ(errorOf(R"({"model": "gouraud"})"),
            "scene.json: /model: expected \"blinn-phong\", \"phong\", \"lambert\", \"cook-torrance\", \"wylie\" or \"bouknight\", got \"gouraud\"");
  EXPECT_EQ(errorOf(R"({"shading": "smooth"})"),
            "scene.json: /shading: expected \"flat\", \"gouraud\" or \"phong\", got \"smooth\"");
}

TEST(SceneRejects, NonFiniteNumbers) {
  EXPECT_EQ(errorOf(R"({"camera": {"eye": [0, 0, 1e999]}})"),
            "scene.json: invalid JSON: number overflow parsing '1e999' (expected a finite number)");
  if constexpr (sizeof(Real) == sizeof(float)) {
    EXPECT_EQ(errorOf(R"({"lights": [{"position": [0, 0, 1e40, 0]}]})"),
              "scene.json: /lights/0/position/2: expected a finite number");  // overflows float
  }
}

TEST(SceneRejects, NegativeSizesAndOutOfRange) {
  EXPECT_EQ(errorOf(R"({"objects": [{"mesh": {"type": "sphere", "radius": -1}}]})"),
            "scene.json: /objects/0/mesh/radius: expected a positive number, got -1");
  EXPECT_EQ(errorOf(R"({"objects": [{"mesh": {"type": "cube", "size": 0}}]})"),
            "scene.json: /objects/0/mesh/size: expected a positive number, got 0");
  EXPECT_EQ(errorOf(R"({"width": 0})"), "scene.json: /width: expected an integer in [1, 16384], got 0");
  EXPECT_EQ(errorOf(R"({"lights": [{"diffuse": [-0.5, 0, 0]}]})"),
            "scene.json: /lights/0/diffuse/0: expected a number ≥ 0, got -0.5");
  // Light colours are intensities (glLight accepts any value); material colours are reflectances.
  EXPECT_EQ(errorOf(R"({"lights": [{"diffuse": [1.5, 2, 0]}], "light_model": {"ambient": [3, 3, 3]}})"), "(no error)");
  EXPECT_EQ(errorOf(R"({"objects": [{"material": {"diffuse": [1.5, 0, 0]}}]})"),
            "scene.json: /objects/0/material/diffuse/0: expected a number in [0, 1], got 1.5");
  EXPECT_EQ(errorOf(R"({"camera": {"fovy": 1e-20}})"),
            "scene.json: /camera/fovy: expected a view angle in [0.01, 179.99] degrees");
  if constexpr (sizeof(Real) == 4) {
    EXPECT_EQ(errorOf(R"({"camera": {"eye": [1e30, 0, 0]}})"),
              "scene.json: /camera: expected numbers the renderer can transform with: the view and projection "
              "overflow single precision");
  }
  EXPECT_EQ(errorOf(R"({"lights": [{"spot_cutoff": 100}]})"),
            "scene.json: /lights/0/spot_cutoff: expected an angle in [0, 90] or 180, got 100");
  EXPECT_EQ(errorOf(R"({"lights": [{"spot_exponent": 129}]})"),
            "scene.json: /lights/0/spot_exponent: expected a number in [0, 128], got 129");
  EXPECT_EQ(errorOf(R"({"lights": [{"attenuation": [0, 0, 0]}]})").rfind(
                "scene.json: /lights/0/attenuation: expected at least one positive coefficient", 0),
            0u);
  EXPECT_EQ(errorOf(R"({"lights": [{"attenuation": [1, -1, 0]}]})"),
            "scene.json: /lights/0/attenuation/1: expected a number ≥ 0, got -1");
  EXPECT_EQ(errorOf(R"({"objects": [{"material": {"shininess": -2}}]})"),
            "scene.json: /objects/0/material/shininess: expected a number ≥ 0, got -2");
  EXPECT_EQ(errorOf(R"({"objects": [{"mesh": {"type": "sphere", "slices": 2}}]})"),
            "scene.json: /objects/0/mesh/slices: expected an integer in [3, 4096], got 2");
  EXPECT_EQ(errorOf(R"({"version": 2})"), "scene.json: /version: expected version 1");
}

TEST(SceneRejects, InconsistentCameraAndGeometry) {
  EXPECT_EQ(errorOf(R"({"camera": {"near": 5, "far": 1}})"), "scene.json: /camera: expected far > near");
  EXPECT_EQ(errorOf(R"({"camera": {"eye": [0, 0, 0]}})"), "scene.json: /camera: expected eye and center to differ");
  EXPECT_NE(errorOf(R"({"camera": {"eye": [0, 5, 0]}})").find("not parallel"), std::string::npos);
  EXPECT_EQ(errorOf(R"({"camera": {"fovy": 180}})"),
            "scene.json: /camera/fovy: expected an angle strictly between 0 and 180 degrees");
  EXPECT_EQ(errorOf(R"({"objects": [{"transform": [{"scale": [1, 0, 1]}]}]})").rfind(
                "scene.json: /objects/0/transform/0/scale: expected non-zero scale factors", 0),
            0u);
  EXPECT_EQ(errorOf(R"({"objects": [{"transform": [{"translate": [1, 0, 0], "scale": [1, 1, 1]}]}]})"),
            "scene.json: /objects/0/transform/0: expected exactly one of translate, rotate, scale or matrix");
  EXPECT_EQ(errorOf(R"({"lights": [{"spot_direction": [0, 0, 0]}]})"),
            "scene.json: /lights/0/spot_direction: expected a non-zero direction");
}

TEST(SceneRejects, BadTriangles) {
  EXPECT_EQ(errorOf(R"({"objects": [{"mesh": {"type": "triangles", "positions": [0,0,0, 1,0,0, 0,1,0], "indices": [0, 1, 3]}}]})"),
            "scene.json: /objects/0/mesh/indices/2: expected an integer in [0, 2], got 3");
  EXPECT_EQ(errorOf(R"({"objects": [{"mesh": {"type": "triangles", "positions": [0,0,0, 1,0], "indices": []}}]})"),
            "scene.json: /objects/0/mesh/positions: expected a multiple of 3 numbers, got 5");
  EXPECT_EQ(errorOf(R"({"objects": [{"mesh": {"type": "triangles", "positions": [0,0,0], "indices": [0, 0]}}]})"),
            "scene.json: /objects/0/mesh/indices: expected a multiple of 3 indices, got 2");
  EXPECT_EQ(errorOf(R"({"objects": [{"mesh": {"type": "triangles", "positions": [0,0,0], "normals": [0,0], "indices": []}}]})"),
            "scene.json: /objects/0/mesh/normals: expected 3 numbers (one normal per position), got 2");
  EXPECT_EQ(errorOf(R"({"objects": [{"mesh": {"type": "blob"}}]})"),
            "scene.json: /objects/0/mesh/type: expected one of sphere, cube, torus, cone, teapot, triangles, file; got \"blob\"");
  EXPECT_EQ(errorOf(R"({"objects": [{"mesh": {"type": "file", "path": "no/such/model.obj"}}]})"),
            "scene.json: /objects/0/mesh/path: ./no/such/model.obj: no such model file");
}

TEST(SceneRejects, DuplicateKeysWithPath) {
  EXPECT_EQ(errorOf(R"({"width": 10, "width": 20})"),
            "scene.json: /width: duplicate key \"width\" (expected each key once; the first would be silently replaced)");
  EXPECT_EQ(errorOf(R"({"lights": [{}, {"diffuse": [1, 1, 1], "position": [0, 0, 1, 0], "diffuse": [0, 0, 0]}]})")
                .rfind("scene.json: /lights/1/diffuse: duplicate key", 0),
            0u);
  EXPECT_EQ(errorOf(R"({"objects": [[], {"mesh": {"type": "cube", "size": 1, "size": 2}}]})")
                .rfind("scene.json: /objects/1/mesh/size: duplicate key", 0),
            0u);
  // The same key in different objects is fine.
  EXPECT_EQ(parse(R"({"lights": [{"diffuse": [1, 0, 0]}, {"diffuse": [0, 1, 0]}]})").lights.size(), 2u);
}

TEST(SceneDefaults, RayTracingKeysLeaveTheRasterizerAsItWas) {
  const Scene s = parse(R"({"objects": [{}]})");
  EXPECT_EQ(s.renderer, RendererKind::Raster);
  EXPECT_EQ(s.rayTracing.maxDepth, 5);
  EXPECT_TRUE(s.rayTracing.shadows);
  EXPECT_EQ(samplesPerPixel(s), 1);
  const SurfaceOptics& o = s.objects[0].optics;
  EXPECT_EQ(o.reflective, Color3(0));
  EXPECT_EQ(o.transmissive, Color3(0));
  EXPECT_FLOAT_EQ(o.ior, 1.5f);
  EXPECT_FALSE(o.transmissionShininess.has_value());
  EXPECT_EQ(o.filter, Color3(1));
}

TEST(SceneFile, ReadsTheRayTracingKeys) {
  const Scene s = parse(R"({"renderer": "hall", "max_depth": 7, "shadows": false, "samples": 16, "seed": 42,
    "objects": [{"material": {"reflective": [0.1, 0.2, 0.3], "transmissive": [0.9, 0.8, 0.7], "ior": 1.33,
                              "transmission_shininess": 12, "filter": [0.5, 0.6, 0.7]}}]})");
  EXPECT_EQ(s.renderer, RendererKind::Hall);
  EXPECT_EQ(s.rayTracing.maxDepth, 7);
  EXPECT_FALSE(s.rayTracing.shadows);
  EXPECT_EQ(s.rayTracing.samples, 16);
  EXPECT_EQ(s.rayTracing.seed, 42u);
  EXPECT_EQ(parse("{}").rayTracing.seed, 0u);
  const SurfaceOptics& o = s.objects[0].optics;
  EXPECT_EQ(o.reflective, Color3(Real(0.1), Real(0.2), Real(0.3)));
  EXPECT_EQ(o.transmissive, Color3(Real(0.9), Real(0.8), Real(0.7)));
  EXPECT_FLOAT_EQ(o.ior, 1.33f);
  EXPECT_EQ(o.transmissionShininess, 12);
  EXPECT_EQ(o.filter, Color3(Real(0.5), Real(0.6), Real(0.7)));
  EXPECT_EQ(parse(R"({"renderer": "whitted"})").renderer, RendererKind::Whitted);
}

TEST(SceneRejects, BadRayTracingKeys) {
  EXPECT_EQ(errorOf(R"({"renderer": "pathtracer"})"),
            "scene.json: /renderer: expected \"raster\", \"whitted\", \"hall\" or \"path\", got \"pathtracer\"");
  EXPECT_NE(errorOf(R"({"max_depth": 17})").find("/max_depth"), std::string::npos);
  EXPECT_NE(errorOf(R"({"seed": -1})").find("/seed"), std::string::npos);
  EXPECT_NE(errorOf(R"({"seed": 0.5})").find("/seed"), std::string::npos);
  EXPECT_NE(errorOf(R"({"environment_map": "no-such-sky.hdr"})").find("/environment_map: expected a readable Radiance .hdr"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"environment": [-1, 0, 0]})").find("/environment"), std::string::npos);
  EXPECT_NE(errorOf(R"({"objects": [{"material": {"emission_strength": 1e7}}]})").find("/objects/0/material/emission_strength"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"samples": 0})").find("/samples"), std::string::npos);
  EXPECT_NE(errorOf(R"({"shadows": 1})").find("/shadows"), std::string::npos);
  EXPECT_NE(errorOf(R"({"objects": [{"material": {"ior": 0.5}}]})").find("/objects/0/material/ior"), std::string::npos);
  EXPECT_NE(errorOf(R"({"objects": [{"material": {"reflective": [2, 0, 0]}}]})").find("/objects/0/material/reflective"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"objects": [{"material": {"filter": [0.5, 0.5]}}]})").find("expected 3 numbers"),
            std::string::npos);
}

TEST(SceneFile, LightColoursMayCarryAlpha) {
  const Scene s = parse(R"({"lights": [{"diffuse": [0.5, 0.25, 1, 1]}], "light_model": {"ambient": [0.1, 0.1, 0.1, 1]}})");
  EXPECT_EQ(s.lights[0].diffuse, Color3(0.5, 0.25, 1));
  EXPECT_FLOAT_EQ(s.lightModel.ambient.g, 0.1f);
}

TEST(SceneFile, Labels) {
  const Scene s = parse(R"({"labels": [{"text": "key light", "position": [1, 2, 3]},
                                       {"text": "title", "pixel": [320, 20], "color": [1, 0, 0], "size": 24}]})");
  ASSERT_EQ(s.labels.size(), 2u);
  EXPECT_EQ(*s.labels[0].position, Vec3(1, 2, 3));
  EXPECT_EQ(s.labels[0].size, 16);
  EXPECT_EQ(*s.labels[1].pixel, Vec2(320, 20));
  EXPECT_EQ(s.labels[1].color, Color3(1, 0, 0));
  EXPECT_EQ(errorOf(R"({"labels": [{"text": "x"}]})"),
            "scene.json: /labels/0: expected either \"position\" (world) or \"pixel\" (image), not both or neither");
  EXPECT_EQ(errorOf(R"({"labels": [{"position": [0, 0, 0]}]})"), "scene.json: /labels/0: expected a \"text\"");
}

TEST(SceneRejects, InvalidJsonNamesLineAndColumn) {
  const std::string e = errorOf("{\n  \"width\": 64,\n  \"height\": ,\n}");
  EXPECT_EQ(e.rfind("scene.json: line 3, column 13: invalid JSON", 0), 0u) << e;
}

TEST(SceneFile, MissingFileIsAnInputError) {
  EXPECT_THROW(loadSceneFile("/nonexistent/scene.json"), InputError);
}

}  // namespace
}  // namespace illum

namespace illum {
namespace {

TEST(SceneFile, ReadsTheDisplayKeys) {
  EXPECT_TRUE(parseScene("{}", "scene.json", ".").display.identity());  // linear, as GL writes
  const Scene s = parseScene(R"({"tone_map": "aces", "encoding": "srgb"})", "scene.json", ".");
  EXPECT_EQ(s.display.toneMap, ToneMap::Aces);
  EXPECT_EQ(s.display.encoding, Encoding::Srgb);
  const auto error = [](const std::string& text) -> std::string {
    try {
      parseScene(text, "scene.json", ".");
    } catch (const InputError& e) {
      return e.what();
    }
    return "(no error)";
  };
  EXPECT_EQ(error(R"({"tone_map": "filmic"})"),
            "scene.json: /tone_map: expected \"none\", \"reinhard\" or \"aces\", got \"filmic\"");
  EXPECT_EQ(error(R"({"encoding": "gamma"})"), "scene.json: /encoding: expected \"linear\" or \"srgb\", got \"gamma\"");
  EXPECT_EQ(parseScene("{}", "scene.json", ".").multisample, 1);  // GL's single sample
  EXPECT_EQ(parseScene(R"({"multisample": 8})", "scene.json", ".").multisample, 8);
  EXPECT_EQ(error(R"({"multisample": 2})"), "scene.json: /multisample: expected 1, 4, 8 or 16 samples per pixel, got 2");
}

}  // namespace
}  // namespace illum

namespace illum {
namespace {

// A model file several objects name is read once: its meshes are shared between them.
TEST(SceneFile, AModelFileNamedManyTimesIsReadOnce) {
  std::string objects;
  for (int i = 0; i < 8; ++i)
    objects += std::string(i ? "," : "") + R"({"mesh": {"type": "file", "path": "/usr/share/assimp/models/PLY/Wuson.ply"},
                                              "transform": [{"translate": [)" + std::to_string(i) + ", 0, 0]}]}";
  const Scene s = parseScene(R"({"objects": [)" + objects + "]}", "scene.json", ".");
  ASSERT_EQ(s.objects.size(), 8u);
  for (const Object& o : s.objects) EXPECT_EQ(o.mesh.get(), s.objects[0].mesh.get());
}

}  // namespace
}  // namespace illum

namespace illum {
namespace {

TEST(SceneFile, ReadsPointSizeAndLineWidth) {
  const Scene defaults = parseScene("{}", "scene.json", ".");
  EXPECT_EQ(defaults.pointSize, 1);  // glPointSize's and glLineWidth's defaults
  EXPECT_EQ(defaults.lineWidth, 1);
  const Scene s = parseScene(R"({"point_size": 4.5, "line_width": 2})", "scene.json", ".");
  EXPECT_EQ(s.pointSize, Real(4.5));
  EXPECT_EQ(s.lineWidth, 2);
  EXPECT_THROW(parseScene(R"({"point_size": 0})", "scene.json", "."), InputError);
  EXPECT_THROW(parseScene(R"({"line_width": 1000})", "scene.json", "."), InputError);
}

// A model file that scenes read one after another name is read once; one the scene before named,
// and this one does not, is let go (no more than two scenes' models are held at once).
TEST(SceneFile, ModelFilesAreKeptForTheNextScene) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("illum_scene_cache_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "tri.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  const std::string withModel = R"({"objects": [{"mesh": {"type": "file", "path": "tri.obj"}}]})";
  SceneModelCache cache;
  const Scene a = parseScene(withModel, "a.json", dir, {}, &cache);
  const Scene b = parseScene(withModel, "b.json", dir, {}, &cache);
  const Scene c = parseScene(withModel, "c.json", dir, {}, &cache);
  EXPECT_EQ(a.objects[0].mesh, b.objects[0].mesh);  // the same mesh, not read again
  EXPECT_EQ(a.objects[0].mesh, c.objects[0].mesh);
  parseScene(R"({"objects": [{}]})", "d.json", dir, {}, &cache);
  const Scene e = parseScene(withModel, "e.json", dir, {}, &cache);  // d let it go: read again
  EXPECT_NE(a.objects[0].mesh, e.objects[0].mesh);
  EXPECT_EQ(a.objects[0].mesh->positions, e.objects[0].mesh->positions);
  // Without a cache, every scene reads its own.
  EXPECT_NE(parseScene(withModel, "f.json", dir).objects[0].mesh, parseScene(withModel, "g.json", dir).objects[0].mesh);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace illum

namespace illum {
namespace {

TEST(SceneFile, EnvironmentKeysAreReadAndCheckedByName) {
  const Scene s = test::parse(R"({"studio_environment": true, "environment_lighting": "physically_based",
                                   "environment_rotation": -45, "environment_background": "blurred"})");
  EXPECT_TRUE(s.environment.studio);
  EXPECT_EQ(s.rayTracing.environmentMap, studioEnvironment());
  EXPECT_EQ(s.environment.lighting, EnvironmentLighting::PhysicallyBased);
  EXPECT_EQ(s.environment.rotation, -45);
  EXPECT_EQ(s.environment.background, EnvironmentBackground::Blurred);
  EXPECT_EQ(test::parse("{}").environment.lighting, EnvironmentLighting::None);
  EXPECT_NE(test::errorOf(R"({"environment_lighting": "yes"})").find(
                "/environment_lighting: expected \"none\", \"physically_based\" or \"all\", got \"yes\""),
            std::string::npos)
      << test::errorOf(R"({"environment_lighting": "yes"})");
  EXPECT_NE(test::errorOf(R"({"environment_background": "sharpest"})").find("expected \"none\", \"sharp\" or \"blurred\""),
            std::string::npos);
  EXPECT_NE(test::errorOf(R"({"environment_rotation": 720})").find("/environment_rotation"), std::string::npos);
  EXPECT_NE(test::errorOf(R"({"studio_environment": true, "environment_map": "sky.hdr"})").find("not both"),
            std::string::npos);
}

}  // namespace
}  // namespace illum
