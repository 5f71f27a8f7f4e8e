// The WebSocket messages of docs/protocol.md: client JSON parsed into RenderService requests
// (with the path of the offending field on error), server messages built as JSON text.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "render/service/render_service.h"
#include "scene/scene_source.h"

namespace geodesic::net {

// `open`: exactly one of a bundled scene name, an inline document, or generator text (a
// Curved Spaces .gen file or SnapPy pairing matrices: the default scene inside that space).
struct OpenRequest {
  std::optional<std::string> scene;
  std::optional<nlohmann::ordered_json> document;
  std::optional<std::string> generators;

  SceneSource source() const;  // what the render service resolves
};

using ClientMessage = std::variant<OpenRequest, CameraMotion, SessionSettings>;

// A client message that cannot be applied; field is its JSON path ("" for the whole message).
class ProtocolError : public std::runtime_error {
 public:
  ProtocolError(std::string field, const std::string& message)
      : std::runtime_error(message), field_(std::move(field)) {}
  const std::string& field() const { return field_; }

 private:
  std::string field_;
};

// Throws ProtocolError.
ClientMessage parse_client_message(std::string_view text, const ServiceLimits& limits);

// Turns a RenderService error "<field>: <reason>" into a ProtocolError whose field is a path in
// the client's message: below `document` for inline documents, `scene` for bundled names.
ProtocolError service_error(const std::exception& error, const OpenRequest* open);

std::string hello_message(uint64_t session, const std::vector<std::string>& scenes,
                          const ServiceLimits& limits, std::size_t max_message_bytes,
                          std::chrono::milliseconds idle_timeout);
std::string scene_message(const SceneInfo& scene);
std::string frame_message(const FrameInfo& frame);
std::string error_message(const ProtocolError& error);

}  // namespace geodesic::net
