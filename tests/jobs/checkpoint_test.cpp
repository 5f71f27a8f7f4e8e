// Checkpoints: the file round-trips the accumulation exactly, and a renderer restored from one
// goes on with new sample indices, so a resumed render is the uninterrupted render, bit for bit
// (its random streams are the ones it would have drawn, independent of those before).
#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
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
  jobs::write_checkpoint(file, 7, 42, 3.5, 1, 2, values);
  const auto checkpoint = jobs::read_checkpoint(file, 7);
  ASSERT_TRUE(checkpoint.has_value());
  EXPECT_EQ(checkpoint->samples, 42u);
  EXPECT_EQ(checkpoint->elapsed, 3.5);
  EXPECT_EQ(checkpoint->width, 1);
  EXPECT_EQ(checkpoint->height, 2);
  EXPECT_EQ(checkpoint->sums, values);
  // Only the final name exists: the temporary one was renamed over it.
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()),
                          std::filesystem::directory_iterator()), 1);

  EXPECT_FALSE(jobs::read_checkpoint(dir.path() / "missing.bin", 7).has_value());
  std::ofstream(dir.path() / "bad.bin") << "not a checkpoint";
  EXPECT_THROW(jobs::read_checkpoint(dir.path() / "bad.bin", 7), std::runtime_error);
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
    jobs::write_checkpoint(file, 7, first.samples(), 1.0, first.width(), first.height(),
                           first.accumulation());
  }  // the process that wrote it is gone
  const auto checkpoint = jobs::read_checkpoint(file, 7);
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

TEST(Checkpoint, AForeignOrLyingCheckpointIsRefusedBeforeAnyAllocation) {
  TempDir dir;
  const auto file = dir.path() / "checkpoint.bin";
  const std::vector<float> values(16, 1.0f);
  jobs::write_checkpoint(file, 7, 42, 3.5, 1, 2, values);
  EXPECT_THROW(jobs::read_checkpoint(file, 8), jobs::CheckpointError);  // another job's
  // A 40-byte file whose header claims 8000 x 8000: refused by its size, nothing allocated.
  std::string bytes;
  {
    std::ifstream in(file, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  int32_t side = 8000;
  std::memcpy(bytes.data() + 12, &side, 4);
  std::memcpy(bytes.data() + 16, &side, 4);
  const uint64_t floats = 2ull * 8000 * 8000 * 4;
  std::memcpy(bytes.data() + 32, &floats, 8);
  bytes.resize(40);
  std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
  try {
    jobs::read_checkpoint(file, 7);
    ADD_FAILURE() << "a lying header was read";
  } catch (const jobs::CheckpointError& e) {
    EXPECT_STREQ(e.what(), "checkpoint: not a checkpoint (bad header)");  // shorter than a header
  }
  bytes.resize(48);  // a whole header, no body
  std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
  try {
    jobs::read_checkpoint(file, 7);
    ADD_FAILURE() << "a lying header was read";
  } catch (const jobs::CheckpointError& e) {
    EXPECT_STREQ(e.what(), "checkpoint: its header disagrees with its size (48 bytes)");
  }
}

TEST(Checkpoint, RestoreRefusesAnotherSize) {
  Renderer renderer(device(), small_furnace());
  const std::vector<float> wrong(10, 0.0f);
  EXPECT_THROW(renderer.restore(1, wrong), std::invalid_argument);
}

}  // namespace
}  // namespace geodesic::test
