#include <illum/framing.h>
#include <illum/import.h>

#include <glm/gtc/matrix_inverse.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

namespace illum {
namespace {

TEST(FileMaterial, MtlValuesMapOntoGlMaterial) {
  FileMaterialValues v;
  v.hasAmbient = v.hasSpecular = true;
  v.ambient = {0.1, 0.2, 0.3};
  v.diffuse = {0.4, 0.5, 0.6, 1};
  v.specular = {0.7, 0.8, 0.9};
  v.emission = {0.05, 0, 0};
  v.shininess = 500;  // MTL Ns is the exponent itself, not capped at 128
  v.opacity = 0.5f;   // d
  const Material m = materialFromFile(v);
  EXPECT_EQ(Vec3(m.ambient), Vec3(0.1, 0.2, 0.3));
  EXPECT_EQ(Vec3(m.diffuse), Vec3(0.4, 0.5, 0.6));
  EXPECT_FLOAT_EQ(m.diffuse.a, 0.5f);
  EXPECT_EQ(Vec3(m.specular), Vec3(0.7, 0.8, 0.9));
  EXPECT_FLOAT_EQ(m.emission.r, 0.05f);
  EXPECT_EQ(m.shininess, 500);
}

TEST(FileMaterial, GltfMetallicRoughness) {
  FileMaterialValues v;
  v.isMetallicRoughness = true;
  v.diffuse = {0.8, 0.2, 0.1, 1};
  v.roughness = 0.5f;
  v.metallic = 0;
  const Material dielectric = materialFromFile(v);
  // Physically based, drawn with cook-torrance by default.
  EXPECT_TRUE(dielectric.physicallyBased);
  EXPECT_EQ(dielectric.model, LightingModel::CookTorrance);
  EXPECT_EQ(dielectric.physical.baseColor, Color3(Real(0.8), Real(0.2), Real(0.1)));
  EXPECT_EQ(dielectric.physical.roughness, 0.5f);
  EXPECT_EQ(dielectric.physical.metallic, 0);
  EXPECT_NEAR(dielectric.physical.f0.r, 0.04, 1e-6);  // glTF's dielectric: ior 1.5
  // Its GL parameters, for --model blinn-phong and the like.
  EXPECT_EQ(Vec3(dielectric.ambient), Vec3(0.8, 0.2, 0.1));  // no ambient in glTF: the base colour
  EXPECT_NEAR(dielectric.specular.r, 0.5, 1e-6);              // 2.5·√0.04
  EXPECT_NEAR(dielectric.shininess, 2 / (0.25 * 0.25) - 2, 1e-3);  // α = roughness² = 0.25
  v.metallic = 1;
  const Material metal = materialFromFile(v);
  EXPECT_NEAR(metal.specular.r, 0.8, 1e-6);  // metals reflect their base colour
  EXPECT_NEAR(metal.diffuse.r, 0, 1e-6);     // and have no diffuse part
  EXPECT_EQ(metal.physical.metallic, 1);
}

TEST(Import, NodeTransformsPlaceTheMeshes) {
  // 2CylinderEngine's meshes sit in a node hierarchy; its bounds in world space are known.
  const ImportedModel m = importModel("/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb");
  EXPECT_EQ(m.triangleCount, 121496u);
  EXPECT_EQ(m.materialCount, 35u);
  EXPECT_NEAR(m.boundsMin.x, -371.692, 1e-2);
  EXPECT_NEAR(m.boundsMax.y, 92.0416, 1e-2);
  EXPECT_NEAR(m.boundsMax.z, 128, 1e-2);
  const bool anyPlaced = std::any_of(m.objects.begin(), m.objects.end(), [](const Object& o) { return o.worldFromObject != Mat4(1); });
  EXPECT_TRUE(anyPlaced);
}

TEST(Import, StlGetsCreaseNormalsAndObjGetsItsMtl) {
  const ImportedModel stl = importModel("/usr/share/assimp/models/STL/Spider_binary.stl");
  ASSERT_FALSE(stl.objects.empty());
  // Generated normals are shared across smooth edges: fewer vertices than 3 per triangle.
  EXPECT_LT(stl.vertexCount, stl.triangleCount * 3);
  // --normals=file keeps STL's facet normals: the three corners of a triangle share its normal.
  // The generated ones vary across triangles where the surface is smooth.
  ImportOptions file;
  file.normals = NormalMode::File;
  const ImportedModel facets = importModel("/usr/share/assimp/models/STL/3DSMaxExport.STL", file);
  const ImportedModel smooth = importModel("/usr/share/assimp/models/STL/3DSMaxExport.STL");
  const auto varyingTriangles = [](const ImportedModel& model) {
    int n = 0;
    for (const Object& o : model.objects)
      for (std::size_t t = 0; t < o.mesh->indices.size(); t += 3) {
        // (assimp welds vertices whose normals agree to within a small epsilon)
        const Vec3& a = o.mesh->normals[o.mesh->indices[t]];
        if (glm::dot(a, o.mesh->normals[o.mesh->indices[t + 1]]) < 0.9999f ||
            glm::dot(a, o.mesh->normals[o.mesh->indices[t + 2]]) < 0.9999f)
          ++n;
      }
    return n;
  };
  EXPECT_EQ(varyingTriangles(facets), 0);
  EXPECT_GT(varyingTriangles(smooth), 1000);
  const ImportedModel obj = importModel("/usr/share/assimp/models/OBJ/cube_usemtl.obj");
  // cube_usemtl.mtl: Ns 200 and Ks 0.05 for "mtl", Ns 16 and Ks 0.375 for "mtl2".
  std::vector<Real> shininess;
  for (const Object& o : obj.objects) shininess.push_back(o.material.shininess);
  EXPECT_NE(std::find(shininess.begin(), shininess.end(), Real(200)), shininess.end());
  EXPECT_NE(std::find(shininess.begin(), shininess.end(), Real(16)), shininess.end());
}

TEST(Import, MtlKaKdKsKeNsDReachTheMaterial) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "illum_import_mtl_test";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "tri.mtl") << "newmtl shiny\nKa 0.1 0.2 0.3\nKd 0.4 0.5 0.6\nKs 0.7 0.8 0.9\nKe 0.05 0.06 0.07\nNs 500\nd 0.25\n";
  std::ofstream(dir / "tri.obj") << "mtllib tri.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl shiny\nf 1 2 3\n";
  const ImportedModel m = importModel(dir / "tri.obj");
  std::filesystem::remove_all(dir);
  ASSERT_EQ(m.objects.size(), 1u);
  const Material& mat = m.objects[0].material;
  EXPECT_NEAR(mat.ambient.b, 0.3, 1e-6);
  EXPECT_NEAR(mat.diffuse.g, 0.5, 1e-6);
  EXPECT_NEAR(mat.specular.r, 0.7, 1e-6);
  EXPECT_NEAR(mat.emission.b, 0.07, 1e-6);
  EXPECT_EQ(mat.shininess, 500);
  EXPECT_NEAR(mat.diffuse.a, 0.25, 1e-6);
  // No normals in the file: generated, facing the counter-clockwise side.
  EXPECT_NEAR(m.objects[0].mesh->normals[0].z, 1, 1e-6);
}

