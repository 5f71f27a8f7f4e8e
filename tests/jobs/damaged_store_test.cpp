// What the daemon stores, damaged: rows of jobs.sqlite3 and checkpoint files corrupted at random
// (a seeded loop of 300 cases) are read without a crash, a damaged row reads as a failed job
// naming the damage while the others stay listed, and a checkpoint is only ever read back into
// the job whose fingerprint it carries. Then the same through a real daemon: a row whose request
// is `{}` answers as a failed job, and a fresh store beside an old job's directory numbers its
// jobs past it (a stale checkpoint is never resumed into a new job).
#include <cstdio>
#include <fstream>
#include <iterator>
#include <random>
#include <sstream>

#include <gtest/gtest.h>
#include <sqlite3.h>

#include "job_daemon.h"
#include "jobs/checkpoint.h"
#include "jobs/job_store.h"

namespace geodesic::test {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

const json kRequest = {{"scene", "furnace"}, {"width", 16}, {"height", 16}, {"spp", 8},
                       {"formats", {"png"}}};

// Runs `sql` with one bound text on the database file (a second connection, as an operator's
// sqlite3 shell would be).
void poke(const fs::path& db_file, const std::string& sql, const std::string& value) {
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(db_file.c_str(), &db), SQLITE_OK);
  sqlite3_stmt* stmt = nullptr;
  ASSERT_EQ(sqlite3_prepare_v2(db, sql.c_str(), -1, &stmt, nullptr), SQLITE_OK) << sql;
  sqlite3_bind_text(stmt, 1, value.data(), int(value.size()), SQLITE_TRANSIENT);
  EXPECT_EQ(sqlite3_step(stmt), SQLITE_DONE) << sql;
  sqlite3_finalize(stmt);
  sqlite3_close(db);
}

// A damaging value for a column: random bytes, JSON of the wrong shape, or a wrong type.
std::string damage(std::mt19937& random) {
  static const char* kShapes[] = {"{}", "[]", "null", "{\"scene\": 3}", "{\"width\": -1}",
                                  "[{\"seconds\": \"x\"}]", "[1, 2]", "exploded", "",
                                  "{\"scene\": \"furnace\", \"width\": 4, \"height\": 2, "
                                  "\"formats\": [\"gif\"]}", "1e400", "\"running\""};
  const int kind = int(random() % 3);
  if (kind == 0) return kShapes[random() % std::size(kShapes)];
  std::string bytes(random() % 40, '\0');
  for (char& c : bytes) c = char(random() % 256);
  if (kind == 1) return bytes;
  return json{{"scene", bytes.substr(0, 3)}, {"width", int(random() % 7) - 2}}.dump(
      -1, ' ', false, json::error_handler_t::replace);
}

TEST(DamagedStore, RandomlyDamagedRowsReadAsFailedJobsAndTheRestStayListed) {
  std::mt19937 random(20261123);
  const char* kColumns[] = {"state", "request", "series", "created", "message", "samples",
                            "elapsed", "progress", "non_finite_samples", "truncated_geodesics"};
  for (int round = 0; round < 200; ++round) {
    TempDir dir;
    const fs::path file = dir.path() / "jobs.sqlite3";
    jobs::JobStore store(file);
    for (int i = 0; i < 4; ++i) store.insert(kRequest);
    const int64_t victim = 1 + int64_t(random() % 4);
    const std::string column = kColumns[random() % std::size(kColumns)];
    const std::string value = damage(random);
    poke(file, "UPDATE jobs SET " + column + " = ? WHERE id = " + std::to_string(victim), value);

    std::vector<jobs::JobRecord> listed;
    ASSERT_NO_THROW(listed = store.list()) << column << " = " << value;
    ASSERT_EQ(listed.size(), 4u) << column << " = " << value;
    for (const jobs::JobRecord& job : listed) {
      const json status = job.status_json(true);  // must not crash on any request
      EXPECT_EQ(status["id"], job.id);
      if (job.id != victim) EXPECT_EQ(job.state, jobs::JobState::Queued);
      if (job.state == jobs::JobState::Failed) {
        EXPECT_TRUE(job.message.starts_with("stored record damaged: ")) << job.message;
        EXPECT_EQ(job.id, victim);
      }
    }
    ASSERT_TRUE(store.get(victim).has_value());
  }
}

// A store written by a daemon before the counters existed (no non_finite_samples or
// truncated_geodesics columns) opens with its jobs intact, counted zero, and keeps new counts.
TEST(DamagedStore, AStoreFromBeforeTheCountersGainsThemAndKeepsItsJobs) {
  TempDir dir;
  const fs::path file = dir.path() / "jobs.sqlite3";
  poke(file,
       "CREATE TABLE jobs (id INTEGER PRIMARY KEY AUTOINCREMENT, state TEXT NOT NULL, request TEXT "
       "NOT NULL, created TEXT NOT NULL, samples INTEGER NOT NULL DEFAULT 0, elapsed REAL NOT NULL "
       "DEFAULT 0, error REAL NOT NULL DEFAULT -1, progress REAL NOT NULL DEFAULT 0, "
       "checkpoint_samples INTEGER NOT NULL DEFAULT 0, message TEXT NOT NULL DEFAULT '', series "
       "TEXT NOT NULL DEFAULT '[]')",
       "");
  poke(file, "INSERT INTO jobs (state, request, created, samples) VALUES ('done', ?, 'then', 8)",
       kRequest.dump());
  jobs::JobStore store(file);
  std::optional<jobs::JobRecord> old = store.get(1);
  ASSERT_TRUE(old.has_value());
  EXPECT_EQ(old->state, jobs::JobState::Done);
  EXPECT_EQ(old->samples, 8u);
  EXPECT_EQ(old->non_finite_samples, 0u);
  old->non_finite_samples = 3;
  old->truncated_geodesics = uint64_t(1) << 40;
  store.update(*old);
  const json status = store.get(1)->status_json(false);
  EXPECT_EQ(status["non_finite_samples"], 3);
  EXPECT_EQ(status["truncated_geodesics"], uint64_t(1) << 40);
  EXPECT_EQ(store.insert(kRequest), 2);
  jobs::JobStore again(file);  // opening once more changes nothing
  EXPECT_EQ(again.list().size(), 2u);
}

