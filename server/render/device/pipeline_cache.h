// Compiled pipelines, keyed by the hash of what went into them (the backend, the feature
// defines, the shader sources and glslang's version), so that reopening a scene or a second
// session on the same scene compiles nothing:
//   in memory  the built VkPipeline and its layout, shared by every renderer on this device;
//   on disk    (when a directory is set: the daemon's data directory) the SPIR-V of each
//              shader, checked by a digest, and the driver's VkPipelineCache blob.
// A pipeline is compiled and built outside the cache's lock: a request for another pipeline,
// built or not, does not wait for it (a heavy job's shaders take seconds on lavapipe), and a
// second request for the same one waits for that build instead of starting its own.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <future>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "render/prepare/pipeline_features.h"
#include "render/device/scene_layout.h"
#include "render/prepare/shader_compiler.h"

namespace geodesic {

using Spirv = std::shared_ptr<const std::vector<uint32_t>>;

// A built pipeline; destroyed with its last user, so dropping it from the cache is safe.
struct CachedPipeline {
  CachedPipeline(VkDevice device, const std::vector<uint32_t>& bindings)
      : device(device), layout(device, bindings) {}
  ~CachedPipeline() { vkDestroyPipeline(device, pipeline, nullptr); }
  VkDevice device;
  SceneLayout layout;  // the layout it was built with
  VkPipeline pipeline = VK_NULL_HANDLE;
  double build_seconds = 0;  // compile (or disk read) + driver build, when it was built
  size_t spirv_bytes = 0;    // over its shader stages
  // Its code compiled ahead of its first dispatch (RenderService::warm_up).
  mutable std::atomic<bool> warmed{false};
};

struct PipelineCacheStats {
  uint64_t glsl_compiles = 0;    // shaders compiled by glslang
  uint64_t spirv_disk_hits = 0;  // shaders read back from the directory instead
  uint64_t pipeline_builds = 0;  // pipelines the driver built
  uint64_t memory_hits = 0;      // pipelines reused as built
};

class PipelineCache {
 public:
  PipelineCache(VkDevice device, const uint8_t (&pipeline_cache_uuid)[VK_UUID_SIZE]);
  ~PipelineCache();
  PipelineCache(const PipelineCache&) = delete;
  PipelineCache& operator=(const PipelineCache&) = delete;

  // Keeps SPIR-V and the driver's cache in `dir` (created if missing) from now on; loads the
  // driver's cache saved there before. Empty: memory only.
  void set_directory(const std::filesystem::path& dir);

  // Builds the pipeline from its entries' SPIR-V (in order), with the layout and the driver's
  // cache given.
  using Builder =
      std::function<VkPipeline(const std::vector<Spirv>&, const SceneLayout&, VkPipelineCache)>;
  // The pipeline of `backend` for `features` made of shaders/<entries>, built by `build` the
  // first time it is asked for.
  std::shared_ptr<const CachedPipeline> pipeline(const std::string& backend,
                                                 const PipelineFeatures& features,
                                                 const std::vector<std::string>& entries,
                                                 const Builder& build);

  PipelineCacheStats stats() const;
  // Drops the built pipelines, the SPIR-V and the driver's cache held in memory (not the
  // directory): the next request builds again, as a new process would. For benchmarks.
  void forget_pipelines();

 private:
  using Built = std::shared_ptr<CachedPipeline>;
  // The SPIR-V of shaders/<entry> under `features`: from memory, the directory `dir` or
  // glslang; called without the lock.
  Spirv spirv(const std::string& entry, const PipelineFeatures& features,
              const std::filesystem::path& dir);
  Built build_pipeline(const PipelineFeatures& features, const std::vector<std::string>& entries,
                       const Builder& build);
  void save_driver_cache();
  void reset_driver_cache();
  // Waits (holding `lock`) until no pipeline is being built: the directory and the driver's
  // cache those builds use stay as they are meanwhile.
  void wait_for_builds(std::unique_lock<std::mutex>& lock);

  VkDevice device_;
  std::string uuid_hex_;
  VkPipelineCache driver_cache_ = VK_NULL_HANDLE;
  std::filesystem::path directory_;
  mutable std::mutex mutex_;
  std::map<std::string, Spirv> spirv_;
  std::map<std::string, Built> pipelines_;
  std::map<std::string, std::shared_future<Built>> building_;  // under way, by key
  std::condition_variable built_;                                  // one of those finished
  PipelineCacheStats stats_;
};

}  // namespace geodesic
