// The GPU-visible structs (shaders/common/gpu_types.h) and binding numbers (bindings.h), which
// host and shaders compile from one definition, against the layout the shader compiler gives
// them: ray_query.comp is compiled with every feature, its SPIR-V read for each struct's member
// offsets, member types and array stride and for each block's binding, and compared with the
// host's offsetof / decltype / sizeof and binding numbers. A member whose C++ layout differs
// from std430 / std140 (a vec3, a scalar before a vec4, a size not a multiple of 16), or a
// block bound at another number than the host binds, fails here instead of in a pipeline.
#include <gtest/gtest.h>

#include <cstddef>
#include <map>
#include <ostream>
#include <type_traits>
#include <string>
#include <vector>

#include "render/prepare/emitters.h"
#include "render/prepare/frame_uniforms.h"
#include "render/prepare/packed_scene.h"
#include "render/prepare/pipeline_features.h"
#include "render/prepare/scene_bindings.h"
#include "render/prepare/shader_compiler.h"
#include "render/prepare/triangle_list.h"

namespace geodesic::test {
namespace {

// A member as both sides see it: its offset and its type ("float", "uint", "vec4", "mat4").
struct Member {
  uint32_t offset;
  std::string type;
  bool operator==(const Member&) const = default;
};

std::ostream& operator<<(std::ostream& out, const Member& m) {
  return out << m.type << " at " << m.offset;
}

// What SPIR-V says of the shader's types: struct names, member offsets and types, array
// strides and the blocks bound at each binding (SPIR-V 1.5 specification, section 3: opcodes
// 5 OpName, 21-24 int/float/vector/matrix types, 28-30 array and struct types, 32 pointer, 59
// OpVariable, 71-72 decorations; decorations 6 ArrayStride, 33 Binding, 35 Offset).
struct SpirvLayout {
  std::map<std::string, std::vector<Member>> structs;  // in member order
  std::map<std::string, uint32_t> strides;  // struct name -> stride of an array of it
  std::map<uint32_t, std::string> blocks;  // binding -> its block's (struct's) name
};

SpirvLayout read_layout(const std::vector<uint32_t>& words) {
  std::map<uint32_t, std::string> names, types;
  std::map<uint32_t, std::vector<uint32_t>> members;  // struct -> member type ids
  std::map<uint32_t, std::map<uint32_t, uint32_t>> member_offsets;
  std::map<uint32_t, uint32_t> array_of, stride_of, pointee_of, binding_of, type_of;
  for (size_t i = 5; i < words.size();) {
    const uint32_t count = words[i] >> 16, op = words[i] & 0xffff;
    const uint32_t* w = &words[i];
    if (op == 5) names[w[1]] = reinterpret_cast<const char*>(&w[2]);
    if (op == 21) types[w[1]] = w[3] ? "int" : "uint";
    if (op == 22) types[w[1]] = "float";
    if (op == 23) types[w[1]] = (types[w[2]] == "float" ? "vec" : "uvec") + std::to_string(w[3]);
    if (op == 24) types[w[1]] = "mat" + std::to_string(w[3]);
    if (op == 28 || op == 29) array_of[w[1]] = w[2];
    if (op == 30) members[w[1]].assign(w + 2, w + count);
    if (op == 32) pointee_of[w[1]] = w[3];
    if (op == 59) type_of[w[2]] = w[1];
    if (op == 71 && w[2] == 6) stride_of[w[1]] = w[3];
    if (op == 71 && w[2] == 33) binding_of[w[1]] = w[3];
    if (op == 72 && w[3] == 35) member_offsets[w[1]][w[2]] = w[4];
    i += count;
  }
  SpirvLayout layout;
  for (const auto& [id, offsets] : member_offsets)
    for (const auto& [member, offset] : offsets) {
      const uint32_t type = members[id][member];
      layout.structs[names[id]].push_back(
          {offset, types.count(type) ? types[type] : array_of.count(type) ? "array" : names[type]});
    }
  for (const auto& [array, element] : array_of)
    if (stride_of.count(array)) layout.strides[names[element]] = stride_of[array];
  for (const auto& [variable, binding] : binding_of)
    layout.blocks[binding] = names[pointee_of[type_of[variable]]];
  return layout;
}

// The shader type a host member stands for.
template <class T>
std::string gpu_type() {
  if constexpr (std::is_same_v<T, float>) return "float";
  if constexpr (std::is_same_v<T, uint32_t>) return "uint";
  if constexpr (std::is_same_v<T, std::array<float, 4>>) return "vec4";
  if constexpr (std::is_same_v<T, std::array<float, 16>>) return "mat4";
  return "?";
}

const SpirvLayout& shader_layout() {
  static const SpirvLayout layout = [] {
    PipelineFeatures f = all_features(GeometryKind::Hyperbolic);
    f.paper = f.point_lights = true;  // the paper model's light list too
    return read_layout(compile_shader("entry/ray_query.comp", f.defines()).spirv);
  }();
  return layout;
}

// A pipeline that lists its cells' triangles (which the all-features one traverses).
const SpirvLayout& listing_layout() {
  static const SpirvLayout layout = [] {
    PipelineFeatures f = all_features(GeometryKind::Euclidean);
    f.shapes = false;
    f.sphere_list = f.triangle_list = true;
    return read_layout(compile_shader("entry/ray_query.comp", f.defines()).spirv);
  }();
  return layout;
}

#define AT(T, m) Member{uint32_t(offsetof(T, m)), gpu_type<decltype(T::m)>()}

TEST(GpuLayout, EveryHostStructHasItsShaderStructsOffsetsAndStride) {
  const SpirvLayout& shader = shader_layout();
  struct Expected {
    const char* glsl;
    std::vector<Member> members;
    uint32_t size;
  };
  const std::vector<Expected> structs = {
      {"Material",
       {AT(GpuMaterial, ambient), AT(GpuMaterial, diffuse), AT(GpuMaterial, specular),
        AT(GpuMaterial, mirror), AT(GpuMaterial, transmission), AT(GpuMaterial, emission)},
       sizeof(GpuMaterial)},
      {"Sphere",
       {AT(GpuSphere, center), AT(GpuSphere, radius), AT(GpuSphere, material),
        AT(GpuSphere, emitter), AT(GpuSphere, pad0)},
       sizeof(GpuSphere)},
      {"SphereRef", {AT(GpuSphereRef, sphere), AT(GpuSphereRef, cell)}, sizeof(GpuSphereRef)},
      {"Shape",
       {AT(GpuShape, a), AT(GpuShape, b), AT(GpuShape, size), AT(GpuShape, kind),
        AT(GpuShape, material), AT(GpuShape, emitter)},
       sizeof(GpuShape)},
      {"ShapeRef", {AT(GpuShapeRef, shape), AT(GpuShapeRef, cell)}, sizeof(GpuShapeRef)},
      {"PointLight", {AT(GpuPointLight, position), AT(GpuPointLight, intensity)},
       sizeof(GpuPointLight)},
      {"TriangleInfo",
       {AT(GpuTriangle, material), AT(GpuTriangle, smooth_normals), AT(GpuTriangle, cell),
        AT(GpuTriangle, emitter)},
       sizeof(GpuTriangle)},
      {"Emitter",
       {AT(GpuEmitter, center), AT(GpuEmitter, corner), AT(GpuEmitter, edge1),
        AT(GpuEmitter, edge2), AT(GpuEmitter, radiance), AT(GpuEmitter, kind),
        AT(GpuEmitter, radius), AT(GpuEmitter, pmf), AT(GpuEmitter, cdf),
        AT(GpuEmitter, image_begin), AT(GpuEmitter, image_count),
        AT(GpuEmitter, antipodal_pairs), AT(GpuEmitter, pad1)},
       sizeof(GpuEmitter)},
      {"LightImage", {AT(GpuLightImage, isometry), AT(GpuLightImage, center)},
       sizeof(GpuLightImage)},
      {"Cell",
       {AT(GpuCell, chart_isometry), AT(GpuCell, content_lo), AT(GpuCell, content_hi),
        AT(GpuCell, triangle_lo), AT(GpuCell, triangle_hi),
        AT(GpuCell, face_begin), AT(GpuCell, face_count),
        AT(GpuCell, tube_begin), AT(GpuCell, tube_count), AT(GpuCell, tube_reach),
        AT(GpuCell, always_begin), AT(GpuCell, sphere_begin), AT(GpuCell, sphere_count),
        AT(GpuCell, listed_begin), AT(GpuCell, listed_count), AT(GpuCell, listed_pairs),
        AT(GpuCell, shape_begin), AT(GpuCell, shape_count), AT(GpuCell, listed_hull_pairs),
        AT(GpuCell, listed_hull_lone), AT(GpuCell, pad0)},
       sizeof(GpuCell)},
      {"Tube",
       {AT(GpuTube, a), AT(GpuTube, b), AT(GpuTube, material), AT(GpuTube, face_a),
        AT(GpuTube, face_b), AT(GpuTube, pad0)},
       sizeof(GpuTube)},
      {"CellFace",
       {AT(GpuCellFace, plane), AT(GpuCellFace, pairing), AT(GpuCellFace, target_cell),
        AT(GpuCellFace, partner), AT(GpuCellFace, internal), AT(GpuCellFace, tubes),
        AT(GpuCellFace, tube_partners), AT(GpuCellFace, pad0), AT(GpuCellFace, pad1),
        AT(GpuCellFace, pad2)},
       sizeof(GpuCellFace)},
  };
  for (const Expected& e : structs) {
    SCOPED_TRACE(e.glsl);
    ASSERT_TRUE(shader.structs.count(e.glsl)) << "the shader has no struct of this name";
    EXPECT_EQ(shader.structs.at(e.glsl), e.members);
    ASSERT_TRUE(shader.strides.count(e.glsl)) << "no array of it in a buffer";
    EXPECT_EQ(shader.strides.at(e.glsl), e.size);
  }
  const SpirvLayout& listing = listing_layout();
  ASSERT_TRUE(listing.structs.count("ListedPrimitive"));
  EXPECT_EQ(listing.structs.at("ListedPrimitive"),
            (std::vector<Member>{AT(GpuListedPrimitive, triangle),
                                 AT(GpuListedPrimitive, second)}));
  EXPECT_EQ(listing.strides.at("ListedPrimitive"), sizeof(GpuListedPrimitive));
  // The uniform block (std140) and the push constants.
  EXPECT_EQ(shader.structs.at("FrameUniforms"),
            (std::vector<Member>{
                AT(FrameUniforms, camera_pose), AT(FrameUniforms, ambient_light),
                AT(FrameUniforms, tan_half_fov_y), AT(FrameUniforms, aspect),
                AT(FrameUniforms, width), AT(FrameUniforms, height), AT(FrameUniforms, max_depth),
                AT(FrameUniforms, light_count), AT(FrameUniforms, seed),
                AT(FrameUniforms, russian_roulette), AT(FrameUniforms, max_crossings),
                AT(FrameUniforms, camera_cell), AT(FrameUniforms, lighting),
                AT(FrameUniforms, light_sampling), AT(FrameUniforms, emitter_count),
                AT(FrameUniforms, light_cutoff), AT(FrameUniforms, clamp_luminance),
                AT(FrameUniforms, light_samples)}));
  EXPECT_EQ(shader.structs.at("SampleRange"),
            (std::vector<Member>{AT(SampleRange, start), AT(SampleRange, count),
                                   AT(SampleRange, column_offset), AT(SampleRange, row_offset),
                                   AT(SampleRange, column_count), AT(SampleRange, row_count)}));
}

TEST(GpuLayout, EveryBindingHoldsTheBlockTheHostBindsThere) {
  const std::map<uint32_t, std::string> expected = {
      {kAccumulationBinding, "Accumulation"}, {kFrameBinding, "Frame"},
      {kSpheresBinding, "Spheres"},           {kMaterialsBinding, "Materials"},
      {kLightsBinding, "Lights"},             {kPositionsBinding, "Positions"},
      {kIndicesBinding, "Indices"},           {kTrianglesBinding, "Triangles"},
      {kRayCountsBinding, "RayCounts"},       {kSphereRefsBinding, "SphereRefs"},
      {kCellsBinding, "Cells"},               {kCellFacesBinding, "CellFaces"},
      {kDiagnosticsBinding, "Diagnostics"},   {kEmittersBinding, "Emitters"},
      {kLightImagesBinding, "LightImages"},   {kTubesBinding, "Tubes"},
      {kShapesBinding, "Shapes"},             {kShapeRefsBinding, "ShapeRefs"},
      {kNormalsBinding, "Normals"},           {kListedBinding, "Listed"}};
  const SpirvLayout& shader = shader_layout();
  for (const auto& [binding, block] : expected) {
    if (binding == kNormalsBinding || binding == kListedBinding) continue;  // checked below
    EXPECT_EQ(shader.blocks.count(binding) ? shader.blocks.at(binding) : "(none)", block)
        << "binding " << binding;
  }
  PipelineFeatures euclidean = all_features(GeometryKind::Euclidean);
  const SpirvLayout e3 =
      read_layout(compile_shader("entry/ray_query.comp", euclidean.defines()).spirv);
  EXPECT_EQ(e3.blocks.count(kNormalsBinding) ? e3.blocks.at(kNormalsBinding) : "(none)",
            "Normals");
  EXPECT_EQ(listing_layout().blocks.count(kListedBinding)
                ? listing_layout().blocks.at(kListedBinding)
                : "(none)",
            "Listed");
  // Every binding the host numbers is one of these, and one more is the scene's acceleration
  // structure (binding 0, which has no block).
  EXPECT_EQ(expected.size() + 1, size_t(kSceneBindingCount));
}

}  // namespace
}  // namespace geodesic::test
