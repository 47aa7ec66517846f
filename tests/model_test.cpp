// Real model files no one here wrote (Debian's assimp-testmodels), rendered as a user would:
// `illum render MODEL`. Checks what the picture must show and that broken files are refused.
#include "cli_support.h"

#include <illum/image.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <fstream>
#include <iterator>
#include <cstring>
#include <numbers>

namespace illum {
namespace {

using test::runIllum;
using test::slurp;
using test::TempDir;
namespace fs = std::filesystem;

const fs::path kModels = "/usr/share/assimp/models";

struct Coverage {
  int minX, minY, maxX, maxY;  // bounding box of the pixels that differ from the background
  int count;
};

Coverage foreground(const Image& img) {
  const std::uint8_t* bg = img.pixel(0, 0);
  Coverage c{img.width, img.height, -1, -1, 0};
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const std::uint8_t* p = img.pixel(x, y);
      if (std::abs(p[0] - bg[0]) + std::abs(p[1] - bg[1]) + std::abs(p[2] - bg[2]) <= 3) continue;
      c.minX = std::min(c.minX, x), c.maxX = std::max(c.maxX, x);
      c.minY = std::min(c.minY, y), c.maxY = std::max(c.maxY, y);
      ++c.count;
    }
  return c;
}

// Pixels whose colour is dominated by one channel: 0 red, 1 green, 2 blue.
int dominated(const Image& img, int channel, int margin = 40) {
  int n = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const std::uint8_t* p = img.pixel(x, y);
      bool ok = true;
      for (int c = 0; c < 3; ++c)
        if (c != channel && int(p[channel]) < int(p[c]) + margin) ok = false;
      n += ok ? 1 : 0;
    }
  return n;
}

Image renderModel(const fs::path& model, const std::string& extra = "") {
  TempDir dir;
  const auto r = runIllum("render " + model.string() + " --resolution=400,300 -o " + (dir / "out.png").string() + " " + extra);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  if (r.exitCode != 0) return Image(400, 300);
  return readPng(dir / "out.png");
}

class GoodModel : public testing::TestWithParam<std::string> {};

TEST_P(GoodModel, IsFramedSensibly) {
  const Image img = renderModel(kModels / GetParam());
  const Coverage c = foreground(img);
  ASSERT_GT(c.count, 0) << "nothing drawn";
  // Nothing cut off at the borders, and the model fills most of the frame in one direction.
  EXPECT_GT(c.minX, 0);
  EXPECT_GT(c.minY, 0);
  EXPECT_LT(c.maxX, img.width - 1);
  EXPECT_LT(c.maxY, img.height - 1);
  const double fillX = double(c.maxX - c.minX + 1) / img.width, fillY = double(c.maxY - c.minY + 1) / img.height;
  EXPECT_GT(std::max(fillX, fillY), 0.6) << fillX << " " << fillY;
  EXPECT_GT(c.count, img.width * img.height / 20);
}

INSTANTIATE_TEST_SUITE_P(AssimpTestModels, GoodModel,
                         testing::Values("OBJ/spider.obj", "PLY/Wuson.ply", "STL/Spider_ascii.stl",
                                         "STL/Spider_binary.stl",
                                         "glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb",
                                         "glTF/CesiumMilkTruck/CesiumMilkTruck.gltf", "FBX/spider.fbx",
                                         "Collada/duck.dae", "3DS/cubes_with_alpha.3DS"),
                         [](const auto& info) {
                           std::string s = fs::path(info.param).filename().string();
                           for (char& ch : s)
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           return s;
                         });

