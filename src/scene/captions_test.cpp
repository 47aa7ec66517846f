#include <illum/captions.h>

#include <illum/error.h>

#include <gtest/gtest.h>

namespace illum {
namespace {

std::vector<std::string> captions(const Scene& scene) {
  std::vector<std::string> out;
  for (const Label& l : scene.labels) out.push_back(expandCaption(l.text, scene));
  return out;
}

bool has(const std::vector<std::string>& texts, const std::string& text) {
  return std::find(texts.begin(), texts.end(), text) != texts.end();
}

// The built-in scene's captions name each highlight as the model drawing it sees it, and the
// titles the model and the shading drawn: `--model lambert` does not keep "plastic, n = 60".
TEST(Captions, TheBuiltInSceneSaysWhatEachModelDraws) {
  const std::vector<std::string> blinn = captions(defaultScene(LightingModel::BlinnPhong, Shading::Phong));
  EXPECT_TRUE(has(blinn, "plastic, n = 60"));
  EXPECT_TRUE(has(blinn, "matte, no specular"));
  EXPECT_TRUE(has(blinn, "Blinn-Phong: ambient + diffuse (N·L) + specular (N·H)ⁿ"));
  const std::vector<std::string> lambert = captions(defaultScene(LightingModel::Lambert, Shading::Gouraud));
  EXPECT_TRUE(has(lambert, "plastic, no specular"));
  EXPECT_TRUE(has(lambert, "Lambert: ambient + diffuse (N·L), no specular"));
  EXPECT_TRUE(has(lambert, "Gouraud shading: lit per vertex, colours interpolated"));
  const std::vector<std::string> ct = captions(defaultScene(LightingModel::CookTorrance, Shading::Phong));
  // α = √(2/(n+2)) and roughness = √α (lighting.h): n = 60 is roughness 0.4253.
  EXPECT_TRUE(has(ct, "plastic, roughness " + [] {
    char b[32];
    std::snprintf(b, sizeof b, "%g", double(std::sqrt(std::sqrt(2.0f / 62))));
    return std::string(b);
  }())) << ct[0];
  // A scene changed after it was made (what a sheet's axis does) is captioned as it is drawn.
  Scene moved = defaultScene();
  moved.model = LightingModel::Phong;
  moved.renderer = RendererKind::Whitted;
  moved.objects[0].material.shininess = 7;
  const std::vector<std::string> now = captions(moved);
  EXPECT_TRUE(has(now, "plastic, n = 7"));
  EXPECT_TRUE(has(now, "Whitted ray tracing (1980): shadows, mirror and refracted rays"));
}

TEST(Captions, PlaceholdersNameLightsAndMaterials) {
  Scene s;
  Light l;
  l.position = Vec4(1, 2, 3, 1);
  l.attenuation = Vec3(0, 0, 1);
  l.spotCutoff = 36;
  s.lights = {l};
  Object o;
  o.material.diffuse = Color4(0.5, 0.25, 1, 1);
  o.material.shininess = 25;
  s.objects = {o};
  EXPECT_EQ(expandCaption("light at {light.0.position}", s), "light at (1, 2, 3, 1)");
  EXPECT_EQ(expandCaption("{light.0.attenuation}, cutoff {light.0.spot_cutoff}°", s), "(0, 0, 1), cutoff 36°");
  EXPECT_EQ(expandCaption("kd = {object.0.material.diffuse}, n = {object.0.material.shininess}", s), "kd = (0.5, 0.25, 1), n = 25");
  EXPECT_EQ(expandCaption("no placeholder", s), "no placeholder");
  EXPECT_EQ(expandCaption("{convention}", s), "gl");
  s.lightModel.convention = Convention::NoteShader;
  EXPECT_EQ(expandCaption("{convention}: {model.description}", s),
            "note-shader: Blinn-Phong as seed 001's shader: ambient + (diffuse + specular (N·H)ⁿ)·(N·L)");
}

TEST(Captions, AnUnknownPlaceholderIsRefusedWithWhatThereIs) {
  Scene s;
  s.lights.resize(1);
  const auto message = [&](const std::string& text) {
    try {
      expandCaption(text, s);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(message("{light.2.position}"), "{light.2.position}: the scene has 1 light (light.0 .. light.0)");
  EXPECT_NE(message("{light.0.colour}").find("expected light.N.position, ambient"), std::string::npos);
  EXPECT_NE(message("{object.0.highlight}").find("the scene has 0 objects"), std::string::npos);
  EXPECT_NE(message("{lightz}").find("expected {model}"), std::string::npos);
  EXPECT_NE(message("open {model").find("a { without its }"), std::string::npos);
  // A scene file's caption is checked as it is read, by its JSON path.
  try {
    parseScene(R"({"labels": [{"text": "light at {light.3.position}", "pixel": [10, 10]}]})", "s.json", ".");
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("s.json: /labels/0/text: {light.3.position}: the scene has 1 light"), std::string::npos)
        << e.what();
  }
}

// Why a black picture is black, from where the lights reach (the vertices, as GL lights them).
TEST(Captions, WhyUnlitNamesTheReason) {
  Scene s;
  Object floor;
  Mesh quad;
  quad.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  quad.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  quad.indices = {0, 1, 2, 0, 2, 3};
  floor.mesh = std::make_shared<const Mesh>(quad);
  s.objects = {floor};
  s.lights.clear();
  EXPECT_EQ(whyUnlit(s), "no light");
  Light spot;
  spot.position = Vec4(0, 0, 1.5, 1);
  spot.spotDirection = Vec3(0, 0, -1);
  spot.spotCutoff = 36;  // the corners are 43° off the axis
  s.lights = {spot};
  s.shading = Shading::Gouraud;
  EXPECT_EQ(whyUnlit(s), "no vertex lies inside a spot's cone (gouraud shading lights vertices only)");
  s.shading = Shading::Phong;
  EXPECT_EQ(whyUnlit(s), "outside every spot's cone");
  s.lights[0].spotCutoff = 50;
  EXPECT_EQ(whyUnlit(s), "");
  s.lights[0].position = Vec4(0, 0, -1.5, 1);  // below the floor
  s.lights[0].spotDirection = Vec3(0, 0, 1);
  EXPECT_EQ(whyUnlit(s), "every light is behind the surfaces");
}

}  // namespace
}  // namespace illum
