#include "render/device/shader_dump.h"

#include <fstream>
#include <stdexcept>

#include "render/prepare/shader_compiler.h"

namespace geodesic {
namespace {

void write(const std::filesystem::path& path, const void* data, size_t size) {
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  file.write(static_cast<const char*>(data), std::streamsize(size));
  if (!file.flush()) throw std::runtime_error("--dump-shaders: cannot write " + path.string());
}

}  // namespace

std::vector<std::filesystem::path> dump_shaders(const Renderer& renderer,
                                                const std::filesystem::path& dir) {
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error) throw std::runtime_error("--dump-shaders: cannot create " + dir.string() + ": " + error.message());
  const PipelineFeatures& features = renderer.features();
  std::vector<std::filesystem::path> written;
  std::string summary = features.summary() + "\n";
  for (std::string define : features.defines()) {
    if (const auto equals = define.find('='); equals != std::string::npos) define[equals] = ' ';
    summary += "#define " + define + "\n";
  }
  written.push_back(dir / "features.txt");
  write(written.back(), summary.data(), summary.size());
  for (const auto& entry : renderer.backend().entries()) {
    const CompiledShader shader = compile_shader(entry, features.defines());
    const std::string name = std::filesystem::path(entry).filename().string();
    written.push_back(dir / (name + ".glsl"));
    write(written.back(), shader.glsl.data(), shader.glsl.size());
    written.push_back(dir / (name + ".spv"));
    write(written.back(), shader.spirv.data(), shader.spirv.size() * 4);
  }
  return written;
}

}  // namespace geodesic
