#include "render/scene_resources.h"

#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>
#include <numbers>

namespace geodesic {
namespace {

constexpr VkBufferUsageFlags kStorage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;

// Binding numbers of shaders/common/scene_data.glsl.
enum Binding : uint32_t {
  kScene = 0, kAccumulation, kFrame, kSpheres, kMaterials, kLights, kPositions, kNormals,
  kIndices, kTriangles, kRayCounts, kSphereRefs, kCells, kCellFaces, kDiagnostics,
  kEmitters, kLightImages, kBindingCount
};

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
  u.light_sampling = scene.render.light_sampling == LightSampling::Bsdf ? 1u : 0u;
  u.emitter_count = static_cast<uint32_t>(packed.emitters.size());
  u.light_cutoff = static_cast<float>(packed.light_cutoff);
  u.clamp = static_cast<float>(scene.render.clamp);
  return u;
}

}  // namespace

SceneResources::SceneResources(VulkanContext& ctx, const Scene& scene)
    : ctx_(ctx),
      geometry_(scene.geometry),
      packed_(pack_scene(scene)), uniforms_(make_uniforms(scene, packed_)) {
  structures_ = SceneAccelerationStructures::build(ctx, packed_);
  capacity_ = size_t(width()) * height();
  frame_ = GpuBuffer(ctx, sizeof(FrameUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
  std::memcpy(frame_.mapped(), &uniforms_, sizeof(uniforms_));
  accumulation_ = GpuBuffer(ctx, 2 * VkDeviceSize(width()) * height() * 4 * sizeof(float),
                            kStorage | VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  ray_counts_ = GpuBuffer(ctx, VkDeviceSize(width()) * height() * sizeof(uint32_t), kStorage);
  clear_accumulation();
  spheres_ = GpuBuffer::from_vector(ctx, packed_.spheres, kStorage);
  materials_ = GpuBuffer::from_vector(ctx, packed_.materials, kStorage);
  lights_ = GpuBuffer::from_vector(ctx, packed_.lights, kStorage);
  positions_ = GpuBuffer::from_vector(ctx, packed_.positions, kStorage);
  normals_ = GpuBuffer::from_vector(ctx, packed_.normals, kStorage);
  indices_ = GpuBuffer::from_vector(ctx, packed_.indices, kStorage);
  triangles_ = GpuBuffer::from_vector(ctx, packed_.triangles, kStorage);
  sphere_refs_ = GpuBuffer::from_vector(ctx, packed_.sphere_refs, kStorage);
  cells_ = GpuBuffer::from_vector(ctx, packed_.cells, kStorage);
  faces_ = GpuBuffer::from_vector(ctx, packed_.faces, kStorage);
  emitters_ = GpuBuffer::from_vector(ctx, packed_.emitters, kStorage);
  light_images_ = GpuBuffer::from_vector(ctx, packed_.light_images, kStorage);
  diagnostics_ = GpuBuffer(ctx, sizeof(uint32_t), kStorage);
  std::memset(diagnostics_.mapped(), 0, sizeof(uint32_t));
  create_descriptors();
}

SceneResources::~SceneResources() {
  VkDevice device = ctx_.device();
  vkDeviceWaitIdle(device);
  vkDestroyPipelineLayout(device, pipeline_layout_, nullptr);
  vkDestroyDescriptorPool(device, pool_, nullptr);
  vkDestroyDescriptorSetLayout(device, set_layout_, nullptr);
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

void SceneResources::set_max_depth(uint32_t max_depth) {
  uniforms_.max_depth = max_depth;
  std::memcpy(frame_.mapped(), &uniforms_, sizeof(uniforms_));
  clear_accumulation();
}

void SceneResources::clear_accumulation() {
  std::memset(accumulation_.mapped(), 0, accumulation_.size());
  std::memset(ray_counts_.mapped(), 0, ray_counts_.size());
}

void SceneResources::load_accumulation(const float* sums) {
  std::memcpy(accumulation_.mapped(), sums, 2 * size_t(width()) * height() * 4 * sizeof(float));
}

uint32_t SceneResources::non_finite_samples() const {
  return *static_cast<const uint32_t*>(diagnostics_.mapped());
}

uint64_t SceneResources::traced_rays() const {
  const auto* counts = static_cast<const uint32_t*>(ray_counts_.mapped());
  uint64_t total = 0;
  for (size_t i = 0; i < size_t(width()) * height(); ++i) total += counts[i];
  return total;
}

void SceneResources::create_descriptors() {
  VkDevice device = ctx_.device();
  VkDescriptorSetLayoutBinding bindings[kBindingCount]{};
  for (uint32_t i = 0; i < kBindingCount; ++i) {
    bindings[i].binding = i;
    bindings[i].descriptorCount = 1;
    bindings[i].stageFlags = SceneResources::kShaderStages;
    bindings[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  }
  bindings[kScene].descriptorType = VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR;
  bindings[kFrame].descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
  VkDescriptorSetLayoutCreateInfo layout{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  layout.bindingCount = kBindingCount;
  layout.pBindings = bindings;
  vk_check(vkCreateDescriptorSetLayout(device, &layout, nullptr, &set_layout_),
           "vkCreateDescriptorSetLayout");

  VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR, 1},
                                  {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1},
                                  {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kBindingCount - 2}};
  VkDescriptorPoolCreateInfo pool{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  pool.maxSets = 1;
  pool.poolSizeCount = 3;
  pool.pPoolSizes = sizes;
  vk_check(vkCreateDescriptorPool(device, &pool, nullptr, &pool_), "vkCreateDescriptorPool");
  VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  alloc.descriptorPool = pool_;
  alloc.descriptorSetCount = 1;
  alloc.pSetLayouts = &set_layout_;
  vk_check(vkAllocateDescriptorSets(device, &alloc, &set_), "vkAllocateDescriptorSets");

  VkPushConstantRange push{SceneResources::kShaderStages, 0, sizeof(SampleRange)};
  VkPipelineLayoutCreateInfo pipeline{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  pipeline.setLayoutCount = 1;
  pipeline.pSetLayouts = &set_layout_;
  pipeline.pushConstantRangeCount = 1;
  pipeline.pPushConstantRanges = &push;
  vk_check(vkCreatePipelineLayout(device, &pipeline, nullptr, &pipeline_layout_),
           "vkCreatePipelineLayout");

  // Write every binding.
  VkAccelerationStructureKHR tlas = structures_.top.handle();
  VkWriteDescriptorSetAccelerationStructureKHR as_write{
      VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET_ACCELERATION_STRUCTURE_KHR};
  as_write.accelerationStructureCount = 1;
  as_write.pAccelerationStructures = &tlas;
  const GpuBuffer* buffers[kBindingCount] = {nullptr,     &accumulation_, &frame_,
                                             &spheres_,   &materials_,    &lights_,
                                             &positions_, &normals_,      &indices_,
                                             &triangles_,   &ray_counts_,   &sphere_refs_,
                                             &cells_,       &faces_,        &diagnostics_,
                                             &emitters_,    &light_images_};
  VkDescriptorBufferInfo infos[kBindingCount]{};
  VkWriteDescriptorSet writes[kBindingCount]{};
  for (uint32_t i = 0; i < kBindingCount; ++i) {
    writes[i].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
    writes[i].dstSet = set_;
    writes[i].dstBinding = i;
    writes[i].descriptorCount = 1;
    writes[i].descriptorType = bindings[i].descriptorType;
    if (i == kScene) {
      writes[i].pNext = &as_write;
    } else {
      infos[i] = {buffers[i]->handle(), 0, VK_WHOLE_SIZE};
      writes[i].pBufferInfo = &infos[i];
    }
  }
  vkUpdateDescriptorSets(device, kBindingCount, writes, 0, nullptr);
}

}  // namespace geodesic
