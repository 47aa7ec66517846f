// The path tracer against physics: the white furnace, a Lambertian plane under a uniform sky, one
// bounce from a point light against the rasterizer's per-pixel Lambert image, error falling as
// 1/√samples, and the same bytes for any thread count.
#include <illum/render.h>
#include <illum/scene.h>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <fstream>
#include <stdexcept>
#include <string>
#include <unistd.h>

namespace illum {
namespace {

// A quad p0 p1 p2 p3, counter-clockwise seen from its front, with its face normal.
std::shared_ptr<const Mesh> quad(Vec3 p0, Vec3 p1, Vec3 p2, Vec3 p3) {
  Mesh m;
  m.positions = {p0, p1, p2, p3};
  m.normals.assign(4, glm::normalize(glm::cross(p1 - p0, p2 - p0)));
  m.indices = {0, 1, 2, 0, 2, 3};
  return std::make_shared<const Mesh>(std::move(m));
}

Material lambertian(Real albedo) {
  Material m;
  m.ambient = m.diffuse = Color4(Color3(albedo), 1);
  return m;
}

Scene pathScene(int size) {
  Scene s;
  s.width = s.height = size;
  s.renderer = RendererKind::Path;
  s.lights.clear();
  s.background = {0, 0, 0, 1};
  s.camera.eye = {0, 0, 4};
  return s;
}

// A Lambertian wall across the view of pathScene's camera, facing it (+Z), in the plane z = 0.
Object wallFacingTheCamera(Real albedo) {
  Object wall;
  wall.mesh = quad({-3, -3, 0}, {3, -3, 0}, {3, 3, 0}, {-3, 3, 0});
  wall.material = lambertian(albedo);
  return wall;
}

// pathScene with the denoiser at `samples` a pixel, the wall (albedo 0.5) filling its view.
Scene denoisedWallScene(int samples) {
  Scene s = pathScene(32);
  s.rayTracing.samples = samples;
  s.rayTracing.denoise = true;
  s.objects.push_back(wallFacingTheCamera(0.5f));
  return s;
}

// Mean and extremes of the linear values of the pixels an object covers whole (every sample hit it).
struct Stats {
  double mean = 0, min = 1e30, max = -1e30;
  int count = 0;
};
Stats over(const FloatImage& image, const Image& coverage) {
  Stats s;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      if (coverage.pixel(x, y)[3] != 255) continue;  // the background (alpha 0) shows, at least in part
      const double v = image.pixel(x, y)[0];
      s.mean += v, s.min = std::min(s.min, v), s.max = std::max(s.max, v), ++s.count;
    }
  s.mean /= std::max(1, s.count);
  return s;
}

// An object alone in a uniform environment of radiance 0.5, with no lights: what the pixels it
// covers whole show.
Stats inTheFurnace(const Object& object, int size, int samples) {
  Scene s = pathScene(size);
  s.background = {0, 0, 0, 0};
  s.rayTracing.environment = Color3(0.5f);
  s.rayTracing.samples = samples;
  s.rayTracing.maxDepth = 16;
  s.objects.push_back(object);
  FloatImage linear;
  const Image image = renderScene(s, nullptr, nullptr, &linear);
  return over(linear, image);
}

TEST(PathTracer, WhiteFurnace) {
  // A white Lambertian object reflects all it receives, so it shows the environment's 0.5
  // everywhere. A sphere reflects every path straight out (no variance at all); a torus sends some
  // paths around itself several times (Russian roulette keeps it unbiased).
  Object o;
  o.worldFromObject = glm::rotate(Mat4(1), glm::radians(Real(60)), Vec3(1, 0, 0));
  o.material = lambertian(1);
  o.mesh = std::make_shared<const Mesh>(makeSphere(1, 32, 16));
  const Stats sphere = inTheFurnace(o, 48, 4);
  ASSERT_GT(sphere.count, 200);
  EXPECT_NEAR(sphere.min, 0.5, 1e-5);
  EXPECT_NEAR(sphere.max, 0.5, 1e-5);
  o.mesh = std::make_shared<const Mesh>(makeTorus(0.4f, 1, 24, 48));
  const Stats torus = inTheFurnace(o, 48, 256);
  ASSERT_GT(torus.count, 200);
  EXPECT_NEAR(torus.mean, 0.5, 0.01);
}

TEST(PathTracer, MirrorsAndGlassConserveEnergyInTheFurnace) {
  // A perfect mirror shows the environment behind the camera exactly; a glass sphere (reflecting F,
  // refracting 1 − F, at any depth) sends every path out again: 0.5 everywhere, within noise.
  Object o;
  o.mesh = std::make_shared<const Mesh>(makeSphere(1, 48, 24));
  o.material = lambertian(0);
  o.optics.reflective = Color3(1);
  const Stats mirror = inTheFurnace(o, 32, 4);
  ASSERT_GT(mirror.count, 250);
  EXPECT_NEAR(mirror.min, 0.5, 1e-5);
  EXPECT_NEAR(mirror.max, 0.5, 1e-5);
  o.optics = SurfaceOptics{};
  o.optics.transmissive = Color3(1);
  const Stats glass = inTheFurnace(o, 32, 128);
  EXPECT_NEAR(glass.mean, 0.5, 0.01);
}

TEST(PathTracer, APartMirrorSendsItsShareOfAPixelsSamplesToTheMirror) {
  // A sphere that is half mirror, its BSDF black: a path that takes the mirror sees the furnace's
  // 0.5, one that takes the BSDF nothing. The choice is stratified over the pixel's samples, so
  // every pixel's 16 samples send exactly 8 to the mirror: 0.25 everywhere, not a binomial spread
  // around it (independent choices gave pixels from 0.0625 to 0.4375).
  Object o;
  o.mesh = std::make_shared<const Mesh>(makeSphere(1, 48, 24));
  o.material = lambertian(0);
  o.material.specular = Color4(0, 0, 0, 1);
  o.optics.reflective = Color3(0.5f);
  const Stats half = inTheFurnace(o, 32, 16);
  ASSERT_GT(half.count, 250);
  EXPECT_NEAR(half.min, 0.25, 1e-5);
  EXPECT_NEAR(half.max, 0.25, 1e-5);
}

TEST(PathTracer, ALambertianPlaneUnderAUniformSkyHasAlbedoTimesSky) {
  Scene s = pathScene(16);
  s.camera.projection = Projection::Orthographic;
  s.rayTracing.environment = {0.5f, 1.0f, 0.25f};
  s.rayTracing.samples = 8;
  Object plane;
  plane.mesh = quad({-50, -50, 0}, {50, -50, 0}, {50, 50, 0}, {-50, 50, 0});
  plane.material = lambertian(0.6f);
  s.objects.push_back(plane);
  FloatImage linear;
  renderScene(s, nullptr, nullptr, &linear);
  for (int y = 0; y < 16; y += 5)
    for (int x = 0; x < 16; x += 5) {
      EXPECT_NEAR(linear.pixel(x, y)[0], 0.6 * 0.5, 1e-5);
      EXPECT_NEAR(linear.pixel(x, y)[1], 0.6 * 1.0, 1e-5);
      EXPECT_NEAR(linear.pixel(x, y)[2], 0.6 * 0.25, 1e-5);
    }
}

TEST(PathTracer, AnEnvironmentMapLightsWhatSeesItsBrightHalf) {
  // A Radiance .hdr sky: radiance 2 above the horizon, 0 below (64×32, flat RGBE). A plane facing
  // up sees the bright half only: radiance = albedo × 2. Facing down it sees nothing.
  const auto path = std::filesystem::temp_directory_path() / ("illum_sky_" + std::to_string(::getpid()) + ".hdr");
  {
    std::ofstream out(path, std::ios::binary);
    out << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 32 +X 64\n";
    for (int y = 0; y < 32; ++y)
      for (int x = 0; x < 64; ++x) {
        const unsigned char bright[4] = {128, 128, 128, 130}, dark[4] = {0, 0, 0, 0};  // 128·2^(130−136) = 2
        out.write(reinterpret_cast<const char*>(y < 16 ? bright : dark), 4);
      }
  }
  for (const bool up : {true, false}) {
    Scene s = pathScene(8);
    s.camera.projection = Projection::Orthographic;
    s.camera.eye = {0, up ? 5.0f : -5.0f, 0};
    s.camera.up = {0, 0, -1};
    s.rayTracing.samples = 256;
    s.rayTracing.environmentMap = EnvironmentMapFile::open(path, Limits{});
    s.rayTracing.environment = Color3(1);
    Object plane;
    plane.mesh = up ? quad({-50, 0, 50}, {50, 0, 50}, {50, 0, -50}, {-50, 0, -50})
                    : quad({-50, 0, 50}, {-50, 0, -50}, {50, 0, -50}, {50, 0, 50});
    plane.material = lambertian(0.5f);
    s.objects.push_back(plane);
    FloatImage linear;
    renderScene(s, nullptr, nullptr, &linear);
    double mean = 0;
    for (std::size_t i = 0; i < linear.rgba.size(); i += 4) mean += linear.rgba[i];
    mean /= double(linear.rgba.size() / 4);
    // The bilinear blend across the horizon dims the lowest directions a little.
    if (up) EXPECT_NEAR(mean, 0.5 * 2, 0.03);
    else EXPECT_NEAR(mean, 0, 0.03);
  }
  std::filesystem::remove(path);
}

TEST(PathTracer, OneBounceFromAPointLightIsTheRasterizersLambertImage) {
  // Direct light only, no ambient, no shadow rays (which would see the faceted sphere shadow itself
  // along the terminator, as the local model cannot): L = (k_d/π)·(π·c·att)·(N·L), GL's diffuse term.
  Scene s = pathScene(256);
  s.model = LightingModel::Lambert;
  s.lightModel.ambient = Color3(0);
  Light light;
  light.position = {2, 3, 4, 1};
  light.diffuse = {0.9f, 0.8f, 0.7f};
  light.attenuation = {1, 0.05f, 0.01f};
  s.lights = {light};
  s.rayTracing.samples = 1;
  s.rayTracing.maxDepth = 1;
  s.rayTracing.shadows = false;
  Object ball;
  ball.mesh = std::make_shared<const Mesh>(makeSphere(1.2f, 48, 24));
  ball.material = lambertian(0.7f);
  ball.material.diffuse = {0.8f, 0.5f, 0.3f, 1};
  s.objects.push_back(ball);
  const Image traced = renderScene(s);
  s.renderer = RendererKind::Raster;
  s.shading = Shading::Phong;
  const Image raster = renderScene(s);
  // Inside the silhouette (at its very edge the viewer can see past the interpolated normal,
  // where the path tracer lights the facet instead).
  int inside = 0, within = 0;
  for (int y = 1; y + 1 < s.height; ++y)
    for (int x = 1; x + 1 < s.width; ++x) {
      bool covered = true;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) covered = covered && raster.pixel(x + dx, y + dy)[3] == 255 && raster.pixel(x + dx, y + dy)[0] != 0;
      if (!covered) continue;
      ++inside;
      bool close = true;
      for (int c = 0; c < 3; ++c) close = close && std::abs(traced.pixel(x, y)[c] - raster.pixel(x, y)[c]) <= 1;
      within += close;
    }
  ASSERT_GT(inside, 10000);
  EXPECT_GE(double(within) / inside, 0.999) << within << " of " << inside;
  // And the background is the background in both.
  EXPECT_EQ(traced.pixel(0, 0)[3], raster.pixel(0, 0)[3]);
}

