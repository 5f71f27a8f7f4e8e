// Clients that break the rules on purpose, over raw TCP: huge bodies, WebSocket frames cut
// short, connections that trickle headers, targets that reach outside web/. Each must cost the
// daemon one connection at most: it answers or drops that one, and serves everyone else.
#include <gtest/gtest.h>

#include <cerrno>
#include <memory>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include <filesystem>

#include <netinet/in.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <unistd.h>

#include "daemon_fixture.h"

namespace geodesic::test {
namespace {

using nlohmann::json;

// A blocking POSIX socket with 5 s send and receive timeouts (Asio's blocking calls would wait
// past SO_RCVTIMEO).
class RawConnection {
 public:
  explicit RawConnection(uint16_t port) : fd_(::socket(AF_INET, SOCK_STREAM, 0)) {
    const timeval timeout{5, 0};
    ::setsockopt(fd_, SOL_SOCKET, SO_RCVTIMEO, &timeout, sizeof timeout);
    ::setsockopt(fd_, SOL_SOCKET, SO_SNDTIMEO, &timeout, sizeof timeout);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(port);
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (::connect(fd_, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0)
      throw std::runtime_error("connect failed");
  }
  ~RawConnection() { close(); }
  RawConnection(const RawConnection&) = delete;
  RawConnection& operator=(const RawConnection&) = delete;

  // False once the server no longer takes bytes.
  bool write(std::string_view bytes) {
    while (!bytes.empty()) {
      const ssize_t n = ::send(fd_, bytes.data(), bytes.size(), MSG_NOSIGNAL);
      if (n <= 0) return false;
      bytes.remove_prefix(size_t(n));
    }
    return true;
  }
  void set_receive_timeout(int seconds) {
    const timeval timeout{seconds, 0};
    ::setsockopt(fd_, SOL_SOCKET, SO_RCVTIMEO, &timeout, sizeof timeout);
  }
  // What has arrived, without waiting.
  std::string available() {
    std::string data;
    char chunk[4096];
    for (ssize_t n; (n = ::recv(fd_, chunk, sizeof chunk, MSG_DONTWAIT)) > 0;) data.append(chunk, n);
    return data;
  }
  // Reads until `end` has arrived, the server closes, or the receive timeout.
  RawReply read_until(std::string_view end = {}) {
    RawReply reply;
    char chunk[4096];
    while (end.empty() || reply.data.find(end) == std::string::npos) {
      const ssize_t n = ::recv(fd_, chunk, sizeof chunk, 0);
      if (n > 0) {
        reply.data.append(chunk, n);
        continue;
      }
      reply.closed = n == 0 || errno == ECONNRESET;
      break;
    }
    return reply;
  }
  // The WebSocket opening handshake at /ws.
  void upgrade() {
    ASSERT_TRUE(write("GET /ws HTTP/1.1\r\nHost: x\r\nConnection: Upgrade\r\n"
                      "Upgrade: websocket\r\nSec-WebSocket-Version: 13\r\n"
                      "Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\n\r\n"));
    const RawReply reply = read_until("\r\n\r\n");
    ASSERT_TRUE(reply.data.starts_with("HTTP/1.1 101")) << reply.data;
  }
  void close() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
  }

