#pragma once
// A study's results in one SQLite database (Debian's libsqlite3):
//
//   study(key TEXT PRIMARY KEY, value TEXT)   name, study_file_hash, software_version, level,
//                                             axes (JSON: key and column of each axis)
//   results(case_id, case_index, variant,     one row per case x variant ("radio"; or
//           <one column per axis>,            "vanilla" and "wifi"): the case's axis values,
//           <one column per metric>,          every metric (deterministic: the same study gives
//           software_version, scene_hash)     the same rows, whatever the machine or shard)
//           PRIMARY KEY (case_id, variant)
//   timing(case_id, variant, <wall-clock      machine-dependent times, kept apart so that
//          seconds>)                          `results` compares row for row
//
// A case's rows are written in one transaction, so a killed run (Ctrl-C, SIGKILL) loses at most
// the case in flight and never leaves half a case. Axis values that read as numbers are stored as
// numbers (so SQL can order and average them), others as text.

#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <variant>
#include <vector>

#include "study/database_lock.hpp"
#include "study/study_file.hpp"

struct sqlite3;

namespace wifislam::study {

using SqlValue = std::variant<std::monostate, std::int64_t, double, std::string>;

struct ResultColumn {
  std::string name;
  SqlValue value;
};

/// One row of `results` (without the axis columns, which the store adds from the case).
struct ResultRow {
  std::string variant;
  std::vector<ResultColumn> metrics;
  std::vector<ResultColumn> timing;  // wall-clock seconds
  std::string scene_hash;
};

/// The database's identity: which study file and build wrote it.
struct StudyIdentity {
  std::string name, study_file_hash, software_version, level;
  std::vector<std::string> axis_keys;
  friend bool operator==(const StudyIdentity&, const StudyIdentity&) = default;
};
StudyIdentity identity_of(const StudyFile& study);

class ResultStore {
 public:
  /// Opens `path`, creating the tables when the file is new. An existing database must be one of
  /// this study (same identity): InvalidInputError naming what differs otherwise. One store at a
  /// time writes a database: it holds a lock on `path`.lock (kept beside it, DatabaseLock) while
  /// it is open, and a second is refused (InvalidInputError) instead of repeating the first one's
  /// cases. `replace_existing`: remove a database already at `path` (--force on another study's
  /// database, checked by the caller) once the lock is held, never before.
  ResultStore(const std::filesystem::path& path, const StudyFile& study,
              const std::vector<std::string>& metric_columns,
              const std::vector<std::string>& timing_columns, bool replace_existing = false);
  ~ResultStore();
  ResultStore(const ResultStore&) = delete;
  ResultStore& operator=(const ResultStore&) = delete;

  /// Case ids with rows already (a rerun skips them).
  std::set<std::string> finished_cases() const;
  /// The scene hash each finished case's rows were written with (empty when none is recorded):
  /// a rerun checks that its scene is still the one they were made on.
  std::map<std::string, std::string> finished_scene_hashes() const;
  /// Writes every row of one case in one transaction.
  void write_case(const StudyCase& c, const std::vector<ResultRow>& rows);

  /// Whether `path` is a study database (has the study table), and its identity.
  static std::optional<StudyIdentity> read_identity(const std::filesystem::path& path);

 private:
  void exec(const std::string& sql) const;
  DatabaseLock lock_;  // first in, last out: held while the database is open
  sqlite3* db_ = nullptr;
  StudyFile study_;
  std::vector<std::string> metric_columns_, timing_columns_;
};

/// Unions shard databases into `out` (a new file): every input must have the same identity,
/// and a case present in two inputs must have identical rows. One file given twice, or a shard
/// whose cases the inputs before it all hold already (a copy), is refused (InvalidInputError):
/// it would leave the shard that was meant out without a word. Returns the number of rows.
std::int64_t merge_study_databases(const std::vector<std::filesystem::path>& inputs,
                                   const std::filesystem::path& out);

/// How many of a study database's cases have rows, and how many the study has (recorded since
/// databases hold it; nullopt in older ones).
struct CaseCount {
  std::int64_t with_rows = 0;
  std::optional<std::int64_t> in_study;
};
CaseCount count_cases(const std::filesystem::path& path);

/// The `results` table as stored: column names and typed values, ordered by case_index, variant.
struct ResultTable {
  StudyIdentity identity;
  std::vector<std::string> columns;
  std::vector<std::vector<SqlValue>> rows;
  /// Index of `column`, or -1.
  int column(const std::string& name) const;
};
/// Reads a study database; InvalidInputError when `path` is not one.
ResultTable read_results(const std::filesystem::path& path);

/// The same with each row's `timing` columns after its results columns (their names as stored;
/// NULL where a row has no timing).
ResultTable read_results_and_timing(const std::filesystem::path& path);

/// Every row of `results` ordered by case_id, variant, as text (for tests and `study show`).
std::vector<std::vector<std::string>> dump_results(const std::filesystem::path& path);

}  // namespace wifislam::study