TEST(PathTracer, ManyLightsAreSampledOneAtATimeWithoutBias) {
  // Beyond 16 lights one light per bounce stands for all: 40 copies of a directional light of
  // colour c/40 give the picture of the one light c, exactly (every copy gives the same).
  Scene s = pathScene(32);
  s.rayTracing.samples = 2;
  s.rayTracing.maxDepth = 1;
  Object ball;
  ball.mesh = std::make_shared<const Mesh>(makeSphere(1, 32, 16));
  ball.material = lambertian(0.8f);
  s.objects.push_back(ball);
  Light light;
  light.position = {1, 1, 1, 0};
  light.diffuse = Color3(1);
  s.lights = {light};
  FloatImage one, many;
  renderScene(s, nullptr, nullptr, &one);
  light.diffuse = Color3(1.0f / 40);
  s.lights.assign(40, light);
  renderScene(s, nullptr, nullptr, &many);
  for (std::size_t i = 0; i < one.rgba.size(); ++i) ASSERT_NEAR(many.rgba[i], one.rgba[i], 1e-5) << i;
}

// A sphere (albedo 0.5) on a floor (0.7) lit by an emissive quad above them.
Scene litRoom(int size) {
  Scene s = pathScene(size);
  s.rayTracing.maxDepth = 4;
  Object floor;
  floor.mesh = quad({-3, -1, 3}, {3, -1, 3}, {3, -1, -3}, {-3, -1, -3});
  floor.material = lambertian(0.7f);
  s.objects.push_back(floor);
  Object ball;
  ball.mesh = std::make_shared<const Mesh>(makeSphere(0.8f, 24, 12));
  ball.material = lambertian(0.5f);
  s.objects.push_back(ball);
  Object lamp;
  lamp.mesh = quad({-1, 2.5f, -1}, {1, 2.5f, -1}, {1, 2.5f, 1}, {-1, 2.5f, 1});  // facing down
  lamp.material = lambertian(0);
  lamp.material.emission = {1, 1, 1, 1};
  s.objects.push_back(lamp);
  return s;
}