TEST(Framing, EveryPointInsideTheView) {
  std::vector<Vec3> points;
  for (int i = 0; i < 50; ++i) points.push_back({Real(i % 7) * 3 - 10, Real(i % 5) - 2, Real(i % 3) * 10 + 5});
  for (Real aspect : {Real(0.5), Real(1), Real(2)}) {
    ViewOptions o;
    o.up = {0, 0, 1};
    const Camera cam = framePoints(points, o, aspect);
    const Mat4 clipFromWorld = cam.clipFromView(aspect) * cam.viewFromWorld();
    Real widest = 0;
    for (const Vec3& p : points) {
      const Vec4 c = clipFromWorld * Vec4(p, 1);
      const Vec3 ndc = Vec3(c) / c.w;
      EXPECT_LE(std::abs(ndc.x), 1);
      EXPECT_LE(std::abs(ndc.y), 1);
      EXPECT_GT(ndc.z, -1);
      EXPECT_LT(ndc.z, 1);
      widest = std::max({widest, std::abs(ndc.x), std::abs(ndc.y)});
    }
    EXPECT_GT(widest, 0.85);  // and it fills the frame
  }
}

}  // namespace
}  // namespace illum

namespace illum {
namespace {

namespace fs = std::filesystem;

std::string base64(const std::vector<std::uint8_t>& bytes) {
  static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::uint32_t n = std::uint32_t(bytes[i]) << 16 | (i + 1 < bytes.size() ? bytes[i + 1] << 8 : 0) |
                            (i + 2 < bytes.size() ? bytes[i + 2] : 0);
    for (int k = 0; k < 4; ++k)
      out += std::size_t(k) <= (bytes.size() - i) * 4 / 3 ? digits[(n >> (18 - 6 * k)) & 63] : '=';
  }
  return out;
}

// A glTF quad whose material has all of glTF's maps, each a PNG of one colour beside the file;
// `baseColorInfo` and `otherInfo`: what the base colour's and the other maps' textureInfo objects
// hold besides their index (extensions).
fs::path writeMappedQuad(const fs::path& dir, const std::string& baseColorInfo = "", const std::string& otherInfo = "") {
  fs::create_directories(dir);
  const auto png = [&](const char* name, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    Image image(2, 2);
    for (std::size_t i = 0; i < 4; ++i) image.rgba[4 * i] = r, image.rgba[4 * i + 1] = g, image.rgba[4 * i + 2] = b, image.rgba[4 * i + 3] = 255;
    writePng(dir / name, image);
  };
  png("base.png", 200, 100, 50);
  png("mr.png", 0, 64, 255);
  png("normal.png", 128, 128, 255);
  png("emissive.png", 10, 20, 30);
  std::vector<std::uint8_t> buffer;
  const auto put = [&](const auto& values) {
    const auto* p = reinterpret_cast<const std::uint8_t*>(values.data());
    buffer.insert(buffer.end(), p, p + values.size() * sizeof(values[0]));
  };
  put(std::vector<float>{-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0});   // 48 bytes of positions
  put(std::vector<float>{0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1});       // 48 of normals
  put(std::vector<float>{0, 1, 1, 1, 1, 0, 0, 0});                   // 32 of uvs
  put(std::vector<std::uint16_t>{0, 1, 2, 0, 2, 3});                 // 12 of indices
  std::ofstream(dir / "quad.gltf") << R"({
  "asset": {"version": "2.0"}, "extensionsUsed": ["KHR_texture_transform"],
  "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}, "indices": 3, "material": 0}]}],
  "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0)" + baseColorInfo + R"(},
                                          "metallicRoughnessTexture": {"index": 1)" + otherInfo + R"(},
                                          "metallicFactor": 1, "roughnessFactor": 0.5},
                 "normalTexture": {"index": 2, "scale": 0.5)" + otherInfo + R"(},
                 "emissiveTexture": {"index": 3)" + otherInfo + R"(}, "emissiveFactor": [1, 1, 1]}],
  "textures": [{"source": 0}, {"source": 1}, {"source": 2}, {"source": 3}],
  "images": [{"uri": "base.png"}, {"uri": "mr.png"}, {"uri": "normal.png"}, {"uri": "emissive.png"}],
  "buffers": [{"byteLength": 140, "uri": "data:application/octet-stream;base64,)" + base64(buffer) + R"("}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 48},
                  {"buffer": 0, "byteOffset": 96, "byteLength": 32}, {"buffer": 0, "byteOffset": 128, "byteLength": 12}],
  "accessors": [
    {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-1, -1, 0], "max": [1, 1, 0]},
    {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3"},
    {"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC2"},
    {"bufferView": 3, "componentType": 5123, "count": 6, "type": "SCALAR"}]
})";
  return dir / "quad.gltf";
}

