// Progressive rendering as the daemon uses it: error estimates from the two halves, new views
// and reduced resolutions, and passes cut into slices (render/service/pass_slicer.h).
#include <cmath>
#include <vector>

#include "render/service/pass_slicer.h"
#include "render/prepare/relative_error.h"
#include "render_fixture.h"

namespace geodesic::test {
namespace {

Scene small_cornell() {
  Scene scene = paper_model(load_scene_file(source_path("scenes/cornell-box.json")));
  scene.render.width = scene.render.height = 48;
  return scene;
}

TEST(Progressive, EstimatedErrorTracksTheTrueErrorAndFallsAsOneOverRootN) {
  const Scene scene = small_cornell();
  const Image reference = render(scene, 2048);
  Renderer renderer(device(), scene);
  EXPECT_LT(renderer.estimated_error(), 0);  // nothing to compare yet
  renderer.add_samples(8);
  const double e8 = renderer.estimated_error();
  renderer.add_samples(24);
  const double e32 = renderer.estimated_error();
  const double true32 = relative_rmse(renderer.image(), reference);
  EXPECT_NEAR(e32 / e8, 0.5, 0.12);             // 1/sqrt(4)
  EXPECT_NEAR(e32 / true32, 1.0, 0.35);         // an estimate, not a bound
}

TEST(Progressive, ANewViewStartsOverAtTheResolutionAsked) {
  const Scene scene = small_cornell();
  Renderer renderer(device(), scene);
  renderer.add_samples(4);
  const Image before = renderer.image();
  Mat4 pose = scene.camera.pose;
  pose.m[0][3] += 0.3;  // step right
  renderer.set_view(pose, 24, 16);
  EXPECT_EQ(renderer.samples(), 0u);
  renderer.add_samples(2);
  const Image after = renderer.image();
  EXPECT_EQ(after.width, 24);
  EXPECT_EQ(after.height, 16);
  EXPECT_GT(mean(after).r, 0.05);  // a real image, not an empty buffer
  renderer.set_view(scene.camera.pose, 48, 48);
  renderer.add_samples(4);
  EXPECT_LT(rms_difference(renderer.image(), before), 0.2);  // same view, same picture
  EXPECT_THROW(renderer.set_view(pose, 64, 64), std::invalid_argument);
}

// A pass cut into slices adds the same samples to every pixel as one dispatch of the whole
// image: each pixel's random stream depends on its index and sample number only.
std::vector<float> sliced_pass(const Scene& scene, double slice_seconds, int& slices) {
  Renderer renderer(device(), scene);
  PassSlicer slicer(slice_seconds);
  slices = 0;
  for (bool done = false; !done; ++slices) done = slicer.render_slice(renderer);
  EXPECT_EQ(renderer.samples(), 1u);
  EXPECT_FALSE(slicer.in_pass());
  const auto sums = renderer.accumulation();
  return {sums.begin(), sums.end()};
}

TEST(Progressive, APassCutIntoSlicesOfPartRowsOrBandsAddsTheSameSamples) {
  Scene scene = small_cornell();
  scene.render.width = 20;  // not a multiple of the shader's 8 x 8 groups
  scene.render.height = 12;
  Renderer whole(device(), scene);
  whole.add_samples(1);
  const auto expected = whole.accumulation();

  int slices = 0;
  // A slice too short for any pixel: the first, before the cost is known, has kFirstPixels
  // (whole rows: 3 x 20); then one pixel per slice, parts of rows.
  const auto by_pixel = sliced_pass(scene, 1e-12, slices);
  EXPECT_EQ(slices, 1 + 20 * 12 - 60);
  EXPECT_TRUE(std::equal(expected.begin(), expected.end(), by_pixel.begin()));
  // A long slice: the first has kFirstPixels, the second the rest (at most kMaxGrowth times).
  const auto at_once = sliced_pass(scene, 10, slices);
  EXPECT_EQ(slices, 2);
  EXPECT_TRUE(std::equal(expected.begin(), expected.end(), at_once.begin()));
}

// The ray-query kernel deals its workgroups' tiles round the dispatch (dealtTile in
// shaders/entry/ray_query.comp): every pixel still gets each sample exactly once, whether the
// dispatch has fewer groups than the deal's 16 blocks, a multiple of them, or a remainder, and
// slices of a pass (other dispatch shapes) add the same samples as the whole image at once.
TEST(Progressive, EveryPixelGetsEachSampleOnceWhateverTheDispatchsShape) {
  Scene scene = small_cornell();
  for (const auto [width, height] : {std::pair{100, 36}, {8, 8}, {136, 9}, {1, 129}, {128, 64}}) {
    scene.render.width = width;
    scene.render.height = height;
    Renderer whole(device(), scene);
    whole.add_samples(3);  // samples 0 and 2 in the even half, 1 in the odd
    const auto sums = whole.accumulation();
    const size_t pixels = size_t(width) * height;
    size_t wrong = 0;
    for (size_t p = 0; p < pixels; ++p)
      wrong += sums[4 * p + 3] != 2.0f || sums[4 * (pixels + p) + 3] != 1.0f;
    EXPECT_EQ(wrong, 0u) << width << " x " << height;
  }
  scene.render.width = 100;  // 13 x 5 groups: 4 per block and one left over
  scene.render.height = 36;
  Renderer once(device(), scene);
  once.add_samples(1);
  const auto expected = once.accumulation();
  for (const double slice_seconds : {1e-12, 1e-3}) {
    int slices = 0;
    const auto sliced = sliced_pass(scene, slice_seconds, slices);
    EXPECT_GT(slices, 2);
    EXPECT_TRUE(std::equal(expected.begin(), expected.end(), sliced.begin()));
  }
}

TEST(Progressive, SlicesGrowFromTheMeasuredCostAndThePassDoublesItsBatchWhenItFits) {
  Scene scene = small_cornell();
  scene.render.width = scene.render.height = 64;
  Renderer renderer(device(), scene);
  PassSlicer slicer(10);
  int slices = 1;
  while (!slicer.render_slice(renderer)) ++slices;
  // kFirstPixels, then each slice kMaxGrowth times the last: 64 + 256 + 1024 + 2752.
  EXPECT_EQ(slices, 4);
  EXPECT_EQ(slicer.batch(), 1u);  // a pass of several slices keeps its batch
  EXPECT_TRUE(slicer.render_slice(renderer));  // now the whole image fits a slice
  EXPECT_EQ(slicer.batch(), 2u);
  EXPECT_TRUE(slicer.render_slice(renderer));
  EXPECT_EQ(renderer.samples(), 1u + 1u + 2u);
  slicer.limit_batch(3);
  EXPECT_EQ(slicer.batch(), 3u);
  EXPECT_GT(slicer.seconds_per_pixel_sample(), 0);
}

// `geodesic render`'s slicer: batches double up to its largest (64 there), never past it, also
// from a batch its stop condition cut to an odd size.
TEST(Progressive, TheSlicersLargestBatchCapsTheDoubling) {
  Scene scene = small_cornell();
  scene.render.width = scene.render.height = 16;
  Renderer renderer(device(), scene);
  PassSlicer slicer(10, 4);
  for (int pass = 0; pass < 8; ++pass)
    while (!slicer.render_slice(renderer)) {}
  // The first pass takes two slices (kFirstPixels, then the rest), then 2, 4, 4, ...
  EXPECT_EQ(slicer.batch(), 4u);
  EXPECT_EQ(renderer.samples(), 1u + 1u + 2u + 5 * 4u);
  slicer.limit_batch(3);
  EXPECT_TRUE(slicer.render_slice(renderer));
  EXPECT_EQ(renderer.samples(), 27u);
  EXPECT_EQ(slicer.batch(), 4u);  // 6 capped
}

}  // namespace
}  // namespace geodesic::test
