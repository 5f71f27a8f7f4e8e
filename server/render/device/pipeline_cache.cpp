#include "render/device/pipeline_cache.h"

#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>

#include "render/device/vk_check.h"

namespace geodesic {
namespace {

constexpr char kSpirvMagic[8] = {'G', 'E', 'O', 'S', 'P', 'V', '0', '1'};

std::string joined(const std::vector<std::string>& parts, const char* separator) {
  std::string s;
  for (const auto& p : parts) s += (s.empty() ? "" : separator) + p;
  return s;
}

std::vector<char> read_file(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) return {};
  return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

// Written next to its final name and renamed over it: a reader sees the old file or the new
// one, never half of one.
void write_file_atomically(const std::filesystem::path& path, const void* data, size_t size) {
  const auto temporary = path.string() + ".tmp";
  {
    std::ofstream file(temporary, std::ios::binary | std::ios::trunc);
    file.write(static_cast<const char*>(data), std::streamsize(size));
    if (!file.flush()) {
      std::error_code ignored;
      std::filesystem::remove(temporary, ignored);
      return;  // a cache that cannot be written only costs a compile next time
    }
  }
  std::error_code ignored;
  std::filesystem::rename(temporary, path, ignored);
}

}  // namespace

PipelineCache::PipelineCache(VkDevice device, const uint8_t (&uuid)[VK_UUID_SIZE])
    : device_(device), uuid_hex_(fnv1a_hex(uuid, VK_UUID_SIZE)) {
  reset_driver_cache();
}

PipelineCache::~PipelineCache() {
  pipelines_.clear();
  vkDestroyPipelineCache(device_, driver_cache_, nullptr);
}

void PipelineCache::set_directory(const std::filesystem::path& dir) {
  std::unique_lock lock(mutex_);
  wait_for_builds(lock);
  directory_ = dir;
  if (!dir.empty()) std::filesystem::create_directories(dir);
  reset_driver_cache();
}

void PipelineCache::wait_for_builds(std::unique_lock<std::mutex>& lock) {
  built_.wait(lock, [&] { return building_.empty(); });
}

// A fresh driver cache, seeded from the directory's blob when there is one. The driver checks
// the blob's header (vendor, device, cache UUID) and ignores a stale one.
void PipelineCache::reset_driver_cache() {
  const auto blob = directory_.empty() ? std::vector<char>()
                                       : read_file(directory_ / ("vulkan-" + uuid_hex_ + ".bin"));
  VkPipelineCacheCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO};
  info.initialDataSize = blob.size();
  info.pInitialData = blob.empty() ? nullptr : blob.data();
  VkPipelineCache fresh = VK_NULL_HANDLE;
  if (vkCreatePipelineCache(device_, &info, nullptr, &fresh) != VK_SUCCESS) {
    info.initialDataSize = 0;  // a blob the driver rejects: start empty
    info.pInitialData = nullptr;
    vk_check(vkCreatePipelineCache(device_, &info, nullptr, &fresh), "vkCreatePipelineCache");
  }
  vkDestroyPipelineCache(device_, driver_cache_, nullptr);
  driver_cache_ = fresh;
}