std::array<int, 3> firstTexel(const std::shared_ptr<const Texture>& t) {
  const Image image = t->baseImage();
  return {image.rgba[0], image.rgba[1], image.rgba[2]};
}

TEST(Import, GltfMapsReachTheObjectInProcessAndIsolated) {
  const fs::path file = writeMappedQuad(fs::temp_directory_path() / "illum_gltf_maps_test");
  for (bool isolated : {false, true}) {
    const ImportedModel m = isolated ? importModel(file) : importModelInProcess(file);
    ASSERT_EQ(m.objects.size(), 1u);
    const Object& o = m.objects[0];
    EXPECT_TRUE(m.warnings.empty()) << m.warnings.front();
    EXPECT_TRUE(o.material.physicallyBased);
    ASSERT_TRUE(o.diffuseTexture && o.maps.metallicRoughness && o.maps.normal && o.maps.emissive) << isolated;
    EXPECT_EQ(firstTexel(o.diffuseTexture), (std::array<int, 3>{200, 100, 50}));
    EXPECT_EQ(firstTexel(o.maps.metallicRoughness), (std::array<int, 3>{0, 64, 255}));
    EXPECT_EQ(firstTexel(o.maps.normal), (std::array<int, 3>{128, 128, 255}));
    EXPECT_EQ(firstTexel(o.maps.emissive), (std::array<int, 3>{10, 20, 30}));
    EXPECT_FLOAT_EQ(o.maps.normalScale, 0.5f);
    EXPECT_EQ(m.textureCount, 4u);
  }
  fs::remove_all(file.parent_path());
}

