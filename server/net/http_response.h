// Building HTTP answers: every response of the daemon goes through these, so they share the
// Server header, keep-alive handling and content length.
#pragma once

#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "net/beast.h"

namespace geodesic::net {

using Request = http::request<http::string_body>;
using Response = http::response<http::string_body>;

Response make_response(const Request& request, http::status status, std::string_view mime,
                       std::string body);
Response json_response(const Request& request, const nlohmann::ordered_json& body,
                       http::status status = http::status::ok);
// {"error": "<field>: <reason>"}: API errors name the field at fault ("" for none).
// The value of `name` in the target's query string, undecoded; empty when absent.
std::string_view query_parameter(std::string_view target, std::string_view name);

Response json_error(const Request& request, http::status status, std::string_view message);
// A method the path does not answer: 405 with the Allow header.
Response method_not_allowed(const Request& request, std::string_view allow);

}  // namespace geodesic::net
