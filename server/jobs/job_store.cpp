#include "jobs/job_store.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <cstdint>
#include <ctime>
#include <stdexcept>
#include <string>

#include <sqlite3.h>

namespace geodesic::jobs {
namespace {

using Json = nlohmann::ordered_json;

constexpr const char* kSchema = R"sql(
CREATE TABLE IF NOT EXISTS jobs (
  id INTEGER PRIMARY KEY AUTOINCREMENT,  -- never reused, even after a delete
  state TEXT NOT NULL,
  request TEXT NOT NULL,                 -- JobRequest::to_json()
  created TEXT NOT NULL,
  samples INTEGER NOT NULL DEFAULT 0,
  elapsed REAL NOT NULL DEFAULT 0,
  error REAL NOT NULL DEFAULT -1,
  progress REAL NOT NULL DEFAULT 0,
  checkpoint_samples INTEGER NOT NULL DEFAULT 0,
  message TEXT NOT NULL DEFAULT '',
  series TEXT NOT NULL DEFAULT '[]',
  non_finite_samples INTEGER NOT NULL DEFAULT 0,  -- samples dropped as NaN/Inf
  truncated_geodesics INTEGER NOT NULL DEFAULT 0  -- cut off at max_crossings
);
)sql";

// Columns added since the first schema, for a store an earlier daemon created.
constexpr const char* kAddedColumns[] = {
    "non_finite_samples INTEGER NOT NULL DEFAULT 0",
    "truncated_geodesics INTEGER NOT NULL DEFAULT 0",
};

constexpr const char* kColumns =
    "id, state, request, created, samples, elapsed, error, progress, checkpoint_samples, "
    "message, series, non_finite_samples, truncated_geodesics";

// One prepared statement, finalized on every path.
class Statement {
 public:
  Statement(sqlite3* db, const std::string& sql) : db_(db) {
    if (sqlite3_prepare_v2(db, sql.c_str(), -1, &stmt_, nullptr) != SQLITE_OK)
      throw std::runtime_error(std::string("job store: ") + sqlite3_errmsg(db));
  }
  ~Statement() { sqlite3_finalize(stmt_); }
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;

  Statement& bind(int i, const std::string& text) {
    sqlite3_bind_text(stmt_, i, text.c_str(), int(text.size()), SQLITE_TRANSIENT);
    return *this;
  }
  Statement& bind(int i, int64_t v) {
    sqlite3_bind_int64(stmt_, i, v);
    return *this;
  }
  Statement& bind(int i, double v) {
    sqlite3_bind_double(stmt_, i, v);
    return *this;
  }
  // True while there is a row to read.
  bool step() {
    const int rc = sqlite3_step(stmt_);
    if (rc == SQLITE_ROW) return true;
    if (rc == SQLITE_DONE) return false;
    throw std::runtime_error(std::string("job store: ") + sqlite3_errmsg(db_));
  }
  int64_t integer(int i) const { return sqlite3_column_int64(stmt_, i); }
  double real(int i) const { return sqlite3_column_double(stmt_, i); }
  std::string text(int i) const {
    const auto* p = sqlite3_column_text(stmt_, i);
    return p ? std::string(reinterpret_cast<const char*>(p)) : std::string();
  }

 private:
  sqlite3* db_;
  sqlite3_stmt* stmt_ = nullptr;
};

void exec(sqlite3* db, const char* sql) {
  char* error = nullptr;
  if (sqlite3_exec(db, sql, nullptr, nullptr, &error) != SQLITE_OK) {
    const std::string message = error ? error : "unknown error";
    sqlite3_free(error);
    throw std::runtime_error("job store: " + message);
  }
}

void add_missing_columns(sqlite3* db) {
  for (const char* column : kAddedColumns) {
    const std::string name(column, std::strchr(column, ' '));
    bool missing = false;
    {  // finalized before the schema changes
      Statement info(db, "SELECT count(*) FROM pragma_table_info('jobs') WHERE name = ?");
      info.bind(1, name);
      missing = info.step() && info.integer(0) == 0;
    }
    if (missing) exec(db, ("ALTER TABLE jobs ADD COLUMN " + std::string(column)).c_str());
  }
}

std::string now_iso8601() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

// What the rest of the daemon reads of a stored request without checking again.
void check_stored_request(const Json& request) {
  if (!request.is_object()) throw std::invalid_argument("request: not an object");
  const auto scene = request.find("scene");
  if (scene == request.end() || !(scene->is_string() || scene->is_object()))
    throw std::invalid_argument("request.scene: missing or neither a name nor a document");
  for (const char* side : {"width", "height"}) {
    const auto it = request.find(side);
    if (it == request.end() || !it->is_number_integer() || it->get<int64_t>() < 1)
      throw std::invalid_argument(std::string("request.") + side + ": missing or not a positive integer");
  }
  const auto formats = request.find("formats");
  if (formats == request.end() || !formats->is_array())
    throw std::invalid_argument("request.formats: missing or not an array");
  for (const Json& format : *formats)
    if (!format.is_string() || (format != "exr" && format != "png" && format != "jpg"))
      throw std::invalid_argument("request.formats: holds an unknown format");
}

double finite_or(double value, double fallback) { return std::isfinite(value) ? value : fallback; }

// A row checked field by field: a damaged one reads as a failed job naming the damage (the
// request it cannot trust replaced by an empty one), and the rest of the store stays readable.
JobRecord read_row(const Statement& row) {
  JobRecord job;
  job.id = row.integer(0);
  job.created = row.text(3);
  job.samples = uint32_t(std::clamp<int64_t>(row.integer(4), 0, UINT32_MAX));
  job.elapsed = std::max(0.0, finite_or(row.real(5), 0));
  job.error = finite_or(row.real(6), -1);
  job.progress = std::clamp(finite_or(row.real(7), 0), 0.0, 1.0);
  job.checkpoint_samples = uint32_t(std::clamp<int64_t>(row.integer(8), 0, UINT32_MAX));
  job.message = row.text(9);
  job.non_finite_samples = uint64_t(std::max<int64_t>(row.integer(11), 0));
  job.truncated_geodesics = uint64_t(std::max<int64_t>(row.integer(12), 0));
  try {
    job.state = parse_state(row.text(1));
    job.request = Json::parse(row.text(2));
    check_stored_request(job.request);
    job.series = series_from_json(Json::parse(row.text(10)));
  } catch (const std::exception& e) {
    job.state = JobState::Failed;
    job.request = Json::object();
    job.series = {};
    job.message = std::string("stored record damaged: ") + e.what();
  }
  return job;
}

}  // namespace