// KHR_texture_transform, as its specification states it: uv' = T·R·S·uv in glTF's texture space
// (v down; illum's coordinates have v up), R = [cos r, sin r; −sin r, cos r]. The quad's corners
// (0,1), (1,1), (1,0), (0,0) in glTF's space land where that matrix puts them, in process and
// through the child process.
TEST(Import, GltfTextureTransformIsBakedIntoTheCoordinates) {
  const std::string transform =
      R"(, "extensions": {"KHR_texture_transform": {"offset": [0.25, -0.5], "rotation": 0.5, "scale": [2, 3]}})";
  const fs::path file = writeMappedQuad(fs::temp_directory_path() / "illum_gltf_transform_test", transform, transform);
  const double r = 0.5, sx = 2, sy = 3, ox = 0.25, oy = -0.5;
  const std::array<std::array<double, 2>, 4> corners = {{{0, 1}, {1, 1}, {1, 0}, {0, 0}}};
  for (bool isolated : {false, true}) {
    const ImportedModel m = isolated ? importModel(file) : importModelInProcess(file);
    ASSERT_EQ(m.objects.size(), 1u);
    EXPECT_TRUE(m.warnings.empty()) << m.warnings.front();
    const std::vector<Vec2>& uvs = m.objects[0].mesh->uvs;
    ASSERT_EQ(uvs.size(), 4u);
    for (std::size_t i = 0; i < 4; ++i) {
      const double u = corners[i][0], v = corners[i][1];
      const double u2 = std::cos(r) * sx * u + std::sin(r) * sy * v + ox;
      const double v2 = -std::sin(r) * sx * u + std::cos(r) * sy * v + oy;
      EXPECT_NEAR(uvs[i].x, u2, 1e-5) << i << " " << isolated;
      EXPECT_NEAR(uvs[i].y, 1 - v2, 1e-5) << i << " " << isolated;
    }
  }
  fs::remove_all(file.parent_path());
}