Spirv PipelineCache::spirv(const std::string& entry, const PipelineFeatures& features,
                           const std::filesystem::path& dir) {
  const std::string name = entry + "\n" + joined(features.defines(), "\n") + "\n" +
                           shader_sources_digest();
  const std::string key = fnv1a_hex(name.data(), name.size());
  {
    std::lock_guard lock(mutex_);
    if (auto it = spirv_.find(key); it != spirv_.end()) return it->second;
  }
  const auto path = dir.empty() ? std::filesystem::path() : dir / (key + ".spv");
  std::vector<uint32_t> words;
  if (!path.empty()) {
    // Magic, the payload's digest, then the SPIR-V; anything else is recompiled.
    const auto bytes = read_file(path);
    const size_t header = sizeof kSpirvMagic + 16;
    if (bytes.size() > header && (bytes.size() - header) % 4 == 0 &&
        std::memcmp(bytes.data(), kSpirvMagic, sizeof kSpirvMagic) == 0 &&
        std::string(bytes.data() + sizeof kSpirvMagic, 16) ==
            fnv1a_hex(bytes.data() + header, bytes.size() - header)) {
      words.resize((bytes.size() - header) / 4);
      std::memcpy(words.data(), bytes.data() + header, bytes.size() - header);
    }
  }
  const bool from_disk = !words.empty();
  if (!from_disk) {
    words = compile_shader(entry, features.defines()).spirv;
    if (!path.empty()) {
      std::string file(kSpirvMagic, sizeof kSpirvMagic);
      file += fnv1a_hex(words.data(), words.size() * 4);
      file.append(reinterpret_cast<const char*>(words.data()), words.size() * 4);
      write_file_atomically(path, file.data(), file.size());
    }
  }
  auto shared = std::make_shared<const std::vector<uint32_t>>(std::move(words));
  std::lock_guard lock(mutex_);
  ++(from_disk ? stats_.spirv_disk_hits : stats_.glsl_compiles);
  spirv_[key] = shared;
  return shared;
}

std::shared_ptr<const CachedPipeline> PipelineCache::pipeline(
    const std::string& backend, const PipelineFeatures& features,
    const std::vector<std::string>& entries, const Builder& build) {
  const std::string key = backend + "|" + joined(features.defines(), " ");
  std::promise<Built> promise;
  std::unique_lock lock(mutex_);
  if (auto it = pipelines_.find(key); it != pipelines_.end()) {
    ++stats_.memory_hits;
    return it->second;
  }
  if (auto it = building_.find(key); it != building_.end()) {
    ++stats_.memory_hits;
    const std::shared_future<Built> under_way = it->second;
    lock.unlock();
    return under_way.get();  // or that build's exception
  }
  building_[key] = promise.get_future().share();
  lock.unlock();
  Built built;
  try {
    built = build_pipeline(features, entries, build);
  } catch (...) {
    lock.lock();
    building_.erase(key);
    promise.set_exception(std::current_exception());
    built_.notify_all();
    throw;
  }
  lock.lock();
  ++stats_.pipeline_builds;
  pipelines_[key] = built;
  building_.erase(key);
  save_driver_cache();
  promise.set_value(built);
  built_.notify_all();
  return built;
}

// Outside the lock: the directory and the driver's cache stay while a build is under way
// (set_directory and forget_pipelines wait for builds), and vkCreate*Pipelines synchronises
// its use of a pipeline cache itself.
PipelineCache::Built PipelineCache::build_pipeline(const PipelineFeatures& features,
                                                   const std::vector<std::string>& entries,
                                                   const Builder& build) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<Spirv> modules;
  auto built = std::make_shared<CachedPipeline>(device_, features.bindings());
  for (const auto& entry : entries) {
    modules.push_back(spirv(entry, features, directory_));
    built->spirv_bytes += modules.back()->size() * 4;
  }
  built->pipeline = build(modules, built->layout, driver_cache_);
  built->build_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return built;
}

void PipelineCache::save_driver_cache() {
  if (directory_.empty()) return;
  size_t size = 0;
  if (vkGetPipelineCacheData(device_, driver_cache_, &size, nullptr) != VK_SUCCESS || size == 0)
    return;
  std::vector<char> blob(size);
  if (vkGetPipelineCacheData(device_, driver_cache_, &size, blob.data()) != VK_SUCCESS) return;
  write_file_atomically(directory_ / ("vulkan-" + uuid_hex_ + ".bin"), blob.data(), size);
}

PipelineCacheStats PipelineCache::stats() const {
  std::lock_guard lock(mutex_);
  return stats_;
}

void PipelineCache::forget_pipelines() {
  std::unique_lock lock(mutex_);
  wait_for_builds(lock);
  pipelines_.clear();
  spirv_.clear();
  reset_driver_cache();
}

}  // namespace geodesic