// A preview saved as a scene file (model file by path, its materials, the rig, the camera, sRGB)
// draws the same bytes; with --color the file's own colours stay dropped.
TEST(ModelScene, APreviewSavedAsASceneDrawsTheSameBytes) {
  TempDir dir;
  for (const std::string args : {"glTF2/BoxTextured-glTF-Binary/BoxTextured.glb", "OBJ/spider.obj --color 0.3,0.6,0.9 --normals flat"}) {
    const auto r = runIllum("render " + (kModels / args).string() + " --resolution 320,200 -o " +
                                 (dir / "a.png").string() + " --save-scene " + (dir / "a.json").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto again = runIllum("render " + (dir / "a.json").string() + " -o " + (dir / "b.png").string());
    ASSERT_EQ(again.exitCode, 0) << again.err;
    EXPECT_EQ(slurp(dir / "a.png"), slurp(dir / "b.png")) << args;
  }
}

// Which previews are physically based pictures, and so go through ACES as the path tracer's do:
// those an environment lights (the studio of glTF's materials, or --environment); classic
// materials keep GL's clamp; --tone-map says otherwise for any.
TEST(ModelScene, EnvironmentLitPreviewsAreToneMapped) {
  TempDir dir;
  const auto toneMapOf = [&](const std::string& args) {
    const auto r = runIllum("render " + args + " --resolution 64,48 -o " + (dir / "t.png").string() + " --save-scene " +
                            (dir / "t.json").string());
    EXPECT_EQ(r.exitCode, 0) << r.err;
    const std::string json = slurp(dir / "t.json");
    const std::size_t at = json.find("\"tone_map\": \"");
    return at == std::string::npos ? std::string("?") : json.substr(at + 13, json.find('"', at + 13) - at - 13);
  };
  const std::string box = (kModels / "glTF2/BoxTextured-glTF-Binary/BoxTextured.glb").string();
  EXPECT_EQ(toneMapOf(box), "aces");
  EXPECT_EQ(toneMapOf(box + " --environment none"), "none");
  EXPECT_EQ(toneMapOf(box + " --tone-map reinhard"), "reinhard");
  EXPECT_EQ(toneMapOf((kModels / "OBJ/spider.obj").string()), "none");
  EXPECT_EQ(toneMapOf((kModels / "OBJ/spider.obj").string() + " --environment studio"), "aces");
}

TEST(ModelMaterials, FileColoursAppear) {
  // The engine's cylinder heads are blue in its glTF materials (as GL writes them: sRGB lifts
  // their green towards cyan); the duck is yellow (red+green).
  EXPECT_GT(dominated(renderModel(kModels / "glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb", "--encoding linear"), 2),
            1000);
  const Image cubes = renderModel(kModels / "3DS/cubes_with_alpha.3DS");
  EXPECT_GT(dominated(cubes, 0), 1000);  // the red cube
}

TEST(ModelMaterials, TexturesAppear) {
  // BoxTextured's texture is a white square with a green and blue logo; untextured it is grey.
  for (const char* file : {"glTF2/BoxTextured-glTF-Binary/BoxTextured.glb", "glTF2/BoxTextured-glTF/BoxTextured.gltf",
                           "glTF2/BoxTextured-glTF-Embedded/BoxTextured.gltf"}) {
    const Image img = renderModel(kModels / file);
    EXPECT_GT(dominated(img, 1, 30), 1000) << file;  // the logo's green
    EXPECT_GT(dominated(img, 2, 30), 1000) << file;  // and its blue
  }
}

TEST(ModelMaterials, VertexColoursDriveTheDiffuseColour) {
  const Image img = renderModel(kModels / "Collada/kwxport_test_vcolors.dae", "--shading=gouraud");
  EXPECT_GT(dominated(img, 0), 500);
  EXPECT_GT(dominated(img, 1), 500);
}

TEST(ModelMaterials, MissingTextureWarnsAndRendersUntextured) {
  TempDir dir;
  const fs::path src = kModels / "glTF2/BoxTextured-glTF";
  fs::copy_file(src / "BoxTextured.gltf", dir / "BoxTextured.gltf");
  fs::copy_file(src / "BoxTextured0.bin", dir / "BoxTextured0.bin");  // but not the PNG
  const auto r = runIllum("render " + (dir / "BoxTextured.gltf").string() + " --resolution=200,150 -o " + (dir / "out.png").string());
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("illum: warning: "), std::string::npos);
  EXPECT_NE(r.err.find("CesiumLogoFlat.png"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(dir / "out.png"));
}

TEST(ModelFiles, WorkInSceneFilesAfterTheObjectTransform) {
  TempDir dir;
  const auto widthAtScale = [&](double scale) {
    std::ofstream(dir / "scene.json") << R"({"width": 200, "height": 150, "camera": {"eye": [0, 0, 600], "far": 2000},
      "objects": [{"mesh": {"type": "file", "path": ")"
        << (kModels / "glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb").string()
        << R"("}, "transform": [{"scale": [)" << scale << "," << scale << "," << scale << "]}]}]}";
    const auto r = runIllum("render " + (dir / "scene.json").string() + " -o " + (dir / "out.png").string());
    EXPECT_EQ(r.exitCode, 0) << r.err;
    const Coverage c = foreground(readPng(dir / "out.png"));
    return c.maxX - c.minX + 1;
  };
  const int small = widthAtScale(0.15), large = widthAtScale(0.3);
  EXPECT_GT(small, 20);
  EXPECT_NEAR(double(large) / small, 2.0, 0.1);
}