TEST(PathTracer, ErrorFallsAsOneOverTheSquareRootOfSamples) {
  // The RMS error against a 4096-sample render halves when the samples quadruple.
  Scene s = litRoom(24);
  s.rayTracing.samples = 4096;
  FloatImage reference;
  renderScene(s, nullptr, nullptr, &reference);
  double previous = 0;
  for (int samples : {16, 64, 256}) {
    s.rayTracing.samples = samples;
    FloatImage estimate;
    renderScene(s, nullptr, nullptr, &estimate);
    double squared = 0;
    for (std::size_t i = 0; i < estimate.rgba.size(); i += 4) {
      const double e = estimate.rgba[i] - reference.rgba[i];
      squared += e * e;
    }
    const double rms = std::sqrt(squared / double(estimate.rgba.size() / 4));
    ASSERT_GT(rms, 0) << samples << " samples: no noise (is the room lit?)";
    if (previous > 0) {
      EXPECT_GT(previous / rms, 1.6) << samples << " samples";
      EXPECT_LT(previous / rms, 2.5) << samples << " samples";
    }
    previous = rms;
  }
}

// Each seed draws the room with noise of its own (RayTracing::seed): the same seed the same
// bytes, seed 0 the picture of no seed at all, and the mean of four seeds' 16-sample pictures as
// far from a 4096-sample render as independent noise leaves it, a quarter of one picture's
// squared error (their noise shares nothing: not the sample points, not the paths).
TEST(PathTracer, EachSeedDrawsIndependentNoiseAndTheSameSeedTheSameBytes) {
  Scene s = litRoom(24);
  s.rayTracing.samples = 4096;
  FloatImage reference;
  renderScene(s, nullptr, nullptr, &reference);
  s.rayTracing.samples = 16;
  const auto drawn = [&](std::uint32_t seed) {
    s.rayTracing.seed = seed;
    FloatImage picture;
    renderScene(s, nullptr, nullptr, &picture);
    return picture;
  };
  const FloatImage unseeded = drawn(0);
  EXPECT_EQ(drawn(5).rgba, drawn(5).rgba);
  std::vector<FloatImage> seeds;
  for (std::uint32_t seed : {1u, 2u, 3u, 4u}) seeds.push_back(drawn(seed));
  EXPECT_NE(seeds[0].rgba, unseeded.rgba);
  FloatImage mean = seeds[0];
  double single = 0;
  for (std::size_t i = 0; i < mean.rgba.size(); i += 4)
    for (std::size_t c = 0; c < 3; ++c) {
      double sum = 0;
      for (const FloatImage& p : seeds) {
        const double e = p.rgba[i + c] - reference.rgba[i + c];
        single += e * e / double(seeds.size());
        sum += p.rgba[i + c];
      }
      mean.rgba[i + c] = float(sum / double(seeds.size()));
    }
  double ofMean = 0;
  for (std::size_t i = 0; i < mean.rgba.size(); i += 4)
    for (std::size_t c = 0; c < 3; ++c) {
      const double e = mean.rgba[i + c] - reference.rgba[i + c];
      ofMean += e * e;
    }
  ASSERT_GT(single, 0);
  EXPECT_GT(ofMean / single, 0.15);
  EXPECT_LT(ofMean / single, 0.35) << "the seeds' noise is correlated";
}

