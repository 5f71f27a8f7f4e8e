#include "net/http_response.h"

#include <utility>

namespace geodesic::net {

Response make_response(const Request& request, http::status status, std::string_view mime,
                       std::string body) {
  Response response(status, request.version());
  response.set(http::field::server, "geodesic");
  response.set(http::field::content_type, beast::string_view(mime.data(), mime.size()));
  response.keep_alive(request.keep_alive());
  response.body() = std::move(body);
  response.prepare_payload();
  return response;
}

Response json_response(const Request& request, const nlohmann::ordered_json& body,
                       http::status status) {
  // Replaced, not thrown on: an error may quote a client's bytes that are not UTF-8.
  return make_response(request, status, "application/json",
                       body.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace));
}

Response json_error(const Request& request, http::status status, std::string_view message) {
  return json_response(request, {{"error", message}}, status);
}

// The value of `name` in the target's query string, undecoded (tokens are URL-safe).
std::string_view query_parameter(std::string_view target, std::string_view name) {
  const size_t query = target.find('?');
  if (query == std::string_view::npos) return {};
  std::string_view rest = target.substr(query + 1);
  while (!rest.empty()) {
    const size_t end = rest.find('&');
    const std::string_view pair = rest.substr(0, end);
    if (pair.size() > name.size() && pair.starts_with(name) && pair[name.size()] == '=')
      return pair.substr(name.size() + 1);
    if (end == std::string_view::npos) break;
    rest = rest.substr(end + 1);
  }
  return {};
}

Response method_not_allowed(const Request& request, std::string_view allow) {
  Response response = json_error(request, http::status::method_not_allowed,
                                 "method: only " + std::string(allow));
  response.set(http::field::allow, beast::string_view(allow.data(), allow.size()));
  return response;
}

}  // namespace geodesic::net
