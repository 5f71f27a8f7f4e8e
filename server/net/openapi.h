// The daemon's OpenAPI document, proto/openapi.json compiled in at build time (one source:
// the file CI validates is the one served at /api/openapi.json).
#pragma once

#include <string_view>

namespace geodesic::net {

std::string_view openapi_document();

}  // namespace geodesic::net
