#include "render/device/scene_resources.h"

#include "render/prepare/scene_bindings.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>
#include <numbers>

namespace geodesic {
namespace {

constexpr VkBufferUsageFlags kStorage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;

// Light samples per vertex as the shaders read them: 1 .. MAX_LIGHT_SAMPLES.
uint32_t device_light_samples(int light_samples) {
  static_assert(kMaxLightSamples == MAX_LIGHT_SAMPLES);
  return static_cast<uint32_t>(std::clamp(light_samples, 1, kMaxLightSamples));
}

FrameUniforms make_uniforms(const Scene& scene, const PackedScene& packed) {
  FrameUniforms u{};
  u.camera_pose = packed.camera_pose.to_glsl();
  u.camera_cell = packed.camera_cell;
  u.max_crossings = static_cast<uint32_t>(scene.manifold.faces.empty() && packed.cells.size() == 1
                                              ? 0
                                              : scene.manifold.max_crossings);
  const Vec3& a = scene.render.ambient_light;
  u.ambient_light = {float(a.x), float(a.y), float(a.z), 0.0f};
  u.tan_half_fov_y =
      static_cast<float>(std::tan(scene.camera.fov_y_degrees * std::numbers::pi / 360.0));
  u.width = static_cast<uint32_t>(scene.render.width);
  u.height = static_cast<uint32_t>(scene.render.height);
  u.aspect = float(u.width) / float(u.height);
  u.max_depth = static_cast<uint32_t>(scene.render.max_depth);
  u.light_count = static_cast<uint32_t>(scene.lights.size());
  u.seed = static_cast<uint32_t>(scene.render.seed ^ (scene.render.seed >> 32));
  u.russian_roulette = scene.render.russian_roulette ? 1u : 0u;
  u.lighting = scene.render.lighting == LightingModel::Physical ? 1u : 0u;
  u.light_sampling = static_cast<uint32_t>(scene.render.light_sampling);
  u.emitter_count = static_cast<uint32_t>(packed.emitters.size());
  u.light_cutoff = static_cast<float>(packed.light_cutoff);
  u.clamp_luminance = static_cast<float>(scene.render.clamp);
  u.light_samples = device_light_samples(scene.render.light_samples);
  return u;
}

}  // namespace

SceneResources::SceneResources(VulkanContext& ctx, const Scene& scene, PipelineVariant variant)
    : ctx_(ctx),
      geometry_(scene.geometry),
      packed_(pack_scene(scene)),
      features_(variant == PipelineVariant::AllFeatures ? all_features(scene.geometry)
                                                        : scene_features(scene, packed_)),
      uniforms_(make_uniforms(scene, packed_)) {
  features_.primitive_culling = ctx.description().primitive_culling;
  features_.shared_cell_masks = packed_.cells.size() > 8;
  structures_ = SceneAccelerationStructures::build(ctx, packed_, features_.traced_spheres(),
                                                   features_.traced_shapes());
  capacity_ = size_t(width()) * height();
  frame_ = GpuBuffer(ctx, sizeof(FrameUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
  std::memcpy(frame_.mapped(), &uniforms_, sizeof(uniforms_));
  accumulation_ = GpuBuffer(ctx, 2 * VkDeviceSize(width()) * height() * 4 * sizeof(float),
                            kStorage | VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  ray_counts_ = GpuBuffer(ctx, VkDeviceSize(width()) * height() * sizeof(uint32_t), kStorage);
  clear_accumulation();
  // Only the buffers the pipeline reads: a binding it does not declare needs no buffer.
  auto upload = [&](uint32_t binding, GpuBuffer& buffer, const auto& data) {
    if (features_.uses_binding(binding)) buffer = GpuBuffer::from_vector(ctx, data, kStorage);
  };
  upload(kSpheresBinding, spheres_, packed_.spheres);
  upload(kMaterialsBinding, materials_, packed_.materials);
  upload(kLightsBinding, lights_, packed_.lights);
  upload(kPositionsBinding, positions_, packed_.positions);
  upload(kNormalsBinding, normals_, packed_.normals);
  upload(kIndicesBinding, indices_, packed_.indices);
  upload(kTrianglesBinding, triangles_, packed_.triangles);
  upload(kSphereRefsBinding, sphere_refs_, packed_.sphere_refs);
  upload(kCellsBinding, cells_, packed_.cells);
  upload(kCellFacesBinding, faces_, packed_.faces);
  upload(kEmittersBinding, emitters_, packed_.emitters);
  upload(kLightImagesBinding, light_images_, packed_.light_images);
  upload(kTubesBinding, tubes_, packed_.tubes);
  upload(kShapesBinding, shapes_, packed_.shapes);
  upload(kShapeRefsBinding, shape_refs_, packed_.shape_refs);
  upload(kListedBinding, listed_, packed_.listed);
  diagnostics_ = GpuBuffer(ctx, sizeof(DeviceDiagnostics), kStorage);
  std::memset(diagnostics_.mapped(), 0, sizeof(DeviceDiagnostics));
  create_descriptors();
}

SceneResources::~SceneResources() {
  VkDevice device = ctx_.device();
  vkDeviceWaitIdle(device);
  vkDestroyDescriptorPool(device, pool_, nullptr);
}

void SceneResources::set_view(const Mat4& camera_pose, uint32_t camera_cell, uint32_t width,
                              uint32_t height) {
  if (width == 0 || height == 0 || size_t(width) * height > capacity_)
    throw std::invalid_argument("resolution " + std::to_string(width) + "x" +
                                std::to_string(height) + " exceeds the allocated buffers");
  uniforms_.camera_pose = camera_pose.to_glsl();
  uniforms_.camera_cell = camera_cell;
  uniforms_.width = width;
  uniforms_.height = height;
  uniforms_.aspect = float(width) / float(height);
  std::memcpy(frame_.mapped(), &uniforms_, sizeof(uniforms_));
  clear_accumulation();
}

void SceneResources::set_sampling(uint32_t max_depth, int light_samples) {
  uniforms_.max_depth = max_depth;
  uniforms_.light_samples = device_light_samples(light_samples);
  std::memcpy(frame_.mapped(), &uniforms_, sizeof(uniforms_));
  clear_accumulation();
}

void SceneResources::clear_accumulation() {
  std::memset(accumulation_.mapped(), 0, accumulation_.size());
  std::memset(ray_counts_.mapped(), 0, ray_counts_.size());
  // (the constructor clears before the diagnostics buffer exists; it starts zeroed)
  if (auto* diagnostics = static_cast<DeviceDiagnostics*>(diagnostics_.mapped()))
    diagnostics->crossed_faces = diagnostics->truncated_rays = 0;
}

void SceneResources::load_accumulation(const float* sums) {
  std::memcpy(accumulation_.mapped(), sums, 2 * size_t(width()) * height() * 4 * sizeof(float));
}

uint32_t SceneResources::non_finite_samples() const {
  return static_cast<const DeviceDiagnostics*>(diagnostics_.mapped())->non_finite_samples;
}

TraceCounters SceneResources::trace_counters() const {
  const auto* diagnostics = static_cast<const DeviceDiagnostics*>(diagnostics_.mapped());
  return {traced_rays(), diagnostics->crossed_faces, diagnostics->truncated_rays};
}

uint64_t SceneResources::traced_rays() const {
  const auto* counts = static_cast<const uint32_t*>(ray_counts_.mapped());
  uint64_t total = 0;
  for (size_t i = 0; i < size_t(width()) * height(); ++i) total += counts[i];
  return total;
}

void SceneResources::create_descriptors() {
  VkDevice device = ctx_.device();
  const std::vector<uint32_t> bindings = features_.bindings();
  layout_ = std::make_unique<SceneLayout>(device, bindings);

  const uint32_t count = static_cast<uint32_t>(bindings.size());
  VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR, 1},
                                  {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1},
                                  {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, count - 2}};
  VkDescriptorPoolCreateInfo pool{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  pool.maxSets = 1;
  pool.poolSizeCount = 3;
  pool.pPoolSizes = sizes;
  vk_check(vkCreateDescriptorPool(device, &pool, nullptr, &pool_), "vkCreateDescriptorPool");
  VkDescriptorSetLayout set_layout = layout_->set();
  VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  alloc.descriptorPool = pool_;
  alloc.descriptorSetCount = 1;
  alloc.pSetLayouts = &set_layout;
  vk_check(vkAllocateDescriptorSets(device, &alloc, &set_), "vkAllocateDescriptorSets");

  VkAccelerationStructureKHR tlas = structures_.top.handle();
  VkWriteDescriptorSetAccelerationStructureKHR as_write{
      VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET_ACCELERATION_STRUCTURE_KHR};
  as_write.accelerationStructureCount = 1;
  as_write.pAccelerationStructures = &tlas;
  const GpuBuffer* buffers[kSceneBindingCount] = {
      nullptr,     &accumulation_, &frame_,     &spheres_,     &materials_,   &lights_,
      &positions_, &normals_,      &indices_,   &triangles_,   &ray_counts_,  &sphere_refs_,
      &cells_,     &faces_,        &diagnostics_, &emitters_,  &light_images_, &tubes_,
      &shapes_,    &shape_refs_,   &listed_};
  std::vector<VkDescriptorBufferInfo> infos(count);
  std::vector<VkWriteDescriptorSet> writes(count);
  for (uint32_t i = 0; i < count; ++i) {
    const uint32_t b = bindings[i];
    writes[i] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    writes[i].dstSet = set_;
    writes[i].dstBinding = b;
    writes[i].descriptorCount = 1;
    writes[i].descriptorType = SceneLayout::descriptor_type(b);
    if (b == kSceneBinding) {
      writes[i].pNext = &as_write;
    } else {
      infos[i] = {buffers[b]->handle(), 0, VK_WHOLE_SIZE};
      writes[i].pBufferInfo = &infos[i];
    }
  }
  vkUpdateDescriptorSets(device, count, writes.data(), 0, nullptr);
}

}  // namespace geodesic
