#include "scene/document_files.h"

#include <algorithm>
#include <system_error>

namespace geodesic {

std::filesystem::path DocumentFiles::resolve(const JsonNode& node) const {
  namespace fs = std::filesystem;
  const fs::path path = dir / read_string(node);
  if (!confined) return path;
  // Symbolic links and ".." resolved: the real location must be under the real directory.
  std::error_code ec;
  const fs::path root = fs::weakly_canonical(dir, ec);
  const fs::path file = ec ? fs::path() : fs::weakly_canonical(path, ec);
  if (ec || std::mismatch(root.begin(), root.end(), file.begin(), file.end()).first != root.end())
    node.fail("must name a file inside the scene directory");
  return file;
}

}  // namespace geodesic
