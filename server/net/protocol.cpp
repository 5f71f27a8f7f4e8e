#include "net/protocol.h"

#include <cmath>
#include <initializer_list>
#include <utility>

#include "scene/render_settings_loader.h"

namespace geodesic::net {
namespace {

using Json = nlohmann::ordered_json;

// Invalid UTF-8 echoed from client input must not make dump() throw.
std::string dump(const Json& message) {
  return message.dump(-1, ' ', false, Json::error_handler_t::replace);
}

void reject_unknown_fields(const Json& message, std::initializer_list<std::string_view> known) {
  for (const auto& [key, value] : message.items()) {
    if (key == "type") continue;
    bool found = false;
    for (std::string_view k : known) found = found || k == key;
    if (!found) throw ProtocolError(key, "unknown field");
  }
}

// The largest step (geodesic length) and turn (degrees) one `move` may ask for.
constexpr double kMaxStep = 10;
constexpr double kMaxTurnDegrees = 360;

double finite_number(const Json& message, const std::string& key) {
  const Json& v = message.at(key);
  if (!v.is_number() || !std::isfinite(v.get<double>()))
    throw ProtocolError(key, "must be a finite number");
  return v.get<double>();
}

int integer_in(const Json& message, const std::string& key, int min, int max) {
  const Json& v = message.at(key);
  const std::string range = "[" + std::to_string(min) + ", " + std::to_string(max) + "]";
  if (!v.is_number_integer()) throw ProtocolError(key, "must be an integer in " + range);
  const int64_t n = v.get<int64_t>();
  if (n < min || n > max) throw ProtocolError(key, "must be in " + range);
  return static_cast<int>(n);
}

OpenRequest parse_open(const Json& message) {
  reject_unknown_fields(message, {"scene", "document", "generators"});
  const int given = int(message.contains("scene")) + int(message.contains("document")) +
                    int(message.contains("generators"));
  if (given != 1)
    throw ProtocolError(!given                          ? "scene"
                        : message.contains("generators") ? "generators"
                                                         : "document",
                        "give one of scene (a bundled name), document (an inline scene) or "
                        "generators (the text of a .gen file)");
  OpenRequest open;
  if (message.contains("scene")) {
    if (!message["scene"].is_string()) throw ProtocolError("scene", "must be a string");
    open.scene = message["scene"].get<std::string>();
  } else if (message.contains("generators")) {
    if (!message["generators"].is_string()) throw ProtocolError("generators", "must be a string");
    open.generators = message["generators"].get<std::string>();
  } else {
    if (!message["document"].is_object()) throw ProtocolError("document", "must be an object");
    open.document = message["document"];
  }
  return open;
}

CameraMotion parse_move(const Json& message) {
  reject_unknown_fields(message, {"forward", "right", "up", "yaw", "pitch", "roll"});
  CameraMotion m;
  const std::pair<const char*, double*> fields[] = {
      {"forward", &m.forward}, {"right", &m.right}, {"up", &m.up},
      {"yaw", &m.yaw},         {"pitch", &m.pitch}, {"roll", &m.roll}};
  for (const auto& [key, target] : fields) {
    if (!message.contains(key)) continue;
    *target = finite_number(message, key);
    // One move is a step within a few domains and a turn within a full circle: beyond that the
    // pose's hyperbolic functions overflow (a 1e308 step made it NaN for good).
    const bool turn = target == &m.yaw || target == &m.pitch || target == &m.roll;
    const double limit = turn ? kMaxTurnDegrees : kMaxStep;
    if (std::abs(*target) > limit)
      throw ProtocolError(key, "must be within [-" + std::to_string(int(limit)) + ", " +
                                   std::to_string(int(limit)) + "] " +
                                   (turn ? "degrees" : "(a geodesic length)"));
  }
  return m;
}

SessionSettings parse_settings(const Json& message, const ServiceLimits& limits) {
  reject_unknown_fields(message, {"width", "height", "max_depth", "exposure"});
  SessionSettings s;
  if (message.contains("width")) s.width = integer_in(message, "width", 16, limits.max_width);
  if (message.contains("height")) s.height = integer_in(message, "height", 16, limits.max_height);
  if (message.contains("max_depth"))
    s.max_depth = integer_in(message, "max_depth", 0, limits.max_depth);
  if (message.contains("exposure")) {
    try {
      s.exposure = exposure_from_json(message["exposure"]);
    } catch (const std::invalid_argument& e) {
      throw ProtocolError("exposure", e.what());
    }
  }
  return s;
}

// nlohmann's messages start with "[json.exception.parse_error.101] "; the rest is the reason.
std::string without_exception_id(const std::string& what) {
  const auto end = what.find("] ");
  return what.starts_with("[json.exception") && end != std::string::npos ? what.substr(end + 2)
                                                                          : what;
}

}  // namespace

SceneSource OpenRequest::source() const {
  if (scene) return SceneSource::bundled(*scene);
  if (generators) return SceneSource::generator_text(*generators);
  return SceneSource::inline_document(*document);  // parse_open gives one of the three
}

ClientMessage parse_client_message(std::string_view text, const ServiceLimits& limits) {
  Json message;
  try {
    message = Json::parse(text);
  } catch (const Json::exception& e) {  // parse_error, or out_of_range for 1e400
    throw ProtocolError("", "invalid JSON: " + without_exception_id(e.what()));
  }
  if (!message.is_object()) throw ProtocolError("", "a message must be a JSON object");
  if (!message.contains("type")) throw ProtocolError("type", "missing");
  if (!message["type"].is_string()) throw ProtocolError("type", "must be a string");
  const std::string type = message["type"].get<std::string>();
  if (type == "open") return parse_open(message);
  if (type == "move") return parse_move(message);
  if (type == "settings") return parse_settings(message, limits);
  throw ProtocolError("type", "unknown message type \"" + type + "\" (open, move or settings)");
}

ProtocolError service_error(const std::exception& error, const OpenRequest* open) {
  // Split "<path>: <reason>" when the text before ": " looks like a path (no spaces).
  const std::string what = error.what();
  std::string path, reason = what;
  const auto colon = what.find(": ");
  if (colon != std::string::npos && colon > 0 && what.find(' ') > colon) {
    path = what.substr(0, colon);
    reason = what.substr(colon + 2);
  }
  if (open && open->scene) return ProtocolError("scene", path == "scene" ? reason : what);
  // Generator errors name the matrix and line in the text: keep the whole message.
  if (open && open->generators) return ProtocolError("generators", what);
  if (open) {
    if (path.empty() || path == "(root)") return ProtocolError("document", reason);
    return ProtocolError(path[0] == '[' ? "document" + path : "document." + path, reason);
  }
  return ProtocolError(path, reason);
}

std::string hello_message(uint64_t session, const std::vector<std::string>& scenes,
                          const ServiceLimits& limits, std::size_t max_message_bytes,
                          std::chrono::milliseconds idle_timeout) {
  return dump(Json{{"type", "hello"},
                   {"session", session},
                   {"scenes", scenes},
                   {"limits",
                    {{"max_message_bytes", max_message_bytes},
                     {"max_width", limits.max_width},
                     {"max_height", limits.max_height},
                     {"max_depth", limits.max_depth},
                     {"max_sessions", limits.max_sessions},
                     {"idle_timeout_seconds", idle_timeout.count() / 1000.0}}}});
}

std::string scene_message(const SceneInfo& scene) {
  return dump(Json{{"type", "scene"},
                   {"name", scene.name},
                   {"source", scene.source},
                   {"title", scene.title},
                   {"geometry", scene.geometry},
                   {"manifold", scene.manifold},
                   {"width", scene.width},
                   {"height", scene.height},
                   {"max_depth", scene.max_depth},
                   {"exposure", exposure_to_json(scene.exposure)}});
}

std::string frame_message(const FrameInfo& frame) {
  Json camera = Json::array();
  for (const auto& row : frame.camera.m)
    for (double v : row) camera.push_back(v);
  return dump(Json{{"type", "frame"},
                   {"frame", frame.frame},
                   {"spp", frame.spp},
                   {"elapsed", frame.elapsed},
                   {"error", frame.error < 0 ? Json(nullptr) : Json(frame.error)},
                   {"width", frame.width},
                   {"height", frame.height},
                   {"moving", frame.moving},
                   {"exposure", frame.exposure},
                   {"non_finite_samples", frame.non_finite_samples},
                   {"truncated_geodesics", frame.truncated_geodesics},
                   {"camera", std::move(camera)}});
}

std::string error_message(const ProtocolError& error) {
  return dump(Json{{"type", "error"}, {"field", error.field()}, {"message", error.what()}});
}

}  // namespace geodesic::net
