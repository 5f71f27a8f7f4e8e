// Where the file names in a scene document (mesh files, generator files) may lead. Documents
// from disk may name any file; documents sent to the daemon only files inside its scene
// directory, or a client could make the server read its other files and echo parts of them
// back in error messages.
#pragma once

#include <filesystem>

#include "scene/json_path.h"

namespace geodesic {

struct DocumentFiles {
  // Implicit: a plain directory means a trusted document.
  DocumentFiles(std::filesystem::path dir = {}, bool confined = false)
      : dir(std::move(dir)), confined(confined) {}

  // The file the string at `node` names, relative to dir. When confined, fails on the node
  // (the same message whether or not the file exists) unless it lies inside dir.
  std::filesystem::path resolve(const JsonNode& node) const;

  std::filesystem::path dir;
  bool confined = false;
};

}  // namespace geodesic