// Khronos' TextureTransformTest (assimp-testmodels): each of its top row's squares reads UV.png
// offset by half of it, onto a coloured quarter that says "U", "V" or "UV" (green, blue, cyan);
// untransformed they read its yellow "not supported" quarter.
TEST(Import, TextureTransformTestsTopRowReadsItsOffsetQuarters) {
  const ImportedModel m = importModel("/usr/share/assimp/models/glTF2/textureTransform/TextureTransformTest.gltf");
  std::vector<Vec4> seen;
  for (const Object& o : m.objects) {
    if (!o.diffuseTexture || o.diffuseTexture->width() != m.objects[0].diffuseTexture->width()) continue;
    Vec2 mean(0);
    for (const Vec2& uv : o.mesh->uvs) mean += uv / Real(o.mesh->uvs.size());
    seen.push_back(o.diffuseTexture->sample(mean, 1));
  }
  ASSERT_GE(seen.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    const Vec4& c = seen[i];
    const bool yellow = c.r > 0.5 && c.g > 0.5 && c.b < 0.3;
    EXPECT_FALSE(yellow) << i << ": " << c.r << " " << c.g << " " << c.b;
    EXPECT_GT(std::max(c.g, c.b), 0.5) << i;
  }
}

// LightWave's spherical mapping (assimp-testmodels' earth): the texture gets coordinates of its own
// (assimp's GenUVCoords), v following the latitude, as the reference picture beside it shows.
TEST(Import, SphericallyMappedTexturesGetCoordinates) {
  const ImportedModel m = importModel("/usr/share/assimp/models/LWO/LWO2/MappingModes/earth_spherical_y.lwo");
  ASSERT_EQ(m.objects.size(), 1u);
  const Mesh& mesh = *m.objects[0].mesh;
  ASSERT_TRUE(m.objects[0].diffuseTexture);
  ASSERT_EQ(mesh.uvs.size(), mesh.positions.size());
  // v against the latitude's sine (the sphere is centred on its box): a correlation near ±1.
  Vec3 lo(1e30f), hi(-1e30f);
  for (const Vec3& p : mesh.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
  const Vec3 centre = (lo + hi) / Real(2);
  double sv = 0, sy = 0, svv = 0, syy = 0, svy = 0;
  const double n = double(mesh.uvs.size());
  for (std::size_t i = 0; i < mesh.uvs.size(); ++i) {
    const Vec3 d = glm::normalize(mesh.positions[i] - centre);
    const double v = mesh.uvs[i].y, y = std::asin(std::clamp(double(d.y), -1.0, 1.0));
    sv += v, sy += y, svv += v * v, syy += y * y, svy += v * y;
  }
  const double correlation = (svy - sv * sy / n) / std::sqrt((svv - sv * sv / n) * (syy - sy * sy / n));
  EXPECT_GT(std::abs(correlation), 0.99) << correlation;
}

// assimp's AMF reader fills a file without colours with transparent black vertex colours: no
// colours at all, drawn in the material's (not black, and no transparency to repair).
TEST(Import, PlaceholderVertexColoursAreNoColours) {
  const ImportedModel m = importModel("/usr/share/assimp/models/AMF/test1.amf");
  ASSERT_EQ(m.objects.size(), 1u);
  EXPECT_TRUE(m.objects[0].mesh->colors.empty());
  EXPECT_FALSE(m.transparencyIgnored);
  EXPECT_TRUE(m.warnings.empty()) << m.warnings.front();
}

// 3ds Max keeps a highlight's strength apart from its colour: 3DS's "shininess strength" 0.2
// scales the white specular colour to 0.2. A specular colour with no exponent (ASE's cubes, whose
// reader leaves it out) draws no highlight rather than GL's exponent 0 over the whole lit side.
TEST(Import, SpecularStrengthScalesTheColourAndNoExponentIsNoHighlight) {
  const ImportedModel strong = importModel("/usr/share/assimp/models/3DS/cube_with_specular_texture.3DS");
  ASSERT_FALSE(strong.objects.empty());
  EXPECT_NEAR(strong.objects[0].material.specular.r, 0.2, 1e-6);
  EXPECT_NEAR(strong.objects[0].material.shininess, 15, 1e-6);
  const ImportedModel cubes = importModel("/usr/share/assimp/models/ASE/ThreeCubesGreen.ASE");
  ASSERT_FALSE(cubes.objects.empty());
  for (const Object& o : cubes.objects) EXPECT_EQ(Color3(o.material.specular), Color3(0));
}

// A mirrored instance (FBX's negative scales) keeps its outside a front face: in world space every
// triangle's winding agrees with its vertices' normals, as it does in the file, so that GL's
// two-sided lighting lights the outside.
TEST(Import, MirroredInstancesKeepTheirFrontFaces) {
  for (const char* file : {"FBX/cubes_with_mirroring_and_pivot.fbx"}) {
    const ImportedModel m = importModel(fs::path("/usr/share/assimp/models") / file);
    std::size_t triangles = 0, agreeing = 0;
    bool mirrored = false;
    for (const Object& o : m.objects) {
      const Mat3 linear(o.worldFromObject);
      mirrored = mirrored || glm::determinant(linear) < 0;
      const Mat3 normalMatrix = glm::inverseTranspose(linear);
      const Mesh& mesh = *o.mesh;
      if (mesh.normals.empty()) continue;
      for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const std::uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
        const Vec3 geometric = glm::cross(linear * (mesh.positions[b] - mesh.positions[a]),
                                          linear * (mesh.positions[c] - mesh.positions[a]));
        const Vec3 shading = normalMatrix * (mesh.normals[a] + mesh.normals[b] + mesh.normals[c]);
        ++triangles;
        agreeing += glm::dot(geometric, shading) > 0;
      }
    }
    EXPECT_TRUE(mirrored) << file;
    EXPECT_GT(triangles, 0u) << file;
    EXPECT_EQ(agreeing, triangles) << file;
  }
}

