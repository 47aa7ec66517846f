// What a user's program does with illum: a model file and a scene built in code drawn in memory, an
// equation evaluated, a refused option caught by type. Prints what the test checks.
#include <illum/illum.h>

#include <cmath>
#include <cstdio>
#include <fstream>

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: consumer MODEL OUT.png\n");
    return 64;
  }
  const illum::Picture model = illum::render(argv[1], {{"resolution", "200,150"}, {"camera_azimuth_angle", "30"}});
  const std::vector<std::uint8_t> png = model.png();
  std::ofstream(argv[2], std::ios::binary).write(reinterpret_cast<const char*>(png.data()), std::streamsize(png.size()));

  // A scene built in code: one sphere lit head-on; the centre pixel is kd·Ld·cos 0, sRGB-encoded.
  const std::string scene = R"({"version": 1, "width": 64, "height": 64, "encoding": "linear",
    "camera": {"eye": [0, 0, 5], "center": [0, 0, 0], "up": [0, 1, 0], "fovy": 30},
    "lights": [{"position": [0, 0, 1, 0], "diffuse": [1, 1, 1], "specular": [0, 0, 0]}],
    "objects": [{"mesh": {"type": "sphere"}, "material": {"ambient": [0, 0, 0], "diffuse": [0.6, 0.2, 1],
                 "specular": [0, 0, 0]}}]})";
  const illum::Picture sphere = illum::render(illum::Source::sceneJson(scene));
  const std::uint8_t* centre = &sphere.rgba[(32 * 64 + 32) * 4];

  const illum::Terms t = illum::evaluate({{"model", "lambert"}, {"angle_nl", "60"}, {"material_diffuse", "1,1,1"}});
  std::string refused;
  try {
    illum::render("", {{"size", "3"}});
  } catch (const illum::InputError& e) {
    refused = e.what();
  }
  std::printf("version %s\nmodel %dx%d\nsphere centre %d %d %d\ndiffuse at 60 degrees %.4f\nrefused: %s\n",
              illum::version(), model.width, model.height, centre[0], centre[1], centre[2], t.diffuse[0], refused.c_str());
  return 0;
}
