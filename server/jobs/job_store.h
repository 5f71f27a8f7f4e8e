// The job table, in SQLite (WAL journal, synchronous commits): a job is stored before its
// 202 goes out, and every state change and checkpoint is one transaction, so a daemon killed at
// any moment finds every accepted job again. Thread-safe.
#pragma once

#include <cstdint>
#include <filesystem>
#include <mutex>
#include <optional>
#include <vector>

#include "jobs/job.h"

struct sqlite3;

namespace geodesic::jobs {

class JobStore {
 public:
  // Opens (creating) the database file; throws std::runtime_error.
  explicit JobStore(const std::filesystem::path& file);
  ~JobStore();
  JobStore(const JobStore&) = delete;
  JobStore& operator=(const JobStore&) = delete;

  // A new queued job with the canonical request; its id.
  int64_t insert(const nlohmann::ordered_json& request);
  std::optional<JobRecord> get(int64_t id) const;
  // Every job in id order; `unfinished_only`: queued and running ones (what a start resumes).
  std::vector<JobRecord> list(bool unfinished_only = false) const;
  // At most `limit` jobs (0: all) with ids above `after`, in id order.
  std::vector<JobRecord> page(int64_t after, int limit) const;
  // Ids of finished jobs, newest first.
  std::vector<int64_t> finished_ids() const;
  void remove(int64_t id);

  // New ids start above `id` (a fresh or restored store beside job directories of a previous
  // one: ids are never reused, so no job meets another's files).
  void reserve_ids_above(int64_t id);

  // Saves state, progress, series, checkpoint and message of `job` (request and created stay).
  void update(const JobRecord& job);

 private:
  sqlite3* db_ = nullptr;
  mutable std::mutex mutex_;
};

}  // namespace geodesic::jobs