// assimp's Blender reader gives each vertex its smooth normal even on solid ("Shade Flat") faces:
// Blender's default cube gets crease normals instead, flat faces as Blender draws it (every normal
// along an axis), unless --normals file asks for the file's.
TEST(Import, BlendersDefaultCubeHasFlatFaces) {
  const fs::path file = "/usr/share/assimp/models/BLEND/BlenderDefault_276.blend";
  const ImportedModel m = importModel(file);
  ASSERT_EQ(m.objects.size(), 1u);
  for (const Vec3& n : m.objects[0].mesh->normals)
    EXPECT_NEAR(std::max({std::abs(n.x), std::abs(n.y), std::abs(n.z)}), 1, 1e-5) << n.x << " " << n.y << " " << n.z;
  ImportOptions fileNormals;
  fileNormals.normals = NormalMode::File;
  const ImportedModel kept = importModel(file, fileNormals);
  const Vec3 n = kept.objects[0].mesh->normals[0];
  EXPECT_LT(std::max({std::abs(n.x), std::abs(n.y), std::abs(n.z)}), 0.99f);  // the corner's smooth normal
}

// MD5's mesh names no shader image: an empty texture name is no texture, and nothing to warn of.
TEST(Import, AnEmptyTextureNameIsNoTexture) {
  const ImportedModel m = importModel("/usr/share/assimp/models/MD5/SimpleCube.md5mesh");
  ASSERT_FALSE(m.objects.empty());
  EXPECT_FALSE(m.objects[0].diffuseTexture);
  EXPECT_TRUE(m.warnings.empty()) << m.warnings.front();
}

