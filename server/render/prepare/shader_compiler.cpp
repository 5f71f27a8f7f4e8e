#include "render/prepare/shader_compiler.h"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <memory>
#include <mutex>
#include <sstream>
#include <stdexcept>

namespace geodesic {
namespace {

std::string read_text(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw std::runtime_error("cannot read shader source " + path.string());
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

EShLanguage stage_of(const std::string& entry) {
  static const std::map<std::string, EShLanguage> stages = {
      {".comp", EShLangCompute},     {".rgen", EShLangRayGen},
      {".rmiss", EShLangMiss},       {".rchit", EShLangClosestHit},
      {".rint", EShLangIntersect},   {".rahit", EShLangAnyHit}};
  const auto it = stages.find(std::filesystem::path(entry).extension().string());
  if (it == stages.end()) throw std::runtime_error("shader " + entry + ": unknown stage");
  return it->second;
}

// #include "x.glsl" resolves against the shader source directory, as -I did at build time.
class SourceIncluder : public glslang::TShader::Includer {
 public:
  IncludeResult* includeLocal(const char* name, const char*, size_t) override {
    return includeSystem(name, nullptr, 0);
  }
  IncludeResult* includeSystem(const char* name, const char*, size_t) override {
    const auto path = shader_source_directory() / name;
    auto text = std::make_unique<std::string>(read_text(path));
    auto* result = new IncludeResult(path.string(), text->data(), text->size(), text.get());
    text.release();
    return result;
  }
  void releaseInclude(IncludeResult* result) override {
    if (!result) return;
    delete static_cast<std::string*>(result->userData);
    delete result;
  }
};

std::string preamble(const std::vector<std::string>& defines) {
  std::string text;
  for (std::string d : defines) {
    std::replace(d.begin(), d.end(), '=', ' ');
    text += "#define " + d + "\n";
  }
  return text;
}

// glslang keeps process-wide tables: initialise once, compile one shader at a time.
std::mutex& glslang_mutex() {
  static std::mutex mutex;
  static const bool initialised = glslang::InitializeProcess();
  (void)initialised;
  return mutex;
}

}  // namespace

std::filesystem::path shader_source_directory() {
  if (const char* dir = std::getenv("GEODESIC_SHADER_DIR"); dir && *dir) return dir;
  return std::filesystem::path(GEODESIC_SOURCE_DIR) / "shaders";
}

std::string fnv1a_hex(const void* data, size_t size, uint64_t seed) {
  uint64_t h = seed;
  const auto* bytes = static_cast<const unsigned char*>(data);
  for (size_t i = 0; i < size; ++i) h = (h ^ bytes[i]) * 0x100000001b3ull;
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return hex;
}

const std::string& shader_sources_digest() {
  static const std::string digest = [] {
    std::vector<std::filesystem::path> files;
    for (const auto& e : std::filesystem::recursive_directory_iterator(shader_source_directory()))
      if (e.is_regular_file()) files.push_back(e.path());
    std::sort(files.begin(), files.end());
    std::string all = "glslang " + std::to_string(glslang::GetVersion().major) + "." +
                      std::to_string(glslang::GetVersion().minor) + "." +
                      std::to_string(glslang::GetVersion().patch) + "\n";
    for (const auto& f : files)
      all += f.lexically_relative(shader_source_directory()).string() + "\n" + read_text(f);
    return fnv1a_hex(all.data(), all.size());
  }();
  return digest;
}

CompiledShader compile_shader(const std::string& entry, const std::vector<std::string>& defines) {
  const EShLanguage stage = stage_of(entry);
  const std::string source = read_text(shader_source_directory() / entry);
  const std::string defs = preamble(defines);
  std::lock_guard lock(glslang_mutex());

  glslang::TShader shader(stage);
  const char* text = source.c_str();
  const char* name = entry.c_str();
  shader.setStringsWithLengthsAndNames(&text, nullptr, &name, 1);
  shader.setPreamble(defs.c_str());
  shader.setEnvInput(glslang::EShSourceGlsl, stage, glslang::EShClientVulkan, 100);
  shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_2);
  shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_5);
  const auto messages = static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules);
  SourceIncluder includer;
  auto fail = [&](const char* what, const char* log) {
    throw std::runtime_error("shader " + entry + " (" + what + "): " + log);
  };

  CompiledShader out;
  if (!shader.preprocess(GetDefaultResources(), 460, ECoreProfile, false, false, messages,
                         &out.glsl, includer))
    fail("preprocess", shader.getInfoLog());
  if (!shader.parse(GetDefaultResources(), 460, false, messages, includer))
    fail("compile", shader.getInfoLog());
  glslang::TProgram program;
  program.addShader(&shader);
  if (!program.link(messages)) fail("link", program.getInfoLog());
  glslang::SpvOptions options;
  options.disableOptimizer = true;  // the driver optimises; glslang's pass needs SPIRV-Tools
  glslang::GlslangToSpv(*program.getIntermediate(stage), out.spirv, &options);
  out.glsl = defs + out.glsl;
  return out;
}

}  // namespace geodesic
