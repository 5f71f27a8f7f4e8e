// libFuzzer: any bytes as a scene document. The loader's contract is a Scene or a SceneError
// naming the field; any other exception, a crash or a sanitizer report is a bug. Mesh and
// generator file names resolve against the bundled scenes, as for documents sent to the daemon.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include <nlohmann/json.hpp>

#include "scene/scene_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using Json = nlohmann::ordered_json;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  // Not JSON: nlohmann's parser is not ours to test, and load_scene_file reports it.
  const Json doc = Json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (doc.is_discarded()) return -1;  // keeps it out of the corpus
  try {
    geodesic::parse_scene(doc, std::filesystem::path(GEODESIC_SOURCE_DIR "/scenes"));
  } catch (const geodesic::SceneError&) {
  }
  return 0;
}