// A material with a texture on a mesh without coordinates is drawn untextured, and says so.
TEST(Import, TexturesWithoutCoordinatesAreReported) {
  const fs::path dir = fs::temp_directory_path() / "illum_texture_without_uvs_test";
  fs::create_directories(dir);
  writePng(dir / "t.png", Image(2, 2));
  std::ofstream(dir / "m.mtl") << "newmtl textured\nKd 1 1 1\nmap_Kd t.png\n";
  std::ofstream(dir / "m.obj") << "mtllib m.mtl\nusemtl textured\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  const ImportedModel m = importModel(dir / "m.obj");
  ASSERT_EQ(m.warnings.size(), 1u);
  EXPECT_NE(m.warnings[0].find("no texture coordinates"), std::string::npos) << m.warnings[0];
  fs::remove_all(dir);
}

// One set of coordinates per mesh: where the maps transform theirs otherwise than the base colour,
// the base colour's transform is the one kept, and a warning names the material.
TEST(Import, GltfTexturesTransformedOtherwiseAreSampledWithTheBaseColoursAndSaySo) {
  const fs::path file = writeMappedQuad(fs::temp_directory_path() / "illum_gltf_mixed_transform_test",
                                        R"(, "extensions": {"KHR_texture_transform": {"offset": [0.5, 0]}})");
  const ImportedModel m = importModel(file);
  ASSERT_EQ(m.objects.size(), 1u);
  ASSERT_EQ(m.warnings.size(), 1u);
  EXPECT_NE(m.warnings[0].find("transform them differently"), std::string::npos) << m.warnings[0];
  const std::vector<Vec2>& uvs = m.objects[0].mesh->uvs;
  ASSERT_EQ(uvs.size(), 4u);
  EXPECT_NEAR(uvs[0].x, 0.5, 1e-6);  // glTF (0, 1): GL (0, 0), moved half a texture right
  EXPECT_NEAR(uvs[0].y, 0, 1e-6);
  EXPECT_NEAR(uvs[1].x, 1.5, 1e-6);
  fs::remove_all(file.parent_path());
}

// BoxTextured's sampler says MIRRORED_REPEAT across (its u runs 0 to 6 around the box, every
// other face read backwards) and CLAMP_TO_EDGE up: the texture keeps both, through the child
// process too.
TEST(Import, SamplerWrapModesReachTheTexture) {
  const fs::path file = "/usr/share/assimp/models/glTF2/BoxTextured-glTF/BoxTextured.gltf";
  for (bool isolated : {false, true}) {
    const ImportedModel m = isolated ? importModel(file) : importModelInProcess(file);
    ASSERT_EQ(m.objects.size(), 1u);
    ASSERT_TRUE(m.objects[0].diffuseTexture);
    EXPECT_EQ(m.objects[0].diffuseTexture->wraps(),
              (TextureWraps{TextureWrap::MirroredRepeat, TextureWrap::ClampToEdge}))
        << isolated;
  }
  // Without a sampler's word: repeat, as GL's default.
  const ImportedModel duck = importModel("/usr/share/assimp/models/Collada/duck.dae");
  ASSERT_TRUE(duck.objects[0].diffuseTexture);
  EXPECT_EQ(duck.objects[0].diffuseTexture->wraps(), TextureWraps{});
}

// Khronos' clear-coat test asset (assimp-testmodels) names every kind of map: its normal-mapped
// rows, its roughness-striped coating and its emissive labels all arrive.
TEST(Import, ClearCoatTestAssetHasItsMaps) {
  const ImportedModel m = importModel("/usr/share/assimp/models/glTF2/ClearCoat-glTF/ClearCoatTest.gltf");
  std::size_t normal = 0, mr = 0, emissive = 0;
  for (const Object& o : m.objects) normal += o.maps.normal != nullptr, mr += o.maps.metallicRoughness != nullptr,
                                    emissive += o.maps.emissive != nullptr;
  EXPECT_GE(normal, 4u);
  EXPECT_GE(mr, 1u);
  EXPECT_GE(emissive, 1u);
}

}  // namespace
}  // namespace illum
