#include "net/auth.h"

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

}  // namespace

bool needs_token(std::string_view path) {
  return path.starts_with("/api/") || path == "/metrics" || path == "/ws";
}

bool authorized(const Request& request, const std::string& token) {
  if (token.empty()) return true;
  const std::string_view header(request[http::field::authorization].data(),
                                request[http::field::authorization].size());
  constexpr std::string_view kBearer = "Bearer ";
  if (header.starts_with(kBearer)) return same_secret(header.substr(kBearer.size()), token);
  const std::string_view target(request.target().data(), request.target().size());
  const std::string_view given = query_parameter(target, "token");
  return !given.empty() && same_secret(given, token);
}

bool is_loopback(const std::string& host) {
  if (host == "localhost") return true;
  boost::system::error_code ec;
  const auto address = boost::asio::ip::make_address(host, ec);
  return !ec && address.is_loopback();
}

}  // namespace geodesic::net
