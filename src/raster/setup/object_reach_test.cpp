// An object's reach holds every pixel its triangles can cover, wherever it lies, and is the
// whole frame or nothing where it must be.
#include "raster/setup/object_reach.h"

#include "raster/setup/draw_record.h"
#include "raster/setup/vertex.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <random>

namespace illum {
namespace {

Scene sceneOf(Object object, int width, int height) {
  Scene scene = defaultScene();
  scene.width = width, scene.height = height;
  scene.objects = {std::move(object)};
  return scene;
}

// The pixels the object's set-up triangles' bounds span (every clipped piece's), or none.
PixelRect boundsOfTriangles(const Scene& scene) {
  const FrameContext frame = FrameContext::fromScene(scene);
  const Object& object = scene.objects[0];
  std::vector<ShadedVertex> vertices(object.mesh->positions.size());
  runVertexStage(frame, object, 0, vertices, 0, vertices.size());
  RecordArena records;
  records.reset(AttributeLayout::forObject(frame, object, false));
  setupTriangles(frame, object, 0, vertices, 0, object.mesh->triangleCount(), records);
  PixelRect r{frame.width, frame.height, -1, -1};
  for (std::size_t i = 0; i < records.size(); ++i) {
    const TriangleSetup& t = records[i].setup;
    r.minX = std::min(r.minX, t.minX), r.minY = std::min(r.minY, t.minY);
    r.maxX = std::max(r.maxX, t.maxX), r.maxY = std::max(r.maxY, t.maxY);
  }
  return r;
}

TEST(ObjectReach, HoldsEveryTriangleOfTheObjectWhereverItLies) {
  std::mt19937 random(7);
  std::uniform_real_distribution<float> offset(-4, 4), angle(0, 6.2831853f), size(0.05f, 1.5f);
  // A cube's box corners are its vertices: its triangles reach the very edge of the projected box.
  const auto cube = std::make_shared<const Mesh>(makeCube(2)), sphere = std::make_shared<const Mesh>(makeSphere(1, 24, 12));
  int partly = 0, inside = 0;
  for (int i = 0; i < 400; ++i) {
    Object object = defaultScene().objects[0];
    object.mesh = i % 2 ? sphere : cube;
    object.worldFromObject = glm::translate(Mat4(1), Vec3(offset(random), offset(random), offset(random) - 2)) *
                             glm::rotate(Mat4(1), angle(random), glm::normalize(Vec3(1, 2, 3))) *
                             glm::scale(Mat4(1), Vec3(size(random), size(random), size(random)));
    const Scene scene = sceneOf(object, 320, 200);
    const PixelRect reach = objectReach(FrameContext::fromScene(scene), scene.objects[0]);
    const PixelRect drawn = boundsOfTriangles(scene);
    if (drawn.minX > drawn.maxX) continue;  // nothing set up: off screen or clipped away
    EXPECT_LE(reach.minX, drawn.minX) << i;
    EXPECT_LE(reach.minY, drawn.minY) << i;
    EXPECT_GE(reach.maxX, drawn.maxX) << i;
    EXPECT_GE(reach.maxY, drawn.maxY) << i;
    const bool whole = reach.minX == 0 && reach.minY == 0 && reach.maxX == 319 && reach.maxY == 199;
    inside += !whole;
    partly += !whole && (drawn.minX == 0 || drawn.maxX == 319 || drawn.minY == 0 || drawn.maxY == 199);
  }
  // Most of them were narrowed down, some of those at the frame's edge.
  EXPECT_GT(inside, 150);
  EXPECT_GT(partly, 10);
}

TEST(ObjectReach, IsTheProjectedBoxWidenedByItsMargin) {
  // A cube of side 2 at the origin, seen from z = 5 at 90°: its near face, at distance 4, spans
  // a quarter of the half-height each way, pixels 75 to 125 of 200; then 8 pixels of margin (each
  // end within a pixel: the matrices are floats).
  Object cube = defaultScene().objects[0];
  cube.mesh = std::make_shared<const Mesh>(makeCube(2));
  cube.worldFromObject = Mat4(1);
  Scene scene = sceneOf(cube, 200, 200);
  scene.camera = Camera{};
  scene.camera.eye = {0, 0, 5};
  scene.camera.fovy = 90;
  const PixelRect reach = objectReach(FrameContext::fromScene(scene), scene.objects[0]);
  EXPECT_NEAR(reach.minX, 67, 1);
  EXPECT_NEAR(reach.maxX, 133, 1);
  EXPECT_NEAR(reach.minY, 67, 1);
  EXPECT_NEAR(reach.maxY, 133, 1);
}

TEST(ObjectReach, IsTheWholeFrameAcrossTheEyeAndNothingOffScreen) {
  Object object = defaultScene().objects[0];
  object.mesh = std::make_shared<const Mesh>(makeSphere(1, 16, 8));
  object.worldFromObject = glm::translate(Mat4(1), Vec3(0, 0, 5));  // around the eye
  Scene scene = sceneOf(object, 160, 120);
  scene.camera = Camera{};  // at z = 5, looking down −z
  PixelRect r = objectReach(FrameContext::fromScene(scene), scene.objects[0]);
  EXPECT_TRUE(r.minX == 0 && r.minY == 0 && r.maxX == 159 && r.maxY == 119);
  scene.objects[0].worldFromObject = glm::translate(Mat4(1), Vec3(40, 0, 0));  // far to the right
  r = objectReach(FrameContext::fromScene(scene), scene.objects[0]);
  EXPECT_GT(r.minX, r.maxX);
  scene.objects[0].worldFromObject = glm::translate(Mat4(1), Vec3(0, -40, 0));  // far below
  r = objectReach(FrameContext::fromScene(scene), scene.objects[0]);
  EXPECT_GT(r.minY, r.maxY);
}

TEST(TileReach, NamesTheLastObjectThatReachesEachTile) {
  // Two small cubes (side 1/4) in a 256×64 frame seen at 90° from z = 2, 2.5 units left and right
  // of the middle: their near faces (at distance 1.875, 17 pixels a unit across) project to
  // pixels 83–88 and 168–173, with the margin 75–96 and 160–181: tiles 1 and 2. Tiles 0 and 3
  // no object reaches.
  Scene scene = defaultScene();
  scene.width = 256, scene.height = 64;
  scene.camera = Camera{};
  scene.camera.eye = {0, 0, 2};
  scene.camera.fovy = 90;
  Object cube = scene.objects[0];
  cube.mesh = std::make_shared<const Mesh>(makeCube(Real(0.25)));
  Object left = cube, right = cube, empty = cube;
  left.worldFromObject = glm::translate(Mat4(1), Vec3(-2.5f, 0, 0));
  right.worldFromObject = glm::translate(Mat4(1), Vec3(2.5f, 0, 0));
  empty.mesh = std::make_shared<const Mesh>();  // no triangles: not among the objects drawn
  const FrameContext frame = FrameContext::fromScene(scene);
  EXPECT_EQ(objectReach(frame, left).minX / kTileSize, 1);
  EXPECT_EQ(objectReach(frame, left).maxX / kTileSize, 1);
  EXPECT_EQ(objectReach(frame, right).minX / kTileSize, 2);
  EXPECT_EQ(objectReach(frame, right).maxX / kTileSize, 2);
  TileReach reach;
  const Object* order[] = {&left, &empty, &right};
  ASSERT_TRUE(reach.find(frame, order));
  EXPECT_TRUE(reach.reachedOnlyBefore(0, 0));   // nothing reaches it
  EXPECT_FALSE(reach.reachedOnlyBefore(1, 0));  // the left cube's: done once it is set up
  EXPECT_TRUE(reach.reachedOnlyBefore(1, 1));
  EXPECT_FALSE(reach.reachedOnlyBefore(2, 2));  // the right cube's: once it is too (third in the order)
  EXPECT_TRUE(reach.reachedOnlyBefore(2, 3));
  EXPECT_TRUE(reach.reachedOnlyBefore(3, 0));
  // The left cube drawn again last: its tile waits for that.
  const Object* leftAgain[] = {&left, &right, &left};
  ASSERT_TRUE(reach.find(frame, leftAgain));
  EXPECT_FALSE(reach.reachedOnlyBefore(1, 2));
  EXPECT_TRUE(reach.reachedOnlyBefore(1, 3));
  EXPECT_TRUE(reach.reachedOnlyBefore(2, 2));
  // One object drawn: nothing is worked out.
  const Object* one[] = {&left, &empty};
  EXPECT_FALSE(reach.find(frame, one));
}

}  // namespace
}  // namespace illum
