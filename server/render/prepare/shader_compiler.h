// GLSL -> SPIR-V at run time with glslang, so each scene's pipeline is compiled with its own
// feature defines (render/prepare/pipeline_features.h) instead of one build-time shader per geometry.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace geodesic {

// The GLSL sources: $GEODESIC_SHADER_DIR if set, else the source tree's shaders/.
std::filesystem::path shader_source_directory();

// A digest of every file under shader_source_directory() and of glslang's version: part of
// each cache key, so an edited shader or a new compiler never reuses a stale binary.
const std::string& shader_sources_digest();

struct CompiledShader {
  std::string glsl;              // preprocessed: includes resolved, #if branches applied
  std::vector<uint32_t> spirv;
};

// Compiles shaders/<entry> (e.g. "entry/ray_query.comp"; the stage comes from the extension)
// with "NAME" / "NAME=VALUE" defines. Throws std::runtime_error with glslang's log on failure.
CompiledShader compile_shader(const std::string& entry, const std::vector<std::string>& defines);

// 64-bit FNV-1a, as 16 hex digits: stable across runs and machines (cache file names).
std::string fnv1a_hex(const void* data, size_t size, uint64_t seed = 0xcbf29ce484222325ull);

}  // namespace geodesic
