// What a frame's draw target works out per object: which objects are lit alike and so share an
// owner in Phong's visible surface.
#include "raster/shade/draw.h"

#include <illum/mesh.h>

#include <gtest/gtest.h>

namespace illum {
namespace {

TEST(DrawTarget, ObjectsLitAlikeShareTheFirstOnesOwner) {
  Scene scene;
  scene.shading = Shading::Phong;
  const auto sphere = std::make_shared<const Mesh>(makeSphere(1, 8, 4));
  Mesh coloured = makeSphere(1, 8, 4);
  coloured.colors.assign(coloured.positions.size(), Color4(1, 0, 0, 1));
  const auto colouredSphere = std::make_shared<const Mesh>(coloured);
  Material shiny, dull;
  shiny.specular = {1, 1, 1, 1};
  shiny.shininess = 20;
  Material lambert = shiny;
  lambert.model = LightingModel::Lambert;
  const struct {
    const Material& material;
    std::shared_ptr<const Mesh> mesh;
  } objects[] = {{shiny, sphere}, {shiny, sphere}, {dull, sphere}, {shiny, sphere}, {shiny, colouredSphere},
                 {lambert, sphere}, {dull, sphere}};
  for (const auto& [material, mesh] : objects) {
    Object o;
    o.mesh = mesh;
    o.material = material;
    scene.objects.push_back(o);
  }
  const FrameContext frame = FrameContext::fromScene(scene);
  Framebuffer fb;
  const DrawTarget target(frame, scene, fb, nullptr);
  // Another material, vertex colours or another lighting model each make a new owner.
  EXPECT_EQ(target.shadeOwner, (std::vector<std::uint32_t>{0, 0, 2, 0, 4, 5, 2}));
}

}  // namespace
}  // namespace illum