TEST(ModelCli, F3dStyleOptions) {
  const fs::path box = kModels / "glTF2/BoxTextured-glTF-Binary/BoxTextured.glb";
  TempDir dir;
  const auto r = runIllum("render " + box.string() + " --resolution=120,90 --up=+Z --camera-azimuth-angle=10 "
                          "--camera-elevation-angle=40 --camera-zoom-factor=0.5 "
                          "--orthographic --light-intensity=1.2 --normals=flat --crease-angle=30 "
                          "--background-color=#336699 --model=phong --shading=gouraud --verbose -o " +
                          (dir / "a.png").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const Image img = readPng(dir / "a.png");
  EXPECT_EQ(img.width, 120);
  EXPECT_EQ(img.pixel(0, 0)[0], 0x33);  // #rrggbb gives exactly those bytes
  EXPECT_EQ(img.pixel(0, 0)[2], 0x99);
  EXPECT_NE(r.err.find("triangles"), std::string::npos);
  EXPECT_NE(r.err.find("bounds"), std::string::npos);
  EXPECT_NE(r.err.find("peak memory"), std::string::npos);
  // Zoomed out to half: the box covers about a quarter of the area it covers at zoom 1.
  const auto full = runIllum("render " + box.string() + " --resolution=120,90 -o " + (dir / "b.png").string());
  const auto half = runIllum("render " + box.string() + " --resolution=120,90 --camera-zoom-factor=0.5 -o " + (dir / "c.png").string());
  ASSERT_EQ(full.exitCode, 0);
  ASSERT_EQ(half.exitCode, 0);
  const double ratio = double(foreground(readPng(dir / "c.png")).count) / foreground(readPng(dir / "b.png")).count;
  EXPECT_NEAR(ratio, 0.25, 0.08);
  // A transparent background.
  ASSERT_EQ(runIllum("render " + box.string() + " --resolution=40,30 --no-background -o " + (dir / "d.png").string()).exitCode, 0);
  EXPECT_EQ(readPng(dir / "d.png").pixel(0, 0)[3], 0);
  // An explicit camera.
  const auto placed = runIllum("render " + box.string() + " --resolution=40,30 --camera-position=0,0,5 --camera-focal-point=0,0,0 "
                               "--camera-view-up=0,1,0 -o " + (dir / "e.png").string());
  EXPECT_EQ(placed.exitCode, 0) << placed.err;
  const auto badUp = runIllum("render " + box.string() + " --up=Q -o " + (dir / "f.png").string());
  EXPECT_EQ(badUp.exitCode, 2);
  EXPECT_NE(badUp.err.find("--up: expected +X, -X, +Y, -Y, +Z or -Z"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir / "f.png"));
}

struct BrokenCase {
  std::string file;
  std::string message;
};

class BrokenModel : public testing::TestWithParam<BrokenCase> {};

TEST_P(BrokenModel, IsRefusedCleanly) {
  TempDir dir;
  std::ofstream(dir / "out.png") << "previous";
  const auto r = runIllum("render " + (kModels / GetParam().file).string() + " -o " + (dir / "out.png").string());
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_EQ(r.err.rfind("illum: error: " + (kModels / GetParam().file).string() + ": ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(GetParam().message), std::string::npos) << r.err;
  EXPECT_EQ(test::slurp(dir / "out.png"), "previous");
  EXPECT_EQ(dir.fileCount(), 1u);
}

INSTANTIATE_TEST_SUITE_P(
    AssimpTestModels, BrokenModel,
    testing::Values(BrokenCase{"glTF2/IndexOutOfRange/IndexOutOfRange.gltf", "out of range"},
                    BrokenCase{"glTF2/IndexOutOfRange/AllIndicesOutOfRange.gltf", "cannot read the model"},
                    BrokenCase{"glTF2/BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb", "expected a finite position"},
                    BrokenCase{"glTF2/MissingBin/BoxTextured.gltf", "BoxTextured0.bin"},
                    BrokenCase{"glTF2/SchemaFailures/sceneWrongType.gltf", "cannot read the model"},
                    BrokenCase{"glTF2/RecursiveNodes/RecursiveNodes.gltf", "is its own ancestor (a cycle)"},
                    BrokenCase{"OBJ/no_such_model.obj", "no such model file"}),
    [](const auto& info) { return std::to_string(info.index); });

class HandMadeBrokenFile : public testing::Test {
 protected:
  void expectRefused(const std::string& name, const std::string& bytes, const std::string& message) {
    TempDir dir;
    { std::ofstream(dir / name, std::ios::binary) << bytes; }
    const auto r = runIllum("render " + (dir / name).string() + " -o " + (dir / "out.png").string());
    EXPECT_EQ(r.exitCode, 2) << name << ": " << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "out.png"));
  }
};

TEST_F(HandMadeBrokenFile, EmptyTruncatedMalformed) {
  expectRefused("empty.obj", "", "the model file is empty");
  expectRefused("index.obj", "v 0 0 0\nv 1 0 0\nf 1 2 7\n", "out of range");
  expectRefused("nan.obj", "v 0 0 nan\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "expected a finite position");
  const std::string ply = test::slurp(kModels / "PLY/Wuson.ply");
  expectRefused("truncated.ply", ply.substr(0, 5000), "truncated");
  const std::string stl = test::slurp(kModels / "STL/Spider_binary.stl");
  expectRefused("truncated.stl", stl.substr(0, 2000), "is the file truncated or corrupt?");
  const std::string glb = test::slurp(kModels / "glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb");
  expectRefused("truncated.glb", glb.substr(0, 3000), "cannot read the model");
  expectRefused("garbage.obj", "this is not a model\n", "cannot read the model");
}

// A 2-million-triangle binary PLY (a finely tessellated sphere without normals) loads and renders.
TEST(BigModel, TwoMillionTrianglePly) {
  TempDir dir;
  const int n = 1000, m = 1000;  // n × m quads
  {
    std::ofstream f(dir / "big.ply", std::ios::binary);
    f << "ply\nformat binary_little_endian 1.0\nelement vertex " << (n + 1) * (m + 1)
      << "\nproperty float x\nproperty float y\nproperty float z\nelement face " << 2 * n * m
      << "\nproperty list uchar int vertex_indices\nend_header\n";
    for (int j = 0; j <= m; ++j)
      for (int i = 0; i <= n; ++i) {
        const double th = std::numbers::pi * j / m, ph = 2 * std::numbers::pi * i / n;
        const float p[3] = {float(std::sin(th) * std::cos(ph)), float(std::cos(th)), float(std::sin(th) * std::sin(ph))};
        f.write(reinterpret_cast<const char*>(p), sizeof p);
      }
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < n; ++i) {
        const int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
        const int triangles[2][3] = {{a, c, b}, {b, c, d}};
        for (const auto& t : triangles) {
          const char count = 3;
          f.write(&count, 1);
          f.write(reinterpret_cast<const char*>(t), sizeof t);
        }
      }
  }
  const auto r = runIllum("render " + (dir / "big.ply").string() + " --resolution=200,150 --verbose -o " + (dir / "big.png").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("2,000,000 triangles"), std::string::npos) << r.err;
  const Image img = readPng(dir / "big.png");
  const Coverage c = foreground(img);
  // A sphere seen from anywhere is a disc: its area is π/4 of its bounding square.
  const double w = c.maxX - c.minX + 1, h = c.maxY - c.minY + 1;
  EXPECT_NEAR(w, h, 2);
  EXPECT_NEAR(c.count / (w * h), std::numbers::pi / 4, 0.03);
}

}  // namespace
}  // namespace illum