// The relative MSE of a picture's linear RGB against a reference: mean (x − r)²/(r² + 0.01).
double relativeError(const FloatImage& x, const FloatImage& reference) {
  double sum = 0;
  for (std::size_t i = 0; i < x.rgba.size(); i += 4)
    for (std::size_t c = 0; c < 3; ++c) {
      const double d = double(x.rgba[i + c]) - reference.rgba[i + c], r = reference.rgba[i + c];
      sum += d * d / (r * r + 0.01);
    }
  return sum / double(x.rgba.size() / 4 * 3);
}

const FloatLayer& layerOf(const FloatImage& image, const std::string& name) {
  for (const FloatLayer& l : image.layers)
    if (l.name == name) return l;
  throw std::runtime_error("no layer " + name);
}

// The denoiser's worth on a small room (64×64, where the filter has little room to work; the
// bigger pictures of bench/denoise.sh gain more): 16 samples denoised are closer to a 1024-sample
// render than 48 samples are without it.
TEST(PathTracer, SixteenSamplesDenoisedBeatThreeTimesAsManyRaw) {
  Scene s = litRoom(64);
  s.rayTracing.samples = 1024;
  FloatImage reference, raw16, raw48, denoised16;
  renderScene(s, nullptr, nullptr, &reference);
  s.rayTracing.samples = 48;
  renderScene(s, nullptr, nullptr, &raw48);
  s.rayTracing.samples = 16;
  renderScene(s, nullptr, nullptr, &raw16);
  s.rayTracing.denoise = true;
  renderScene(s, nullptr, nullptr, &denoised16);
  const double e16 = relativeError(raw16, reference), e48 = relativeError(raw48, reference);
  const double d16 = relativeError(denoised16, reference);
  EXPECT_LT(d16, e48) << "relative MSE: 16 samples " << e16 << ", denoised " << d16 << ", 48 samples " << e48;
  // The layers keep the picture before the filter, bit for bit the undenoised render's.
  EXPECT_EQ(layerOf(denoised16, "beauty").values, raw16.rgba);
}

TEST(PathTracer, TheDenoisersGuidesAreTheFirstSurfacesAlbedoAndNormal) {
  Scene s = litRoom(32);
  s.rayTracing.samples = 8;
  s.rayTracing.denoise = true;
  FloatImage linear;
  renderScene(s, nullptr, nullptr, &linear);
  const FloatLayer &albedo = layerOf(linear, "albedo"), &normal = layerOf(linear, "normal");
  ASSERT_EQ(albedo.values.size(), std::size_t(32 * 32 * 3));
  // The bottom row sees the floor (albedo 0.7, normal +Y in eye space: the camera looks down −Z);
  // the centre the ball (0.5, facing the camera); the top row nothing (0, no normal).
  const auto at = [&](const FloatLayer& l, int x, int y, int c) { return l.values[3 * std::size_t(y * 32 + x) + std::size_t(c)]; };
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(at(albedo, 16, 31, c), 0.7f, 1e-6f);
    EXPECT_NEAR(at(albedo, 16, 16, c), 0.5f, 1e-6f);
    EXPECT_EQ(at(albedo, 16, 0, c), 0.0f);
    EXPECT_EQ(at(normal, 16, 0, c), 0.0f);
  }
  EXPECT_NEAR(at(normal, 16, 31, 1), 1.0f, 1e-5f);
  EXPECT_GT(at(normal, 16, 16, 2), 0.95f);
}

TEST(PathTracer, ASilhouettesGuidesAreThoseOfItsSamplesThatHitSomething) {
  // The radiance filtered is the mean of the samples that hit something (the background is laid
  // under it after), so the guides are too: where the floor's far edge or the ball meets the
  // empty background, a pixel's albedo is still a surface's (0.5, 0.7, or the lamp's 1, or a mix),
  // not shrunk by its misses, and where most samples missed its normal is about unit length.
  Scene s = litRoom(48);
  s.background = Color4(0);  // transparent: the beauty's alpha is the share of samples that hit
  s.rayTracing.samples = 16;
  s.rayTracing.denoise = true;
  FloatImage linear;
  renderScene(s, nullptr, nullptr, &linear);
  const FloatLayer &albedo = layerOf(linear, "albedo"), &normal = layerOf(linear, "normal"), &beauty = layerOf(linear, "beauty");
  int silhouettes = 0;
  for (std::size_t i = 0; i < albedo.values.size() / 3; ++i) {
    const float a = albedo.values[3 * i];
    if (a == 0) continue;  // nothing hit
    const float* n = &normal.values[3 * i];
    const float alpha = beauty.values[4 * i + 3];
    EXPECT_GE(a, 0.5f - 1e-6f) << "pixel " << i << ", alpha " << alpha;
    if (alpha > 0.5f) continue;
    // Mostly background: a mix of that few samples' normals stays about unit length.
    ++silhouettes;
    EXPECT_GT(std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]), 0.7f) << "pixel " << i << ", alpha " << alpha;
  }
  EXPECT_GE(silhouettes, 10);
}

