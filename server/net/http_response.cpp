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
  return make_response(request, status, "application/json", body.dump());
}

Response json_error(const Request& request, http::status status, std::string_view message) {
  return json_response(request, {{"error", message}}, status);
}

Response method_not_allowed(const Request& request, std::string_view allow) {
  Response response = json_error(request, http::status::method_not_allowed,
                                 "method: only " + std::string(allow));
  response.set(http::field::allow, beast::string_view(allow.data(), allow.size()));
  return response;
}

}  // namespace geodesic::net
