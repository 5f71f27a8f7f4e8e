#include "net/auth.h"

#include <algorithm>
#include <cctype>

#include <boost/asio/ip/address.hpp>

namespace geodesic::net {
namespace {

// Compares without an early exit, so the time taken does not tell how much of a guess matched.
bool same_secret(std::string_view given, std::string_view token) {
  unsigned char difference = given.size() == token.size() ? 0 : 1;
  for (size_t i = 0; i < given.size(); ++i)
    difference |= static_cast<unsigned char>(given[i] ^ token[i % token.size()]);
  return difference == 0;
}

}  // namespace

bool needs_token(std::string_view path) {
  return path.starts_with("/api/") || path == "/metrics" || path == "/ws";
}

bool authorized(const Request& request, const std::string& token) {
  if (token.empty()) return true;
  const std::string_view header(request[http::field::authorization].data(),
                                request[http::field::authorization].size());
  // The scheme is case-insensitive (RFC 7235 section 2.1): "bearer", "BEARER" and "Bearer".
  constexpr std::string_view kBearer = "bearer ";
  if (header.size() >= kBearer.size() &&
      std::equal(kBearer.begin(), kBearer.end(), header.begin(), [](char a, char b) {
        return a == std::tolower(static_cast<unsigned char>(b));
      }))
    return same_secret(header.substr(kBearer.size()), token);
  const std::string_view target(request.target().data(), request.target().size());
  const std::string_view given = query_parameter(target, "token");
  return !given.empty() && same_secret(given, token);
}

std::string usable_token(const std::string& token) {
  if (token.empty()) return "";
  for (char c : token)
    if (std::isspace(static_cast<unsigned char>(c)) || !std::isprint(static_cast<unsigned char>(c)))
      return "must be printable characters without spaces";
  if (token.size() < 8) return "must be at least 8 characters";
  return "";
}

bool is_loopback(const std::string& host) {
  if (host == "localhost") return true;
  boost::system::error_code ec;
  const auto address = boost::asio::ip::make_address(host, ec);
  return !ec && address.is_loopback();
}

}  // namespace geodesic::net