TEST(PathTracer, AnEdgeInsideAPixelTakesItsCoverageFromMoreSamples) {
  // Where a pixel's 16 samples disagree (here: only some hit the ball or the floor), the denoised
  // picture lays the light over the background by a coverage taken over 4 times as many samples,
  // the next ones of the pixel's sequence: its alpha is then, byte for byte, that of 64 raw
  // samples, and not that of its own 16 (which differ at some of the silhouette's pixels). Where
  // they agree, it is theirs.
  Scene s = litRoom(48);
  s.background = Color4(0);  // transparent: alpha is the share of samples that hit
  s.rayTracing.samples = 64;
  s.rayTracing.denoise = false;
  const Image raw64 = renderScene(s);
  s.rayTracing.samples = 16;
  const Image raw16 = renderScene(s);
  s.rayTracing.denoise = true;
  const Image denoised16 = renderScene(s);
  int edges = 0, differing = 0;
  for (std::size_t i = 3; i < raw64.rgba.size(); i += 4) {
    const bool edge = raw16.rgba[i] != 0 && raw16.rgba[i] != 255;
    EXPECT_EQ(int(denoised16.rgba[i]), int((edge ? raw64 : raw16).rgba[i])) << "pixel " << i / 4;
    edges += edge;
    differing += edge && raw16.rgba[i] != raw64.rgba[i];
  }
  EXPECT_GE(edges, 20);
  EXPECT_GE(differing, 10);
}

// pathScene seen orthographically (16 pixels a unit) with the denoiser at 16 samples, filled by a
// white wall of vertical stripes 8 texels wide, white and black, at 8 texels a pixel, the stripes'
// edges on the pixels' edges. Every pixel's samples see different albedos (the bilinear ramps
// between the stripes), so every pixel takes its guides over 64 samples.
Scene stripedWallScene() {
  Scene s = pathScene(32);
  s.camera.projection = Projection::Orthographic;
  s.camera.viewHeight = 2;
  s.rayTracing.samples = 16;
  s.rayTracing.denoise = true;
  Image stripes(16, 16);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      std::uint8_t* p = stripes.pixel(x, y);
      p[0] = p[1] = p[2] = x < 8 ? 255 : 0, p[3] = 255;
    }
  Object wall = wallFacingTheCamera(1);
  Mesh mesh = *wall.mesh;
  for (const Vec3& p : mesh.positions) mesh.uvs.push_back({(p.x + 1) * 8, (p.y + 1) * 8});  // 128 texels a unit
  wall.mesh = std::make_shared<const Mesh>(std::move(mesh));
  wall.diffuseTexture = std::make_shared<const Texture>(stripes);
  s.objects.push_back(wall);
  return s;
}

TEST(PathTracer, DenoisedATexturesEdgesAreFilteredForTheGuidesSamples) {
  // Each sample reads the texture bilinearly: at the base level a pixel of a white stripe
  // averages 31/32 (the linear ramp to the next stripe's texel centres reaches half a texel into
  // it on both sides), at the next level 15/16. The guides' 64 samples filter the texture over an
  // eighth of a pixel, 1 texel, the base level; the 16 samples' own quarter pixel would have been
  // the next level and blurred the stripes' edges into the picture.
  FloatImage linear;
  renderScene(stripedWallScene(), nullptr, nullptr, &linear);
  const FloatLayer& albedo = layerOf(linear, "albedo");
  double sum[2] = {0, 0};
  int count[2] = {0, 0};
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      const int white = x % 2 == 0 ? 1 : 0;
      const float a = albedo.values[3 * std::size_t(y * 32 + x)];
      EXPECT_NEAR(a, white ? 31.0 / 32 : 1.0 / 32, 0.012) << "pixel " << x << ", " << y;
      sum[white] += a, ++count[white];
    }
  EXPECT_NEAR(sum[1] / count[1], 31.0 / 32, 0.003);
  EXPECT_NEAR(sum[0] / count[0], 1.0 / 32, 0.003);
}

// One bounce, no environment, and nothing a light bounces off onto the rest: a raw picture of
// `s` is its direct light alone. The denoised 16 samples' unfiltered direct light, where a
// pixel's guides are taken over 64 samples, is theirs, the same points as 64 raw samples: the
// same values, at every pixel `compared` picks (given the 64 raw samples; of those with a
// direct light kept: not one sample alone's), where 16 raw samples differ from them by more
// than `differs` in at least `differing` pixels.
void expectTheDirectLightOf64Samples(Scene s, const std::function<bool(std::size_t, const FloatImage&)>& compared, float differs,
                                     int atLeastCompared, int differing) {
  s.rayTracing.samples = 16;
  s.rayTracing.denoise = true;
  s.rayTracing.maxDepth = 1;
  FloatImage denoised16, raw16, raw64;
  renderScene(s, nullptr, nullptr, &denoised16);
  s.rayTracing.denoise = false;
  renderScene(s, nullptr, nullptr, &raw16);
  s.rayTracing.samples = 64;
  renderScene(s, nullptr, nullptr, &raw64);
  const FloatLayer& direct = layerOf(denoised16, "direct");
  int count = 0, differ = 0;
  for (std::size_t i = 0; i < direct.values.size() / 3; ++i) {
    if (direct.values[3 * i] == 0 || !compared(i, raw64)) continue;
    ++count;
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(direct.values[3 * i + std::size_t(c)], raw64.rgba[4 * i + std::size_t(c)], 1e-6f) << "pixel " << i;
    differ += std::abs(raw16.rgba[4 * i] - raw64.rgba[4 * i]) > differs;
  }
  EXPECT_GE(count, atLeastCompared);
  EXPECT_GE(differ, differing);
}

