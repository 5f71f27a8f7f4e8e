// The pipeline cache builds outside its lock: while one pipeline is being built (seconds on
// lavapipe for a heavy scene's shaders), a pipeline already built is handed out at once, and a
// second request for the one under way waits for that build instead of starting another.
// Before, the cache held its lock through every build, and any renderer made meanwhile (a
// session opening a scene it had open before) waited for another client's compile.
#include <atomic>
#include <chrono>
#include <future>
#include <thread>

#include "render/device/pipeline_cache.h"
#include "render/prepare/packed_scene.h"
#include "render/prepare/pipeline_features.h"
#include "render_fixture.h"

namespace geodesic::test {
namespace {

using namespace std::chrono_literals;

PipelineFeatures features_of(const std::string& scene_name) {
  const Scene scene = load_scene_file(source_path("scenes/" + scene_name + ".json"));
  return scene_features(scene, pack_scene(scene));
}

VkPipeline no_pipeline(const std::vector<Spirv>&, const SceneLayout&, VkPipelineCache) {
  return VK_NULL_HANDLE;
}

TEST(PipelineCache, ABuildUnderWayHoldsUpNoOtherPipeline) {
  VulkanContext ctx;
  PipelineCache& cache = ctx.pipeline_cache();
  const std::vector<std::string> entries{"entry/ray_query.comp"};
  const PipelineFeatures built = features_of("cornell-box"), held = features_of("hyperbolic-spheres");
  const auto first = cache.pipeline("test", built, entries, no_pipeline);

  // A build that waits here until released, counting how often it runs.
  std::promise<void> entered, release;
  const std::shared_future<void> released = release.get_future().share();
  std::atomic<int> builds{0};
  const PipelineCache::Builder hold = [&](const std::vector<Spirv>&, const SceneLayout&,
                                          VkPipelineCache) {
    if (builds++ == 0) entered.set_value();
    released.wait();
    return VkPipeline(VK_NULL_HANDLE);
  };
  std::future<std::shared_ptr<const CachedPipeline>> building, again, same;
  struct Release {  // whatever fails below, the held build ends before the futures wait
    std::promise<void>& release;
    bool done = false;
    ~Release() {
      if (!done) release.set_value();
    }
  } guard{release};

  const uint64_t hits = cache.stats().memory_hits;
  building = std::async(std::launch::async, [&] { return cache.pipeline("test", held, entries, hold); });
  entered.get_future().wait();
  again = std::async(std::launch::async, [&] { return cache.pipeline("test", built, entries, no_pipeline); });
  ASSERT_EQ(again.wait_for(60s), std::future_status::ready) << "waited for another pipeline's build";
  EXPECT_EQ(again.get().get(), first.get());

  same = std::async(std::launch::async, [&] { return cache.pipeline("test", held, entries, hold); });
  // Released only once the second request found the build under way (a hit, not a build).
  const auto deadline = std::chrono::steady_clock::now() + 60s;
  while (cache.stats().memory_hits < hits + 2 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(5ms);
  EXPECT_EQ(cache.stats().memory_hits, hits + 2);
  guard.done = true;
  release.set_value();
  const auto a = building.get(), b = same.get();
  EXPECT_EQ(a.get(), b.get());
  EXPECT_EQ(builds, 1);
  EXPECT_EQ(cache.stats().pipeline_builds, 2u);
}

}  // namespace
}  // namespace geodesic::test
