// Vulkan faults under WebSocket sessions, injected (GEODESIC_FAULT: lavapipe cannot lose its
// device or run out of device memory for real): three sessions render, one queue submission
// fails as a driver would report it; the session it was for gets an `error` naming the Vulkan
// error and the close 1011, the other two keep getting frames (followed for 3 s after the
// failure), a new session renders, and the daemon stays up. After a device loss that means a
// new device under the surviving sessions.
#include <algorithm>
#include <atomic>
#include <memory>
#include <thread>

#include <gtest/gtest.h>

#include "job_daemon.h"

namespace geodesic::test {
namespace {

using nlohmann::json;
using Clock = std::chrono::steady_clock;

struct SessionEnd {
  std::string error;  // the `error` message's text, if one came
  Clock::time_point error_at;
  uint16_t close_code = 0;
  std::string close_failure;  // why no close code came, if none did
  std::vector<Clock::time_point> frames;
};

// How long the other sessions are followed after the failure, and how many frames each must
// get in that time (about 8 a second each when they share the device three ways).
constexpr auto kWatchAfterFailure = 3s;
constexpr int kFramesAfterFailure = 3;

// When the first session's `error` came, as steady-clock ticks; 0 until then.
using FailureTime = std::atomic<Clock::rep>;

int64_t frames_after(const SessionEnd& end, Clock::time_point failure) {
  return std::count_if(end.frames.begin(), end.frames.end(), [&](auto t) { return t > failure; });
}

// Reads one session's messages until its close, the deadline, or (for a session that did not
// fail) kWatchAfterFailure past another session's failure with kFramesAfterFailure frames in it.
void follow(WsClient& ws, Clock::time_point deadline, FailureTime& failure, SessionEnd& end) {
  try {
    while (Clock::now() < deadline) {
      const WsClient::Message message =
          ws.read(std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()));
      if (message.binary) {
        end.frames.push_back(Clock::now());
        const Clock::rep failed_at = failure.load();
        if (failed_at != 0) {
          const Clock::time_point at{Clock::duration(failed_at)};
          if (Clock::now() - at > kWatchAfterFailure &&
              frames_after(end, at) >= kFramesAfterFailure)
            return;
        }
      } else if (message.json["type"] == "error") {
        end.error = message.json["message"];
        end.error_at = Clock::now();
        Clock::rep expected = 0;
        failure.compare_exchange_strong(expected, end.error_at.time_since_epoch().count());
        try {
          end.close_code = ws.read_until_close();
        } catch (const std::exception& e) {
          end.close_failure = e.what();
        }
        return;
      }
    }
  } catch (const std::exception&) {  // the deadline
  }
}

void one_session_fails(const std::string& fault, const std::string& vulkan_error) {
  TempDir data;
  // Three sessions at 64x48 submit about 25 times a second: the 300th submission comes seconds
  // after all three are rendering.
  DaemonProcess daemon(data.path() / "data", {}, {"GEODESIC_FAULT=" + fault + "@300"});
  std::vector<std::unique_ptr<WsClient>> sessions;
  for (int i = 0; i < 3; ++i) {
    sessions.push_back(std::make_unique<WsClient>(daemon.port()));
    sessions.back()->send({{"type", "settings"}, {"width", 64}, {"height", 48}});
    sessions.back()->read_frame(60s);
  }
  std::vector<SessionEnd> ends(sessions.size());
  std::vector<std::thread> threads;
  FailureTime failure{0};
  const auto deadline = Clock::now() + 45s;
  for (size_t i = 0; i < sessions.size(); ++i)
    threads.emplace_back([&, i] { follow(*sessions[i], deadline, failure, ends[i]); });
  for (auto& thread : threads) thread.join();

  int failed = 0;
  Clock::time_point failure_seen;
  for (const SessionEnd& end : ends)
    if (!end.error.empty()) {
      ++failed;
      EXPECT_NE(end.error.find(vulkan_error), std::string::npos) << end.error;
      EXPECT_EQ(end.close_code, 1011) << end.close_failure << "\n" << daemon.log();
      failure_seen = end.error_at;
    }
  ASSERT_EQ(failed, 1) << daemon.log();
  for (const SessionEnd& end : ends)
    if (end.error.empty())  // went on rendering after the failure
      EXPECT_GE(frames_after(end, failure_seen), kFramesAfterFailure) << daemon.log();

  // The failed client reconnects and renders again.
  WsClient again(daemon.port());
  again.send({{"type", "settings"}, {"width", 64}, {"height", 48}});
  // Frames of the default size may come before the settings take effect.
  const auto give_up = Clock::now() + 60s;
  int width = 0;
  while (width != 64 && Clock::now() < give_up) width = again.read_frame(60s).info["width"];
  EXPECT_EQ(width, 64);
  EXPECT_EQ(http_get(daemon.port(), "/healthz").result_int(), 200u);
}

TEST(DeviceFaults, DeviceLostClosesOneSessionTheOthersGoOnOnANewDevice) {
  one_session_fails("device-lost", "VK_ERROR_DEVICE_LOST");
}

TEST(DeviceFaults, OutOfDeviceMemoryClosesOneSessionTheOthersGoOn) {
  one_session_fails("oom", "VK_ERROR_OUT_OF_DEVICE_MEMORY");
}

}  // namespace
}  // namespace geodesic::test