TEST(PathTracer, DenoisedAnEdgeInsideAPixelTakesItsDirectLightFromTheGuidesSamples) {
  // The striped wall under a directional light, a black bar in front of it casting a shadow whose
  // edges cross pixels.
  Scene s = stripedWallScene();
  Light light;
  light.position = {0, 0.6f, 1, 0};
  light.diffuse = Color3(1);
  s.lights = {light};
  Object bar;
  bar.mesh = quad({-3, 0.2f, 1}, {3, 0.2f, 1}, {3, 0.35f, 1}, {-3, 0.35f, 1});  // its shadow: y in (-0.4, -0.25)
  bar.material = lambertian(0);
  s.objects.push_back(bar);
  // Rows 10 to 12 show the bar: where a black stripe's pixel holds it, no sample saw an albedo
  // over 1/64 and its guides stay its own 16 samples'.
  expectTheDirectLightOf64Samples(s, [](std::size_t i, const FloatImage&) { return i / 32 < 10 || i / 32 > 12; }, 0.01f, 500, 10);
}

TEST(PathTracer, DenoisedAModelsEdgeInsideAPixelTakesItsDirectLightFromTheGuidesSamples) {
  // A grey cube turned 45° about the vertical, its edge towards the camera, under a directional
  // light from the right: the two faces it shows are of one albedo but lit 0.32 and 0.95. Where a
  // pixel's samples met both faces its guides are taken over 64 samples; elsewhere (one face)
  // every sample has the same light. So the direct light equals the 64 raw samples' everywhere
  // the cube covers, where 16 raw samples differ from them along the edge.
  Scene s = pathScene(32);
  s.background = Color4(0);  // transparent: alpha is the share of samples that hit
  Light light;
  light.position = {0.5f, 0, 1, 0};
  light.diffuse = Color3(1);
  s.lights = {light};
  Object cube;
  cube.mesh = std::make_shared<const Mesh>(makeCube(1.5f));
  // (Its edge a little off the picture's centre, so that it crosses a column of pixels.)
  cube.worldFromObject = glm::rotate(glm::translate(Mat4(1), Vec3(0.04f, 0, 0)), Real(glm::radians(45.0)), Vec3(0, 1, 0));
  cube.material = lambertian(0.5f);
  s.objects.push_back(cube);
  // (Where the background shows, the direct light is the hits' mean, the picture every sample's.)
  const auto covered = [](std::size_t i, const FloatImage& raw64) { return raw64.rgba[4 * i + 3] == 1.0f; };
  expectTheDirectLightOf64Samples(s, covered, 0.005f, 100, 8);
}

TEST(PathTracer, APartMirrorsReflectionIsALayerOfItsOwnGuidedByWhatItSaw) {
  // A black wall facing the camera that mirrors half of what arrives (k = 0.5), and behind the
  // camera a lamp (emission 1) facing it, off to the left: the wall's left half reflects the lamp,
  // its right half the black sky. With the denoiser, both parts of the wall are followed (no draw
  // among the samples): the reflection is k × the lamp exactly, the reflected lamp's guides are its
  // own (albedo 1: what it emits; normal towards the wall, −Z), and where the mirror saw the sky,
  // no albedo and the mirrored direction (towards +Z) for a normal. The wall's own guides are
  // (1 − k) × black + k.
  Scene s = pathScene(32);
  s.rayTracing.samples = 4;
  s.rayTracing.denoise = true;
  Object wall = wallFacingTheCamera(0);
  wall.optics.reflective = Color3(0.5f);
  s.objects.push_back(wall);
  Object lamp;
  lamp.mesh = quad({-3, 3, 6}, {0, 3, 6}, {0, -3, 6}, {-3, -3, 6});  // facing −Z, behind the camera
  lamp.material = lambertian(0);
  lamp.material.emission = {1, 1, 1, 1};
  s.objects.push_back(lamp);
  FloatImage linear;
  renderScene(s, nullptr, nullptr, &linear);
  const FloatLayer &reflection = layerOf(linear, "reflection"), &reflectedAlbedo = layerOf(linear, "reflection.albedo"),
                   &reflectedNormal = layerOf(linear, "reflection.normal"), &albedo = layerOf(linear, "albedo");
  int lampSeen = 0, skySeen = 0;
  for (std::size_t i = 0; i < albedo.values.size() / 3; ++i) {
    const float* a = &reflectedAlbedo.values[3 * i];
    const float* n = &reflectedNormal.values[3 * i];
    for (int c = 0; c < 3; ++c) ASSERT_EQ(albedo.values[3 * i + std::size_t(c)], 0.5f) << "pixel " << i;
    if (a[0] == 1.0f) {  // every sample's mirror saw the lamp
      ++lampSeen;
      EXPECT_EQ(n[0], 0.0f);
      EXPECT_EQ(n[1], 0.0f);
      EXPECT_EQ(n[2], -1.0f);
      for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(reflection.values[3 * i + std::size_t(c)], 0.5f) << "pixel " << i;
        EXPECT_NEAR(linear.rgba[4 * i + std::size_t(c)], 0.5f, 1e-6f) << "pixel " << i << " denoised";
      }
    } else if (a[0] == 0.0f) {  // every sample's mirror saw the sky
      ++skySeen;
      EXPECT_GT(n[2], 0.8f) << "pixel " << i;
      // the mean of its samples' directions, a pixel apart: about unit length
      EXPECT_NEAR(n[0] * n[0] + n[1] * n[1] + n[2] * n[2], 1.0f, 1e-3f) << "pixel " << i;
      for (int c = 0; c < 3; ++c) EXPECT_EQ(reflection.values[3 * i + std::size_t(c)], 0.0f) << "pixel " << i;
    }
  }
  EXPECT_GT(lampSeen, 100);
  EXPECT_GT(skySeen, 100);
}