TEST(DamagedStore, RandomlyDamagedCheckpointsNeverResumeIntoAnotherJob) {
  std::mt19937 random(1123);
  const uint64_t mine = jobs::checkpoint_fingerprint(kRequest.dump(), 16, 16, 1);
  const uint64_t other = jobs::checkpoint_fingerprint(kRequest.dump(), 16, 16, 2);
  ASSERT_NE(mine, other);
  std::vector<float> sums(2 * 16 * 16 * 4);
  for (std::size_t i = 0; i < sums.size(); ++i) sums[i] = float(i);
  int refused = 0, read_back = 0;
  for (int round = 0; round < 200; ++round) {
    TempDir dir;
    const fs::path file = dir.path() / "checkpoint.bin";
    jobs::write_checkpoint(file, mine, 8, 1.5, 16, 16, sums);
    std::string bytes;
    {
      std::ifstream in(file, std::ios::binary);
      bytes.assign(std::istreambuf_iterator<char>(in), {});
    }
    switch (random() % 3) {
      case 0: bytes[random() % bytes.size()] ^= char(1 + random() % 255); break;  // one byte
      case 1: bytes.resize(random() % bytes.size()); break;                       // truncated
      default: bytes += std::string(1 + random() % 64, char(random() % 256));     // extended
    }
    std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
    EXPECT_THROW(jobs::read_checkpoint(file, other), jobs::CheckpointError);
    try {
      const auto checkpoint = jobs::read_checkpoint(file, mine);
      ASSERT_TRUE(checkpoint.has_value());
      EXPECT_EQ(checkpoint->width, 16);  // a flipped bit in the sums or the sample count only
      EXPECT_EQ(checkpoint->height, 16);
      ++read_back;
    } catch (const jobs::CheckpointError& e) {
      EXPECT_TRUE(std::string(e.what()).starts_with("checkpoint: ")) << e.what();
      ++refused;
    }
  }
  EXPECT_GT(refused, 50);
  std::printf("damaged checkpoints: %d refused, %d read back (bits flipped in their body)\n",
              refused, read_back);
}

TEST(DamagedStore, ADaemonAnswersADamagedRowAsAFailedJob) {
  TempDir data;
  const fs::path dir = data.path() / "data";
  {
    DaemonProcess daemon(dir);
    const JobsApi api(daemon.port());
    for (int i = 0; i < 3; ++i) api.wait_for(api.submit(kRequest), job_ended);
  }
  poke(dir / "jobs.sqlite3", "UPDATE jobs SET request = ? WHERE id = 2", "{}");
  poke(dir / "jobs.sqlite3", "UPDATE jobs SET state = ? WHERE id = 3", "exploded");
  DaemonProcess daemon(dir);
  const JobsApi api(daemon.port());
  const ApiReply two = api.get("/api/jobs/2");
  EXPECT_EQ(two.status, 200u) << two.body;
  EXPECT_EQ(two.json["state"], "failed");
  EXPECT_TRUE(two.json["message"].get<std::string>().starts_with("stored record damaged: request"))
      << two.body;
  const ApiReply list = api.get("/api/jobs");
  ASSERT_EQ(list.status, 200u) << list.body;
  ASSERT_EQ(list.json["jobs"].size(), 3u);
  EXPECT_EQ(list.json["jobs"][0]["state"], "done");
  EXPECT_EQ(list.json["jobs"][2]["state"], "failed");
  EXPECT_EQ(api.get("/api/jobs/2/result.png").status, 404u);
  EXPECT_EQ(daemon.kill(SIGTERM), 0);
}

TEST(DamagedStore, AFreshStoreNumbersJobsPastTheDirectoriesLeftBehind) {
  TempDir data;
  const fs::path dir = data.path() / "data";
  int64_t old_id = 0;
  {
    DaemonProcess daemon(dir, {"--checkpoint-seconds", "1"});
    const JobsApi api(daemon.port());
    old_id = api.submit({{"scene", "furnace"}, {"width", 64}, {"height", 48}, {"spp", 1 << 20},
                         {"formats", {"png"}}});
    api.wait_for(old_id, [](const json& s) { return s["checkpoint_samples"].get<int>() > 0; });
  }  // SIGTERM: the job stays running, its checkpoint on disk
  ASSERT_TRUE(fs::exists(dir / "jobs" / std::to_string(old_id) / "checkpoint.bin"));
  fs::remove(dir / "jobs.sqlite3");  // a fresh (or restored) store beside the old files
  fs::remove(dir / "jobs.sqlite3-wal");
  fs::remove(dir / "jobs.sqlite3-shm");
  DaemonProcess daemon(dir);
  const JobsApi api(daemon.port());
  const int64_t id = api.submit(kRequest);
  EXPECT_GT(id, old_id);
  const json done = api.wait_for(id, job_ended);
  EXPECT_EQ(done["state"], "done");
  EXPECT_EQ(done["samples"], 8);  // its own 8 samples, nothing resumed
}

}  // namespace
}  // namespace geodesic::test
