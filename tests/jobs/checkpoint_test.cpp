// Checkpoints: the file round-trips the accumulation exactly, and a renderer restored from one
// goes on with new sample indices, so a resumed render is the uninterrupted render, bit for bit
// (its random streams are the ones it would have drawn, independent of those before).
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <vector>

#include <gtest/gtest.h>

#include "../render/render_fixture.h"
#include "job_daemon.h"
#include "jobs/checkpoint.h"

namespace geodesic::test {
namespace {

Scene small_furnace() {
  Scene scene = load_scene_file(source_path("scenes/furnace.json"));
  scene.render.width = 24;
  scene.render.height = 16;
  return scene;
}

std::vector<float> sums(const Renderer& renderer) {
  const auto span = renderer.accumulation();
  return {span.begin(), span.end()};
}

TEST(Checkpoint, FileRoundTripsTheAccumulation) {
  TempDir dir;
  const std::vector<float> values = {1.5f, -2.0f, 3.25f, 0.0f, 1e-7f, 4e6f, 7.0f, 8.0f,
                                     9.0f, 10.0f, 11.0f, 12.0f, 13.0f, 14.0f, 15.0f, 16.0f};
  const auto file = dir.path() / "checkpoint.bin";
  jobs::write_checkpoint(file, 42, 3.5, 1, 2, values);
  const auto checkpoint = jobs::read_checkpoint(file);
  ASSERT_TRUE(checkpoint.has_value());
  EXPECT_EQ(checkpoint->samples, 42u);
  EXPECT_EQ(checkpoint->elapsed, 3.5);
  EXPECT_EQ(checkpoint->width, 1);
  EXPECT_EQ(checkpoint->height, 2);
  EXPECT_EQ(checkpoint->sums, values);
  // Only the final name exists: the temporary one was renamed over it.
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()),
                          std::filesystem::directory_iterator()), 1);

  EXPECT_FALSE(jobs::read_checkpoint(dir.path() / "missing.bin").has_value());
  std::ofstream(dir.path() / "bad.bin") << "not a checkpoint";
  EXPECT_THROW(jobs::read_checkpoint(dir.path() / "bad.bin"), std::runtime_error);
}

TEST(Checkpoint, ResumedRenderEqualsTheUninterruptedOne) {
  const Scene scene = small_furnace();
  Renderer straight(device(), scene);
  straight.add_samples(4);
  straight.add_samples(4);

  TempDir dir;
  const auto file = dir.path() / "checkpoint.bin";
  {
    Renderer first(device(), scene);
    first.add_samples(4);
    jobs::write_checkpoint(file, first.samples(), 1.0, first.width(), first.height(),
                           first.accumulation());
  }  // the process that wrote it is gone
  const auto checkpoint = jobs::read_checkpoint(file);
  ASSERT_TRUE(checkpoint.has_value());
  Renderer resumed(device(), scene);
  resumed.restore(checkpoint->samples, checkpoint->sums);
  EXPECT_EQ(resumed.samples(), 4u);
  resumed.add_samples(4);
  EXPECT_EQ(resumed.samples(), 8u);
  EXPECT_EQ(sums(resumed), sums(straight));

  // Control: restarting the sample indices instead draws the first 4 samples' streams again,
  // which the comparison above would catch.
  Renderer repeated(device(), scene);
  repeated.restore(0, checkpoint->sums);
  repeated.add_samples(4);
  EXPECT_NE(sums(repeated), sums(straight));
}

TEST(Checkpoint, RestoreRefusesAnotherSize) {
  Renderer renderer(device(), small_furnace());
  const std::vector<float> wrong(10, 0.0f);
  EXPECT_THROW(renderer.restore(1, wrong), std::invalid_argument);
}

}  // namespace
}  // namespace geodesic::test
