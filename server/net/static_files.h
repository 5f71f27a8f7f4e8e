// The web client's files, served only from inside the web directory.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace geodesic::net {

struct StaticFile {
  std::string body;
  std::string_view mime_type;
};

// `target_path` is the request target without its query, still percent-encoded; a directory
// means its index.html. Returns nullopt (answer 404) when the file is absent, not a regular
// file, or would lie outside web_dir: any ".." segment, encoded or not, is refused before
// touching the file system, and the resolved path must still be inside web_dir (symbolic links
// cannot lead out).
std::optional<StaticFile> load_static_file(const std::filesystem::path& web_dir,
                                           std::string_view target_path);

// Decodes %XX escapes; nullopt for a malformed escape or an encoded NUL.
std::optional<std::string> percent_decode(std::string_view text);

std::string_view mime_type(const std::filesystem::path& file);

}  // namespace geodesic::net