 private:
  int fd_;
};

void expect_healthy(uint16_t port, int sessions) {
  const auto health = http_get(port, "/healthz");
  EXPECT_EQ(health.result(), http::status::ok);
  EXPECT_EQ(json::parse(health.body())["sessions"], sessions);
}

// 100 MiB offered, with a length and chunked: the daemon stops reading past its 1 MiB limit.
TEST(HostileClients, HundredMegabyteBodyIsRefusedAndTheDaemonServesOn) {
  Daemon daemon;
  constexpr size_t kOffered = 100 << 20;
  const std::string block(1 << 20, 'x');
  {
    RawConnection c(daemon.port());
    ASSERT_TRUE(c.write("POST /healthz HTTP/1.1\r\nHost: x\r\nContent-Length: " +
                        std::to_string(kOffered) + "\r\n\r\n"));
    EXPECT_TRUE(c.read_until("\r\n\r\n").data.starts_with("HTTP/1.1 413"));
    size_t sent = 0;
    while (sent < kOffered && c.write(block)) sent += block.size();
    EXPECT_LT(sent, kOffered);
  }
  {
    RawConnection c(daemon.port());
    ASSERT_TRUE(c.write("POST /healthz HTTP/1.1\r\nHost: x\r\nTransfer-Encoding: chunked\r\n\r\n"));
    const std::string chunk = "100000\r\n" + block + "\r\n";  // 1 MiB
    size_t sent = 0;
    std::string reply;
    while (sent < kOffered && c.write(chunk)) {
      sent += block.size();
      reply += c.available();
    }
    EXPECT_LT(sent, kOffered);
    // The answer may be lost to the reset that the unread body causes; if it came, it is 413.
    if (!reply.empty()) EXPECT_TRUE(reply.starts_with("HTTP/1.1 413")) << reply.substr(0, 80);
  }
  expect_healthy(daemon.port(), 0);
}

// Frame headers cut short, then the connection closed; one left stalled; one announcing 2^62
// bytes. Each ends only its own session, and a normal client streams meanwhile.
TEST(HostileClients, TruncatedWebSocketFramesEndOnlyTheirSession) {
  Daemon daemon;
  RawConnection stalled(daemon.port());
  stalled.upgrade();
  ASSERT_TRUE(stalled.write("\x81\xfe"));  // a text frame whose 16-bit length never comes
  for (const std::string partial :
       {std::string("\x81"), std::string("\x81\xfe\x00", 3), std::string("\x82\xff\x00\x00", 4),
        std::string("\x81\x85\x01\x02"), std::string("\x81\x85\x01\x02\x03\x04hel")}) {
    RawConnection c(daemon.port());
    c.upgrade();
    ASSERT_TRUE(c.write(partial));
  }
  {
    RawConnection c(daemon.port());
    c.upgrade();
    ASSERT_TRUE(c.write(std::string("\x81\xff\x40\x00\x00\x00\x00\x00\x00\x00\x01\x02\x03\x04", 14)));
    // Its session reads once its first scene is prepared, after the six connections before it
    // (seconds in the sanitizer build): the close may come that late, but it must come.
    c.set_receive_timeout(60);
    const RawReply reply = c.read_until();
    EXPECT_TRUE(reply.closed);
    EXPECT_TRUE(reply.data.ends_with("\x88\x02\x03\xf1"));  // close 1009, message too big
  }
  WsClient client(daemon.port());
  EXPECT_EQ(client.read_until("hello")["type"], "hello");
  EXPECT_GT(client.read_frame().jpeg.size(), 0u);
  // The truncated sessions are gone; the stalled one and the client remain.
  for (int attempt = 0; attempt < 50; ++attempt) {
    if (json::parse(http_get(daemon.port(), "/healthz").body())["sessions"] == 2) break;
    std::this_thread::sleep_for(100ms);
  }
  expect_healthy(daemon.port(), 2);
}

// Slowloris: connections that trickle a header one byte at a time are cut at the HTTP timeout
// without an answer, and a normal request is served while they trickle.
TEST(HostileClients, TricklingConnectionsAreCutAndOthersServed) {
  DaemonOptions options;
  options.http_timeout = 2s;
  Daemon daemon(options);
  std::vector<std::unique_ptr<RawConnection>> trickling;
  for (int i = 0; i < 32; ++i) {
    trickling.push_back(std::make_unique<RawConnection>(daemon.port()));
    ASSERT_TRUE(trickling.back()->write("GET / HTTP/1.1\r\nX-Slow: "));
  }
  for (int round = 0; round < 16; ++round) {  // 4 s: twice the timeout
    for (auto& c : trickling) c->write("a");
    if (round == 2) expect_healthy(daemon.port(), 0);
    std::this_thread::sleep_for(250ms);
  }
  for (auto& c : trickling) {
    const RawReply reply = c->read_until();
    EXPECT_TRUE(reply.closed);
    EXPECT_TRUE(reply.data.empty()) << reply.data;
  }
  expect_healthy(daemon.port(), 0);
}

// Absolute paths, absolute-form targets and NUL bytes, raw or encoded: 400 or 404, never a file
// from outside web/ (the daemon's temporary directory holds kSecret next to it).
TEST(HostileClients, TargetsOutsideTheWebDirectoryAreRefused) {
  Daemon daemon;
  for (const char* target : {"//CMakeLists.txt", "/%2fCMakeLists.txt", "/%2e%2e%2fCMakeLists.txt",
                             "/sub/..%2f..%2fCMakeLists.txt", "/index.html%00.js", "/%00",
                             "http://x/../CMakeLists.txt", "/%2e%2e/%2e%2e/etc/passwd"}) {
    const auto response = http_get(daemon.port(), target);
    EXPECT_EQ(response.result(), http::status::not_found) << target;
    EXPECT_EQ(response.body().find(Daemon::kSecret), std::string::npos) << target;
  }
  for (const std::string target :
       {std::string("/index.html\0.js", 15), std::string("/../CMakeLists.txt\0", 19)}) {
    const RawReply reply =
        raw_exchange(daemon.port(), "GET " + target + " HTTP/1.1\r\nHost: x\r\n\r\n", 5s);
    EXPECT_TRUE(reply.data.starts_with("HTTP/1.1 400")) << reply.data;
    EXPECT_EQ(reply.data.find(Daemon::kSecret), std::string::npos);
    EXPECT_TRUE(reply.closed);
  }
  expect_healthy(daemon.port(), 0);
}

// Out of file descriptors, accept() fails at once for as long as a connection waits in the
// backlog: the listener waits 50 ms between tries instead of spinning (37 % of a core before),
// and serves again once descriptors are free. The daemon runs in this process, so the
// descriptor limit is this process's, lowered to 16 above those open.
TEST(HostileClients, OutOfFileDescriptorsTheListenerBacksOffAndServesAgain) {
#ifdef GEODESIC_SANITIZED
  // The daemon runs in this process, which the test leaves without a free descriptor; UBSan's
  // vptr check opens /proc/self/maps on a type-cache miss and then reports a false "invalid
  // vptr" (samangh/libsg#40 describes the same). The plain build runs it.
  GTEST_SKIP() << "needs a process without free descriptors, which UBSan's vptr check cannot run in";
#endif
  Daemon daemon;
  expect_healthy(daemon.port(), 0);
  rlimit limit{};
  ASSERT_EQ(getrlimit(RLIMIT_NOFILE, &limit), 0);
  const rlimit restore = limit;
  int open_now = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator("/proc/self/fd"))
    ++open_now;
  limit.rlim_cur = rlim_t(open_now + 16);
  ASSERT_EQ(setrlimit(RLIMIT_NOFILE, &limit), 0);
  // Connections until this side has no descriptor left: the daemon has accepted what its share
  // allowed, and the last ones wait in the backlog.
  std::vector<std::unique_ptr<RawConnection>> clients;
  try {
    while (clients.size() < 64) clients.push_back(std::make_unique<RawConnection>(daemon.port()));
  } catch (const std::runtime_error&) {
  }
  rusage before{}, after{};
  getrusage(RUSAGE_SELF, &before);
  std::this_thread::sleep_for(1s);
  getrusage(RUSAGE_SELF, &after);
  auto seconds = [](const timeval& t) { return double(t.tv_sec) + t.tv_usec * 1e-6; };
  const double cpu = seconds(after.ru_utime) - seconds(before.ru_utime) + seconds(after.ru_stime) -
                     seconds(before.ru_stime);
  const size_t connections = clients.size();
  clients.clear();
  ASSERT_EQ(setrlimit(RLIMIT_NOFILE, &restore), 0);
  std::printf("out of descriptors with %zu connections: %.0f ms of CPU in 1 s\n", connections,
              cpu * 1000);
  EXPECT_LT(cpu, 0.1) << "the listener spins";
  for (int attempt = 0; attempt < 50; ++attempt) {  // the backlog drains as the clients close
    if (json::parse(http_get(daemon.port(), "/healthz").body())["sessions"] == 0) break;
    std::this_thread::sleep_for(100ms);
  }
  expect_healthy(daemon.port(), 0);
}

}  // namespace
}  // namespace geodesic::test