TEST(PathTracer, TheFirstSurfacesLightFromPointLightsIsExactAndNotFiltered) {
  // A wall (albedo 0.5) facing the camera, lit by a directional light from the right, 45° off its
  // normal, and by a lamp behind the camera, to the left (area light: a draw per sample, noisy).
  // With the denoiser, what the wall took from the directional light is its own EXR layer, exact at
  // every pixel the wall covers: (k_d/π)·π·c·(N·L) = 0.5·cos 45°; the filtered rest (the lamp) is
  // added to it, never taken from it.
  // Forty copies of the light (c/40 each) are one drawn per bounce: a draw, filtered, no layer.
  Scene s = denoisedWallScene(4);
  Object lamp;
  lamp.mesh = quad({-3, 3, 6}, {0, 3, 6}, {0, -3, 6}, {-3, -3, 6});
  lamp.material = lambertian(0);
  lamp.material.emission = {1, 1, 1, 1};
  s.objects.push_back(lamp);
  Light light;
  light.position = {1, 0, 1, 0};
  light.diffuse = Color3(1);
  s.lights = {light};
  const float lit = 0.5f * std::sqrt(0.5f);
  FloatImage linear;
  renderScene(s, nullptr, nullptr, &linear);
  const FloatLayer& direct = layerOf(linear, "direct");
  const FloatLayer& beauty = layerOf(linear, "beauty");
  int lampVaries = 0;
  for (std::size_t i = 0; i < direct.values.size() / 3; ++i) {
    ASSERT_EQ(beauty.values[4 * i + 3], 1.0f) << "pixel " << i;  // the wall covers the picture
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(direct.values[3 * i + std::size_t(c)], lit, 1e-6f) << "pixel " << i;
      EXPECT_GT(linear.rgba[4 * i + std::size_t(c)], lit) << "pixel " << i << " denoised";
    }
    lampVaries += std::abs(beauty.values[4 * i] - beauty.values[0]) > 1e-3f;
  }
  EXPECT_GT(lampVaries, 100);  // the rest is noisy: what the filter is for
  // The wall's depth, a guide too: its distance from the eye, 4 straight ahead, 4/cos θ aside.
  const FloatLayer& depth = layerOf(linear, "depth");
  ASSERT_EQ(depth.channels, 1);
  for (std::size_t i = 0; i < depth.values.size(); ++i) {
    const int x = int(i % 32), y = int(i / 32);
    const float wall = linear.pixel(x, y)[3] > 0 ? 4.0f : 0.0f;
    EXPECT_GE(depth.values[i], wall) << "pixel " << i;
    EXPECT_LT(depth.values[i], 4.6f) << "pixel " << i;
  }
  EXPECT_NEAR(depth.values[16 * 32 + 16], 4.0f, 0.01f);
  light.diffuse = Color3(1.0f / 40);
  s.lights.assign(40, light);
  renderScene(s, nullptr, nullptr, &linear);
  for (const float v : layerOf(linear, "direct").values) ASSERT_EQ(v, 0.0f);
}

