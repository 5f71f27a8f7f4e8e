// libFuzzer: any bytes as a client's WebSocket message and as raw HTTP request bytes, through
// the daemon's handling that needs no device or socket.
//   WebSocket: parse_client_message, then for `open` the scene it names, resolved as the daemon
//   resolves it (scene/scene_source.h: a bundled name, an inline document whose files are
//   confined to the scene directory, generator text) and the error message the client would get. Contract: ProtocolError or SceneError, nothing else.
//   HTTP: Beast's request parser with the daemon's body limit, then the token check and the
//   static file lookup in web/. Contract: never a file from outside web/.
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <string>
#include <string_view>
#include <variant>

#include "net/auth.h"
#include "net/protocol.h"
#include "net/server_context.h"
#include "net/static_files.h"
#include "scene/scene_source.h"

namespace geodesic::net {
namespace {

void client_message(std::string_view text) {
  const ServiceLimits limits;
  ClientMessage message;
  try {
    message = parse_client_message(text, limits);
  } catch (const ProtocolError& e) {
    error_message(e);
    return;
  }
  const auto* open = std::get_if<OpenRequest>(&message);
  if (!open) return;  // camera moves and settings need the render service
  try {
    resolve_scene(open->source(), GEODESIC_SOURCE_DIR "/scenes");
  } catch (const SceneError& e) {
    error_message(service_error(e, open));
  }
}

std::string read_file(const char* path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

void http_request(std::string_view bytes) {
  http::request_parser<http::string_body> parser;
  parser.body_limit(kMaxMessageBytes);
  parser.eager(true);  // header and body in one put()
  beast::error_code ec;
  parser.put(asio::buffer(bytes.data(), bytes.size()), ec);
  if (!ec && !parser.is_done()) parser.put_eof(ec);  // the client closed after these bytes
  if (ec || !parser.is_done()) return;
  const Request& request = parser.get();
  const std::string_view target(request.target().data(), request.target().size());
  const std::string_view path = target.substr(0, target.find('?'));
  if (needs_token(path)) authorized(request, "secret");
  const auto file = load_static_file(GEODESIC_SOURCE_DIR "/web", path);
  // The file next to web/ that a traversal would reach first.
  static const std::string outside = read_file(GEODESIC_SOURCE_DIR "/CMakeLists.txt");
  if (file && file->body == outside) __builtin_trap();
}

}  // namespace
}  // namespace geodesic::net

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  geodesic::net::client_message(bytes);
  geodesic::net::http_request(bytes);
  return 0;
}
