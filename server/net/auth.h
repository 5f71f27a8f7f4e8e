// Optional bearer-token auth (`geodesic serve --token`, or GEODESIC_TOKEN): when a token is set,
// the API (/api/...), /metrics and the WebSocket need it; /healthz and the web client's files
// stay open (a health check and the page that asks for the token need none).
#pragma once

#include <string>
#include <string_view>

#include "net/http_response.h"

namespace geodesic::net {

// Whether `path` needs the token when one is set.
bool needs_token(std::string_view path);

// True when no token is set, or the request carries it: "Authorization: Bearer <token>", or a
// `token` query parameter (browsers cannot set headers on a WebSocket). Constant-time compare.
bool authorized(const Request& request, const std::string& token);

// "" when `token` may be used (or is empty: no auth), else why not: a token of blanks or control
// characters, or shorter than 8 characters, would be guessed or mistyped into the open.
std::string usable_token(const std::string& token);

// True for 127.0.0.0/8, ::1 and "localhost": the addresses that may serve without a token.
bool is_loopback(const std::string& host);

}  // namespace geodesic::net