TEST(PathTracer, LightThatOneSampleOfAPixelSawIsTakenOverMoreSamplesOrFiltered) {
  // A narrow spot light's disc on the wall, smaller than a pixel, one bounce: where all of a
  // pixel's samples agree (none saw the disc) its direct light is exact and kept out of the
  // filter. Where one sample alone of 16 saw it, that is the pixel's noise, not its value (the
  // reference's is the disc's share of the pixel): the direct light is taken over 64 samples, the
  // same points as 64 raw samples, and kept if more than one of those saw the disc; if one alone
  // did, it goes to the filter, whose outlier pass brings the pixel down towards its neighbours.
  struct Seen {
    int more = 0, oneOf16 = 0, oneOf64 = 0;
  };
  const auto spotOnTheWall = [](Vec3 at, Real cutoff) {
    Scene s = denoisedWallScene(16);
    s.rayTracing.maxDepth = 1;
    Light spot;
    spot.position = Vec4(at, 1);
    spot.spotDirection = {0, 0, -1};
    spot.spotCutoff = cutoff;
    s.lights = {spot};
    FloatImage linear, raw64;
    renderScene(s, nullptr, nullptr, &linear);
    s.rayTracing.denoise = false;
    s.rayTracing.samples = 64;
    renderScene(s, nullptr, nullptr, &raw64);
    const FloatLayer &direct = layerOf(linear, "direct"), &beauty = layerOf(linear, "beauty");
    // Each sample on the disc sees 0.5 (its cosines are 1 within 1e-4).
    Seen seen;
    for (std::size_t i = 0; i < direct.values.size() / 3; ++i) {
      const float raw = beauty.values[4 * i], kept = direct.values[3 * i], denoised = linear.rgba[4 * i];
      const long of16 = std::lround(raw / (0.5f / 16)), of64 = std::lround(raw64.rgba[4 * i] / (0.5f / 64));
      if (of16 > 1) {
        ++seen.more;
        EXPECT_EQ(kept, raw) << "pixel " << i;
        EXPECT_NEAR(denoised, raw, 1e-6f) << "pixel " << i;
      } else if (of16 == 1 && of64 > 1) {
        ++seen.oneOf16;
        EXPECT_NEAR(kept, raw64.rgba[4 * i], 1e-6f) << "pixel " << i;
      } else if (of16 == 1) {
        ++seen.oneOf64;
        EXPECT_EQ(kept, 0.0f) << "pixel " << i;
        EXPECT_LT(denoised, 0.5f * raw) << "pixel " << i;
      }
    }
    return seen;
  };
  // A disc of radius 0.026 (the wall's pixels are 0.1 wide): one pixel where two or more of 16
  // samples saw it, one where one did and 5 of 64.
  const Seen wide = spotOnTheWall({0.31f, 0.27f, 3}, 0.5f);
  EXPECT_EQ(wide.more, 1);
  EXPECT_EQ(wide.oneOf16, 1);
  // Of radius 0.005: one sample of 16 saw it, and of 64 that one alone.
  const Seen narrow = spotOnTheWall({0.33f, 0.25f, 3}, 0.1f);
  EXPECT_EQ(narrow.oneOf64, 1);
}

TEST(PathTracer, TheSameBytesOnEveryThreadCount) {
  Scene s = defaultScene(LightingModel::BlinnPhong, Shading::Phong, RendererKind::Path);
  s.width = 160, s.height = 90;
  s.rayTracing.samples = 4;
  s.rayTracing.environment = Color3(0.2f);
  for (const bool denoise : {false, true}) {
    s.rayTracing.denoise = denoise;
    const Image all = renderScene(s);
    for (int threads : {1, 3}) {
      const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
      EXPECT_EQ(renderScene(s).rgba, all.rgba) << threads << " threads" << (denoise ? ", denoised" : "");
    }
  }
}

}  // namespace
}  // namespace illum

namespace illum {
namespace {

// A sun of one texel in a black sky lights a plane with little noise at 16 samples, because the
// environment map is sampled as a light: the mean is the integral of radiance × cos over the sky
// (by quadrature of the map's own lookups) × albedo/π, and the pixels agree with each other.
TEST(PathTracer, ASmallSunInTheEnvironmentMapIsSampledAsALight) {
  const int w = 64, h = 32;
  std::vector<Vec3> texels(std::size_t(w * h), Vec3(0));
  texels[std::size_t(6 * w + 40)] = Vec3(400);  // 34° from the zenith
  const auto map = std::make_shared<const EnvironmentMap>(w, h, texels);
  double irradiance = 0;  // ∫ L cos θ dω over the upper hemisphere, dω = 2π² sin θ du dv
  const int nu = 2048, nv = 1024;
  for (int j = 0; j < nv; ++j) {
    const double v = 0.5 * (j + 0.5) / nv, theta = v * M_PI;
    for (int i = 0; i < nu; ++i) {
      const double phi = ((i + 0.5) / nu - 0.5) * 2 * M_PI;
      const Vec3 d(Real(std::sin(theta) * std::sin(phi)), Real(std::cos(theta)), Real(-std::sin(theta) * std::cos(phi)));
      irradiance += double(map->radiance(d).r) * std::cos(theta) * 2 * M_PI * M_PI * std::sin(theta) * (1.0 / nu) * (0.5 / nv);
    }
  }
  const double expected = 0.5 / M_PI * irradiance;
  ASSERT_GT(expected, 0.1);
  Scene s = pathScene(8);
  s.camera.projection = Projection::Orthographic;
  s.camera.eye = {0, 5, 0};
  s.camera.up = {0, 0, -1};
  s.rayTracing.samples = 16;
  s.rayTracing.maxDepth = 1;
  s.rayTracing.environmentMap = EnvironmentMapFile::of(map);
  s.rayTracing.environment = Color3(1);
  Object plane;
  plane.mesh = quad({-50, 0, 50}, {50, 0, 50}, {50, 0, -50}, {-50, 0, -50});
  plane.material = lambertian(0.5f);
  s.objects.push_back(plane);
  FloatImage linear;
  renderScene(s, nullptr, nullptr, &linear);
  double mean = 0, squares = 0;
  const double n = double(linear.rgba.size() / 4);
  for (std::size_t i = 0; i < linear.rgba.size(); i += 4) mean += linear.rgba[i], squares += double(linear.rgba[i]) * linear.rgba[i];
  mean /= n;
  const double deviation = std::sqrt(std::max(0.0, squares / n - mean * mean));
  // Measured: 23 % between pixels; BSDF sampling alone gives 220 % and a mean 70 % off.
  EXPECT_NEAR(mean, expected, 0.05 * expected);
  EXPECT_LT(deviation, 0.35 * expected);
}

}  // namespace
}  // namespace illum
