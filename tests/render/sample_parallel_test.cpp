// Sample-parallel rendering: parts over disjoint ranges of sample indices, each starting from
// empty sums (as `geodesic render --samples-from K` does), merge into the render of all the
// samples, with the same error estimate.
#include <cstring>
#include <filesystem>
#include <vector>

#include "render/prepare/accumulation_file.h"
#include "render_fixture.h"

namespace geodesic::test {
namespace {

Scene small_cornell_box() {
  Scene scene = small_scene("scenes/cornell-box.json", 24, 16);
  scene.render.max_depth = 3;
  return scene;
}

// Samples [first, first + count) in batches of `batch`, from empty sums.
Accumulation render_part(const Scene& scene, uint32_t first, uint32_t count, uint32_t batch) {
  Renderer renderer(device(), scene);
  if (first > 0) renderer.restore(first, std::vector<float>(renderer.accumulation().size(), 0.0f));
  for (uint32_t done = 0; done < count; done += batch) renderer.add_samples(std::min(batch, count - done));
  const auto sums = renderer.accumulation();
  return {renderer.width(), renderer.height(), first, count, "cornell-box",
          std::vector<float>(sums.begin(), sums.end())};
}

TEST(SampleParallel, TwoHalvesMergeBitwiseIntoOneRenderWithTheSameBatches) {
  const Scene scene = small_cornell_box();
  // One render whose submissions are the parts' (4 samples, then 4 more): each float of its
  // accumulation is one addition a + b, which the merge (in double, rounded once) reproduces.
  const Accumulation full = render_part(scene, 0, 8, 4);
  const std::vector<Accumulation> parts = {render_part(scene, 4, 4, 4), render_part(scene, 0, 4, 4)};
  const Accumulation merged = merge_accumulations(parts);
  EXPECT_EQ(merged.sample_start, 0u);
  EXPECT_EQ(merged.samples, 8u);
  ASSERT_EQ(merged.sums.size(), full.sums.size());
  EXPECT_EQ(std::memcmp(merged.sums.data(), full.sums.data(), full.sums.size() * sizeof(float)), 0);
  EXPECT_EQ(merged.estimated_error(), full.estimated_error());
  EXPECT_GT(full.estimated_error(), 0.0);
  // The halves really are different samples: the parts' own images differ.
  EXPECT_GT(rms_difference(parts[0].image(), parts[1].image()), 1e-3);
}

TEST(SampleParallel, MergeMatchesOneSubmissionWithinFloatRoundOff) {
  const Scene scene = small_cornell_box();
  const Accumulation full = render_part(scene, 0, 8, 8);
  const std::vector<Accumulation> parts = {render_part(scene, 0, 4, 4), render_part(scene, 4, 4, 2)};
  const Accumulation merged = merge_accumulations(parts);
  ASSERT_EQ(merged.sums.size(), full.sums.size());
  for (size_t i = 0; i < full.sums.size(); ++i)
    ASSERT_NEAR(merged.sums[i], full.sums[i], 1e-5 * (1 + std::abs(full.sums[i]))) << i;
  EXPECT_NEAR(merged.estimated_error(), full.estimated_error(), 1e-4 * full.estimated_error());
}

TEST(SampleParallel, AccumulationFileRoundTripsExactlyAndMergeRefusesOverlaps) {
  const Scene scene = small_cornell_box();
  const Accumulation part = render_part(scene, 6, 3, 3);
  const auto path = std::filesystem::temp_directory_path() / "geodesic-sample-parallel.exr";
  write_accumulation(path, part);
  const Accumulation read = read_accumulation(path);
  std::filesystem::remove(path);
  EXPECT_EQ(read.sample_start, 6u);
  EXPECT_EQ(read.samples, 3u);
  EXPECT_EQ(read.view, "cornell-box");
  ASSERT_EQ(read.sums.size(), part.sums.size());
  EXPECT_EQ(std::memcmp(read.sums.data(), part.sums.data(), part.sums.size() * sizeof(float)), 0);
  // Samples 6..8 and 8..10 are disjoint; 6..8 twice is not.
  const std::vector<Accumulation> overlapping = {part, part};
  EXPECT_THROW(merge_accumulations(overlapping), std::invalid_argument);
  Accumulation other = part;
  other.view = "torus";
  other.sample_start = 9;
  const std::vector<Accumulation> mismatched = {part, other};
  EXPECT_THROW(merge_accumulations(mismatched), std::invalid_argument);
}

}  // namespace
}  // namespace geodesic::test