namespace illum {
namespace {

// Exporters that mark every surface fully transparent would render nothing: drawn opaque, warned.
TEST(NothingSilentlyEmpty, FullyTransparentModelsAreDrawnOpaque) {
  for (const char* file : {"Collada/teapots.DAE", "Collada/ConcavePolygon.dae"}) {
    TempDir dir;
    const auto r = runIllum("render " + (kModels / file).string() + " --resolution=200,120 -o " + (dir / "m.png").string());
    ASSERT_EQ(r.exitCode, 0) << file << ": " << r.err;
    EXPECT_NE(r.err.find("fully transparent"), std::string::npos) << file << ": " << r.err;
    EXPECT_GT(foreground(readPng(dir / "m.png")).count, 200) << file;
  }
}

// Blender's default cube as assimp reads it: every vertex colour transparent black, a placeholder
// for none. It is drawn in its material's grey (it was once drawn opaque black), with no warning.
TEST(NothingSilentlyEmpty, PlaceholderVertexColoursAreNotDrawnBlack) {
  TempDir dir;
  const auto r = runIllum("render " + (kModels / "BLEND/BlenderDefault_250.blend").string() +
                          " --resolution=200,120 -o " + (dir / "m.png").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
  const Image img = readPng(dir / "m.png");
  const Coverage c = foreground(img);
  ASSERT_GT(c.count, 200);
  double sum = 0;
  for (int y = c.minY; y <= c.maxY; ++y)
    for (int x = c.minX; x <= c.maxX; ++x) sum += img.pixel(x, y)[1];
  // The cube's box, background corners included, averages well above a black cube's ~40.
  EXPECT_GT(sum / double((c.maxX - c.minX + 1) * (c.maxY - c.minY + 1)), 100.0);
}

TEST(NothingSilentlyEmpty, DegenerateFilesAreRefused) {
  TempDir dir;
  const auto off = runIllum("render " + (kModels / "OFF/invalid.off").string() + " -o " + (dir / "a.png").string());
  EXPECT_EQ(off.exitCode, 2);
  EXPECT_NE(off.err.find("all its vertices are at one point"), std::string::npos) << off.err;
  const auto lights = runIllum("render " + (kModels / "Collada/lights.dae").string() + " -o " + (dir / "b.png").string());
  EXPECT_EQ(lights.exitCode, 2);
  EXPECT_NE(lights.err.find("no triangles, lines or points"), std::string::npos) << lights.err;
  std::ofstream(dir / "flat.obj") << "v 0 0 0\nv 1 1 1\nv 2 2 2\nf 1 2 3\n";
  const auto flat = runIllum("render " + (dir / "flat.obj").string() + " -o " + (dir / "c.png").string());
  EXPECT_EQ(flat.exitCode, 2);
  EXPECT_NE(flat.err.find("no drawable triangle"), std::string::npos) << flat.err;
  EXPECT_FALSE(fs::exists(dir / "a.png") || fs::exists(dir / "b.png") || fs::exists(dir / "c.png"));
}

// Point clouds and line sets are drawn as GL_POINTS and GL_LINES (--point-size, --line-width).
TEST(PointsAndLines, PointCloudsAndLineSetsAreDrawn) {
  TempDir dir;
  std::ofstream(dir / "points.ply") << "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                       "property float z\nend_header\n0 0 0\n1 0 0\n0 1 0\n";
  const auto small = runIllum("render " + (dir / "points.ply").string() + " --resolution=200,120 -v -o " + (dir / "a.png").string());
  ASSERT_EQ(small.exitCode, 0) << small.err;
  EXPECT_NE(small.err.find("0 triangles, 3 points"), std::string::npos) << small.err;
  const auto big = runIllum("render " + (dir / "points.ply").string() + " --resolution=200,120 --point-size 9 -o " +
                            (dir / "b.png").string());
  ASSERT_EQ(big.exitCode, 0) << big.err;
  // Three discs of 3 and of 9 pixels across (the preview's 8 samples soften their edges).
  const double a = foreground(readPng(dir / "a.png")).count, b = foreground(readPng(dir / "b.png")).count;
  EXPECT_GE(a, 3 * 5);
  EXPECT_NEAR(b / a, 9.0, 4.0);

  std::ofstream(dir / "lines.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\nl 2 3\n";
  const auto lines = runIllum("render " + (dir / "lines.obj").string() + " --resolution=200,120 -o " + (dir / "c.png").string());
  ASSERT_EQ(lines.exitCode, 0) << lines.err;
  const double thin = foreground(readPng(dir / "c.png")).count;
  EXPECT_GT(thin, 150);  // two lines across most of the picture
  ASSERT_EQ(runIllum("render " + (dir / "lines.obj").string() + " --resolution=200,120 --line-width 4 -o " +
                     (dir / "d.png").string()).exitCode, 0);
  EXPECT_GT(foreground(readPng(dir / "d.png")).count, 2 * thin);  // anti-aliased, a 1-pixel line touches 2

  // The ray tracers trace surfaces: points alone are refused, points beside surfaces left out.
  const auto traced = runIllum("render " + (dir / "points.ply").string() + " --renderer whitted -o " + (dir / "e.png").string());
  EXPECT_EQ(traced.exitCode, 2);
  EXPECT_NE(traced.err.find("only points and lines, which the rasterizer draws"), std::string::npos) << traced.err;
  EXPECT_FALSE(fs::exists(dir / "e.png"));
  const auto mixed = runIllum("render " + (kModels / "OBJ/testmixed.obj").string() +
                              " --renderer whitted --resolution=80,60 -o " + (dir / "f.png").string());
  EXPECT_EQ(mixed.exitCode, 0) << mixed.err;
  EXPECT_NE(mixed.err.find("points and lines are left out"), std::string::npos) << mixed.err;
}

// glTF's primitive modes 0-3 (points, lines, line loop, line strip) from Khronos' asset generator.
TEST(PointsAndLines, GltfPrimitiveModesAreDrawn) {
  TempDir dir;
  const fs::path folder = kModels / "glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode";
  for (const char* file : {"Mesh_PrimitiveMode_00.gltf", "Mesh_PrimitiveMode_01.gltf", "Mesh_PrimitiveMode_02.gltf",
                           "Mesh_PrimitiveMode_03.gltf"}) {
    const auto r = runIllum("render " + (folder / file).string() + " --resolution=120,90 -o " + (dir / "m.png").string());
    ASSERT_EQ(r.exitCode, 0) << file << ": " << r.err;
    EXPECT_GT(foreground(readPng(dir / "m.png")).count, 150) << file;
  }
}

TEST(NothingSilentlyEmpty, AnEmptyPictureIsWarnedAbout) {
  TempDir dir;
  std::ofstream(dir / "behind.json") << R"({"camera":{"eye":[0,0,5],"center":[0,0,10]},"objects":[{}]})";
  const auto r = runIllum("render " + (dir / "behind.json").string() + " -o " + (dir / "e.png").string());
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("shows only the background"), std::string::npos) << r.err;
  const auto seen = runIllum("render -o " + (dir / "d.png").string());
  EXPECT_EQ(seen.err.find("shows only the background"), std::string::npos) << seen.err;
}

}  // namespace
}  // namespace illum

namespace illum {
namespace {

// docs/models.md's claims about formats, as behaviour.
TEST(DocumentedFormats, GltfOneTextReadsAndBinaryIsRefused) {
  TempDir dir;
  const auto text = runIllum("render " + (kModels / "glTF/TwoBoxes/TwoBoxes.gltf").string() + " --resolution=80,60 -o " +
                             (dir / "a.png").string());
  EXPECT_EQ(text.exitCode, 0) << text.err;
  const auto binary = runIllum("render " + (kModels / "glTF/BoxTextured-glTF-Binary/BoxTextured.glb").string() +
                               " -o " + (dir / "b.png").string());
  EXPECT_EQ(binary.exitCode, 2) << binary.err;
}

TEST(DocumentedFormats, ObjWithoutMtlGetsTheNeutralMaterialLikePly) {
  TempDir dir;
  std::ofstream(dir / "quad.obj") << "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3 4\n";
  std::ofstream(dir / "quad.ply") << "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                                     "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                                     "end_header\n-1 -1 0\n1 -1 0\n1 1 0\n-1 1 0\n4 0 1 2 3\n";
  for (const char* f : {"quad.obj", "quad.ply"}) {
    const auto r = runIllum("render " + (dir / f).string() + " --resolution=80,60 -o " + (dir / (std::string(f) + ".png")).string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
  }
  EXPECT_EQ(readPng(dir / "quad.obj.png").rgba, readPng(dir / "quad.ply.png").rgba);
}

}  // namespace
}  // namespace illum

namespace illum {
namespace {

// Previews are encoded sRGB: the background shows the grey it is meant to (46,48,54, the bytes of
// 0.18,0.19,0.21), textures are decoded from sRGB before lighting, and --encoding linear gives GL's
// bytes back.
TEST(ModelColour, PreviewsAreSrgbAndLinearOnRequest) {
  const fs::path box = kModels / "glTF2/BoxTextured-glTF-Binary/BoxTextured.glb";
  const Image srgb = renderModel(box), linear = renderModel(box, "--encoding linear");
  for (const Image* image : {&srgb, &linear}) {
    EXPECT_EQ(image->pixel(0, 0)[0], 46);
    EXPECT_EQ(image->pixel(0, 0)[1], 48);
    EXPECT_EQ(image->pixel(0, 0)[2], 54);
  }
  // The lit box differs: the encodings are not the same picture.
  const Coverage c = foreground(srgb);
  EXPECT_GT(c.count, 10000);
  EXPECT_NE(srgb.rgba, linear.rgba);
  // The same background bytes from the ray tracer.
  const Image traced = renderModel(box, "--renderer whitted");
  EXPECT_EQ(traced.pixel(0, 0)[0], 46);
  EXPECT_EQ(traced.pixel(0, 0)[2], 54);
}

}  // namespace
}  // namespace illum

namespace illum {
namespace {

// The up axis comes from the file where the format says it: STL is +Z up (and --up still rules).
// --ambient-occlusion on a preview darkens its crevices: the fill light becomes light from
// everywhere, which the traced occlusion shades at each pixel before the colour is quantised. On
// the engine's finned cylinders the picture changes by several levels on average (it was 0.6/255
// when occlusion darkened only the faint ambient of the finished bytes).
TEST(ModelAmbientOcclusion, DarkensTheCreviceOfAPreview) {
  const fs::path engine = kModels / "glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb";
  TempDir dir;
  for (const char* name : {"plain", "occluded"}) {
    const auto r = runIllum("render " + engine.string() + " -o " + (dir / (std::string(name) + ".png")).string() +
                            (std::string(name) == "occluded" ? " --ambient-occlusion" : ""));
    ASSERT_EQ(r.exitCode, 0) << r.err;
  }
  const Image plain = readPng(dir / "plain.png"), occluded = readPng(dir / "occluded.png");
  ASSERT_EQ(plain.rgba.size(), occluded.rgba.size());
  double change = 0;
  std::size_t darker = 0;
  for (std::size_t i = 0; i < plain.rgba.size(); i += 4) {
    for (int c = 0; c < 3; ++c) change += std::abs(int(plain.rgba[i + c]) - int(occluded.rgba[i + c]));
    const int before = plain.rgba[i] + plain.rgba[i + 1] + plain.rgba[i + 2];
    const int after = occluded.rgba[i] + occluded.rgba[i + 1] + occluded.rgba[i + 2];
    darker += after + 30 < before;
  }
  EXPECT_GE(change / double(plain.rgba.size() / 4 * 3), 6.0);
  EXPECT_GT(darker, 10000u);  // the fins' gaps and the casing's corners
  // The background is the same bytes.
  EXPECT_EQ(std::memcmp(plain.pixel(0, 0), occluded.pixel(0, 0), 4), 0);
}

// A path-traced preview is denoised by default; its OpenEXR keeps the picture before the filter
// and the guides as layers; --no-denoise turns it off; the other renderers refuse --denoise.
TEST(ModelDenoise, OnForPathTracedPreviewsWithItsLayersInTheExr) {
  const fs::path duck = kModels / "Collada/duck.dae";
  TempDir dir;
  const auto render = [&](const std::string& name, const std::string& options) {
    const auto r = runIllum("render " + duck.string() + " --renderer path --samples 4 --resolution 160,120 -o " +
                            (dir / name).string() + " " + options);
    EXPECT_EQ(r.exitCode, 0) << r.err;
  };
  render("default.png", ""), render("denoised.png", "--denoise"), render("raw.png", "--no-denoise");
  render("denoised.exr", "");
  EXPECT_EQ(readPng(dir / "default.png").rgba, readPng(dir / "denoised.png").rgba);
  EXPECT_NE(readPng(dir / "default.png").rgba, readPng(dir / "raw.png").rgba);
  std::ifstream exr(dir / "denoised.exr", std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(exr)), std::istreambuf_iterator<char>());
  for (const char* channel : {"beauty.R", "beauty.A", "albedo.G", "normal.B"})
    EXPECT_NE(bytes.find(channel), std::string::npos) << channel;
  const auto raster = runIllum("render " + duck.string() + " --denoise -o " + (dir / "raster.png").string());
  EXPECT_EQ(raster.exitCode, 2);
  EXPECT_NE(raster.err.find("--denoise: the path tracer's"), std::string::npos) << raster.err;
  EXPECT_FALSE(fs::exists(dir / "raster.png"));
  const auto both = runIllum("render " + duck.string() + " --renderer path --denoise --no-denoise -o " +
                             (dir / "both.png").string());
  EXPECT_EQ(both.exitCode, 2);
  EXPECT_NE(both.err.find("expected one of them"), std::string::npos) << both.err;
}

// The background is a display colour: the same bytes from every renderer, tone map or not (the
// path tracer's preview is tone mapped, the rasterizer's not), and --background-color's bytes are
// the colour given.
TEST(ModelBackground, TheSameBytesFromEveryRendererToneMapOrNot) {
  const fs::path duck = kModels / "Collada/duck.dae";
  TempDir dir;
  for (const std::string colour : {"", "0.5,0.5,0.5", "0.02,0.9,0.3"}) {
    std::vector<std::array<std::uint8_t, 4>> corners;
    for (const std::string options : {"--renderer raster", "--renderer raster --tone-map aces", "--renderer whitted",
                                      "--renderer hall", "--renderer path --samples 4", "--renderer path --samples 4 --no-denoise"}) {
      const fs::path out = dir / "corner.png";
      const auto r = runIllum("render " + duck.string() + " --resolution 120,90 -o " + out.string() + " " + options +
                              (colour.empty() ? "" : " --background-color " + colour));
      ASSERT_EQ(r.exitCode, 0) << options << ": " << r.err;
      const Image image = readPng(out);
      corners.push_back({image.pixel(0, 0)[0], image.pixel(0, 0)[1], image.pixel(0, 0)[2], image.pixel(0, 0)[3]});
      EXPECT_EQ(corners.back(), corners.front()) << options << " " << colour;
    }
    if (colour == "0.02,0.9,0.3") {
      const std::array<std::uint8_t, 4> given{5, 230, 77, 255};  // round(c·255)
      EXPECT_EQ(corners.front(), given);
    }
  }
}

// Inputs as file managers give them: a file:// URI (percent-decoded), and a file whose name has no
// extension or the wrong one: the content says the format, and the picture is the original's.
TEST(ModelInputs, FileUrisAndNamesThatDoNotSayTheFormat) {
  TempDir dir;
  const fs::path box = kModels / "glTF2/BoxTextured-glTF-Binary/BoxTextured.glb", spider = kModels / "STL/Spider_binary.stl";
  fs::create_directories(dir / "my files");
  fs::copy_file(box, dir / "my files" / "Bóx.glb");
  fs::copy_file(box, dir / "box-download");
  fs::copy_file(spider, dir / "spider.obj");
  const auto picture = [&](const std::string& input) {
    const fs::path out = dir / "out.png";
    const auto r = runIllum("render '" + input + "' --resolution 120,90 -o " + out.string());
    EXPECT_EQ(r.exitCode, 0) << input << ": " << r.err;
    return r.exitCode == 0 ? readPng(out).rgba : std::vector<std::uint8_t>{};
  };
  const std::vector<std::uint8_t> boxPicture = picture(box.string()), spiderPicture = picture(spider.string());
  EXPECT_EQ(picture("file://" + (dir / "my%20files" / "B%C3%B3x.glb").string()), boxPicture);
  EXPECT_EQ(picture("file://localhost" + box.string()), boxPicture);
  EXPECT_EQ(picture((dir / "box-download").string()), boxPicture);
  EXPECT_EQ(picture((dir / "spider.obj").string()), spiderPicture);
  const auto remote = runIllum("render file://fileserver/models/box.glb -o " + (dir / "remote.png").string());
  EXPECT_EQ(remote.exitCode, 2);
  EXPECT_NE(remote.err.find("another machine"), std::string::npos) << remote.err;
}

TEST(ModelDefaults, StlIsZUpUnlessToldOtherwise) {
  const fs::path spider = kModels / "STL/Spider_binary.stl";
  const Image byDefault = renderModel(spider), zUp = renderModel(spider, "--up=+Z"), yUp = renderModel(spider, "--up=+Y");
  EXPECT_EQ(byDefault.rgba, zUp.rgba);
  EXPECT_NE(byDefault.rgba, yUp.rgba);
}

// --color, --opacity and --geometry-only override the file's materials.
TEST(ModelDefaults, MaterialOverrides) {
  const fs::path box = kModels / "glTF2/BoxTextured-glTF-Binary/BoxTextured.glb";
  EXPECT_GT(dominated(renderModel(box, "--color 0.9,0.1,0.1"), 0), 10000);  // red all over
  const Image geometry = renderModel(box, "--geometry-only --encoding linear");
  EXPECT_EQ(dominated(geometry, 1, 20) + dominated(geometry, 2, 20), 0);  // no green or blue logo: grey
  const Image seeThrough = renderModel(box, "--opacity 0.5 --no-background");
  EXPECT_GT(seeThrough.pixel(200, 150)[3], 0);
  EXPECT_LT(seeThrough.pixel(200, 150)[3], 255);
  TempDir dir;
  const auto r = runIllum("render " + std::string(ILLUM_EXAMPLES_DIR) + "/shininess.json --color 1,0,0 -o " +
                          (dir / "x.png").string());
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("--color"), std::string::npos);
}

}  // namespace
}  // namespace illum
