// What a frame keeps in memory: a tile that no object still to be drawn can reach is finished as
// soon as its last object is (resolved into the picture, its samples' memory given back), so a
// scene of many objects holds the samples of the tiles its objects in progress reach, not the
// frame's; and the picture is the reference driver's, bit for bit.
#include "raster/pipeline.h"

#include "raster/reference/reference_pipeline.h"
#include "raster/tile/framebuffer.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace illum {
namespace {

// Sixteen dense spheres in a row, each in a band of two tile columns of its own (a 2048×64
// frame seen at 3°: 32 pixels a unit, 4 units a band), 16 thousand triangles each: set up and
// drawn over several batches.
Scene rowOfSpheres(int samples) {
  Scene scene = defaultScene();
  scene.width = 2048, scene.height = 64, scene.multisample = samples;
  scene.camera = Camera{};
  scene.camera.eye = {0, 0, 38.2f};
  scene.camera.fovy = 3, scene.camera.near = 30, scene.camera.far = 50;
  const Object like = scene.objects.front();
  const auto sphere = std::make_shared<const Mesh>(makeSphere(Real(0.5), 128, 64));
  scene.objects.clear();
  for (int i = 0; i < 16; ++i) {
    Object o = like;
    o.mesh = sphere;
    o.worldFromObject = glm::translate(Mat4(1), Vec3(Real(4 * i + 2 - 32), 0, 0));
    scene.objects.push_back(o);
  }
  return scene;
}

TEST(RasterPipeline, TilesFinishedBeforeTheFrameGiveTheirSamplesBack) {
  for (int samples : {1, 4, 8}) {
    const Scene scene = rowOfSpheres(samples);
    RasterPipeline pipeline;
    Image image, reference;
    RenderStats stats, referenceStats;
    pipeline.draw(scene, image, stats, nullptr);
    drawSceneReference(scene, reference, referenceStats);
    EXPECT_EQ(image.rgba, reference.rgba) << samples;
    EXPECT_EQ(stats.pixelsDrawn, referenceStats.pixelsDrawn) << samples;
    EXPECT_GT(stats.pixelsDrawn, 16u * 600u) << samples;
    // The spheres reach 32 tiles. Multisampled, every triangle is a record, and the batches of
    // records hold a few spheres each: a batch's tiles are finished when it is drawn, but the
    // sphere it stopped in, so a few tiles are held at once (kept to the frame's end, every tile
    // drawn before the last batch would be: 24 of them). At 1 sample the spheres' tiny triangles
    // fit one batch, drawn tile by tile in lent memory.
    EXPECT_LE(pipeline.tileBlocksMade(), 8u) << samples;
    // The next frame reuses the blocks, and draws the same.
    Image again;
    pipeline.draw(scene, again, stats, nullptr);
    EXPECT_EQ(again.rgba, image.rgba) << samples;
    EXPECT_LE(pipeline.tileBlocksMade(), 8u) << samples;
  }
}

}  // namespace
}  // namespace illum