JobStore::JobStore(const std::filesystem::path& file) {
  if (sqlite3_open_v2(file.c_str(), &db_, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, nullptr) !=
      SQLITE_OK) {
    const std::string message = db_ ? sqlite3_errmsg(db_) : "out of memory";
    sqlite3_close(db_);
    throw std::runtime_error("job store: " + file.string() + ": " + message);
  }
  try {
    // WAL: readers (status requests) never wait for a checkpoint's write. FULL: a commit is on
    // disk before the call returns, so a 202 means the job survives a crash of the machine too.
    exec(db_, "PRAGMA journal_mode=WAL; PRAGMA synchronous=FULL; PRAGMA busy_timeout=5000;");
    exec(db_, kSchema);
    add_missing_columns(db_);
  } catch (...) {
    sqlite3_close(db_);
    throw;
  }
}

JobStore::~JobStore() { sqlite3_close(db_); }

int64_t JobStore::insert(const Json& request) {
  std::lock_guard lock(mutex_);
  Statement insert(db_, "INSERT INTO jobs (state, request, created) VALUES (?, ?, ?)");
  insert.bind(1, std::string(state_name(JobState::Queued)))
      .bind(2, request.dump())
      .bind(3, now_iso8601())
      .step();
  return sqlite3_last_insert_rowid(db_);
}

void JobStore::reserve_ids_above(int64_t id) {
  std::lock_guard lock(mutex_);
  Statement current(db_, "SELECT coalesce(max(seq), 0) FROM sqlite_sequence WHERE name = 'jobs'");
  const int64_t seq = current.step() ? current.integer(0) : 0;
  Statement rows(db_, "SELECT coalesce(max(id), 0) FROM jobs");
  const int64_t last = rows.step() ? rows.integer(0) : 0;
  if (id <= std::max(seq, last)) return;
  Statement clear(db_, "DELETE FROM sqlite_sequence WHERE name = 'jobs'");
  clear.step();
  Statement set(db_, "INSERT INTO sqlite_sequence (name, seq) VALUES ('jobs', ?)");
  set.bind(1, id).step();
}

std::optional<JobRecord> JobStore::get(int64_t id) const {
  std::lock_guard lock(mutex_);
  Statement select(db_, std::string("SELECT ") + kColumns + " FROM jobs WHERE id = ?");
  select.bind(1, id);
  if (!select.step()) return std::nullopt;
  return read_row(select);
}

std::vector<JobRecord> JobStore::list(bool unfinished_only) const {
  std::lock_guard lock(mutex_);
  Statement select(db_, std::string("SELECT ") + kColumns + " FROM jobs" +
                            (unfinished_only ? " WHERE state IN ('queued', 'running')" : "") +
                            " ORDER BY id");
  std::vector<JobRecord> jobs;
  while (select.step()) jobs.push_back(read_row(select));
  return jobs;
}

std::vector<JobRecord> JobStore::page(int64_t after, int limit) const {
  std::lock_guard lock(mutex_);
  Statement select(db_, std::string("SELECT ") + kColumns +
                            " FROM jobs WHERE id > ? ORDER BY id LIMIT ?");
  select.bind(1, after).bind(2, int64_t(limit > 0 ? limit : -1));
  std::vector<JobRecord> jobs;
  while (select.step()) jobs.push_back(read_row(select));
  return jobs;
}

std::vector<int64_t> JobStore::finished_ids() const {
  std::lock_guard lock(mutex_);
  Statement select(db_, "SELECT id FROM jobs WHERE state NOT IN ('queued', 'running') ORDER BY id DESC");
  std::vector<int64_t> ids;
  while (select.step()) ids.push_back(select.integer(0));
  return ids;
}

void JobStore::remove(int64_t id) {
  std::lock_guard lock(mutex_);
  Statement remove(db_, "DELETE FROM jobs WHERE id = ?");
  remove.bind(1, id).step();
}

void JobStore::update(const JobRecord& job) {
  std::lock_guard lock(mutex_);
  Statement update(db_,
                   "UPDATE jobs SET state = ?, samples = ?, elapsed = ?, error = ?, progress = ?, "
                   "checkpoint_samples = ?, message = ?, series = ?, non_finite_samples = ?, "
                   "truncated_geodesics = ? WHERE id = ?");
  update.bind(1, std::string(state_name(job.state)))
      .bind(2, int64_t(job.samples))
      .bind(3, job.elapsed)
      .bind(4, job.error)
      .bind(5, job.progress)
      .bind(6, int64_t(job.checkpoint_samples))
      .bind(7, job.message)
      .bind(8, job.series.to_json()["series"].dump())
      .bind(9, int64_t(job.non_finite_samples))
      .bind(10, int64_t(job.truncated_geodesics))
      .bind(11, job.id)
      .step();
}

}  // namespace geodesic::jobs
