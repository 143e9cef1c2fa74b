#include "study/result_store.hpp"

#include <sqlite3.h>

#include <charconv>
#include <cstdlib>
#include <memory>
#include <system_error>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/error.hpp"

namespace wifislam::study {

namespace {

namespace fs = std::filesystem;

#ifndef WIFISLAM_VERSION
#define WIFISLAM_VERSION "unknown"
#endif

std::string quote_identifier(const std::string& name) {
  std::string out = "\"";
  for (char c : name) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

[[noreturn]] void sqlite_failure(sqlite3* db, const std::string& what) {
  throw IoError(fmt::format("{}: {}", what, db ? sqlite3_errmsg(db) : "out of memory"));
}

/// A prepared statement, finalised on scope exit.
class Statement {
 public:
  Statement(sqlite3* db, const std::string& sql) : db_(db) {
    if (sqlite3_prepare_v2(db, sql.c_str(), -1, &stmt_, nullptr) != SQLITE_OK) {
      sqlite_failure(db, "SQLite: preparing \"" + sql + "\"");
    }
  }
  ~Statement() { sqlite3_finalize(stmt_); }
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;

  void bind(int index, const SqlValue& value) {
    int rc = SQLITE_OK;
    if (std::holds_alternative<std::monostate>(value)) {
      rc = sqlite3_bind_null(stmt_, index);
    } else if (const auto* i = std::get_if<std::int64_t>(&value)) {
      rc = sqlite3_bind_int64(stmt_, index, *i);
    } else if (const auto* d = std::get_if<double>(&value)) {
      rc = sqlite3_bind_double(stmt_, index, *d);
    } else {
      const std::string& s = std::get<std::string>(value);
      rc = sqlite3_bind_text(stmt_, index, s.c_str(), static_cast<int>(s.size()), SQLITE_TRANSIENT);
    }
    if (rc != SQLITE_OK) sqlite_failure(db_, "SQLite: binding a value");
  }
  /// Steps once; true while there is a row.
  bool step() {
    const int rc = sqlite3_step(stmt_);
    if (rc == SQLITE_ROW) return true;
    if (rc == SQLITE_DONE) return false;
    sqlite_failure(db_, "SQLite");
  }
  std::string text(int column) const {
    const unsigned char* t = sqlite3_column_text(stmt_, column);
    return t ? reinterpret_cast<const char*>(t) : "";
  }
  std::string as_text(int column) const {
    switch (sqlite3_column_type(stmt_, column)) {
      case SQLITE_NULL:
        return "NULL";
      case SQLITE_INTEGER:
        return std::to_string(sqlite3_column_int64(stmt_, column));
      case SQLITE_FLOAT:
        return fmt::format("{}", sqlite3_column_double(stmt_, column));
      default:
        return text(column);
    }
  }
  std::int64_t int64(int column) const { return sqlite3_column_int64(stmt_, column); }
  /// The first `n` columns of the current row, typed as stored.
  std::vector<SqlValue> values(std::size_t n) const {
    std::vector<SqlValue> row;
    for (int c = 0; c < static_cast<int>(n); ++c) {
      switch (sqlite3_column_type(stmt_, c)) {
        case SQLITE_NULL:
          row.emplace_back(std::monostate{});
          break;
        case SQLITE_INTEGER:
          row.emplace_back(std::int64_t{sqlite3_column_int64(stmt_, c)});
          break;
        case SQLITE_FLOAT:
          row.emplace_back(sqlite3_column_double(stmt_, c));
          break;
        default:
          row.emplace_back(text(c));
      }
    }
    return row;
  }

 private:
  sqlite3* db_;
  sqlite3_stmt* stmt_ = nullptr;
};

sqlite3* open_database(const fs::path& path, int flags) {
  sqlite3* db = nullptr;
  if (sqlite3_open_v2(path.c_str(), &db, flags, nullptr) != SQLITE_OK) {
    const std::string message = db ? sqlite3_errmsg(db) : "out of memory";
    sqlite3_close(db);
    throw IoError(fmt::format("{}: cannot open the study database ({})", path.string(), message));
  }
  // Wait for a concurrent writer instead of failing at once (two shards on one file system).
  sqlite3_busy_timeout(db, 60000);
  return db;
}

void exec_on(sqlite3* db, const std::string& sql) {
  char* error = nullptr;
  if (sqlite3_exec(db, sql.c_str(), nullptr, nullptr, &error) != SQLITE_OK) {
    const std::string message = error ? error : "unknown error";
    sqlite3_free(error);
    throw IoError("SQLite: " + message + " in \"" + sql.substr(0, 200) + "\"");
  }
}

/// A value as the store writes it: numbers as numbers, other text as text.
SqlValue typed(const std::string& text) {
  if (text.empty()) return text;
  std::int64_t i = 0;
  const char* end = text.data() + text.size();
  if (auto [p, ec] = std::from_chars(text.data(), end, i); ec == std::errc() && p == end) return i;
  double d = 0;
  if (auto [p, ec] = std::from_chars(text.data(), end, d); ec == std::errc() && p == end) return d;
  return text;
}

std::optional<StudyIdentity> identity_from(sqlite3* db, const fs::path& path) {
  {
    Statement exists(db, "SELECT count(*) FROM sqlite_master WHERE type='table' AND name='study'");
    exists.step();
    if (exists.int64(0) == 0) return std::nullopt;
  }
  StudyIdentity id;
  Statement q(db, "SELECT key, value FROM study");
  while (q.step()) {
    const std::string key = q.text(0), value = q.text(1);
    if (key == "name") id.name = value;
    if (key == "study_file_hash") id.study_file_hash = value;
    if (key == "software_version") id.software_version = value;
    if (key == "level") id.level = value;
    if (key == "axes") {
      const nlohmann::json axes = nlohmann::json::parse(value, nullptr, false);
      if (!axes.is_array()) {
        throw InvalidInputError(path.string() +
                                ": the study table's 'axes' is not a list of axis keys (damaged?)");
      }
      for (const auto& a : axes) {
        if (!a.is_string()) {
          throw InvalidInputError(
              path.string() + ": the study table's 'axes' is not a list of axis keys (damaged?)");
        }
        id.axis_keys.push_back(a.get<std::string>());
      }
    }
  }
  return id;
}

std::string difference(const StudyIdentity& a, const StudyIdentity& b) {
  if (a.study_file_hash != b.study_file_hash) {
    return "another study file (or another version of it) wrote it";
  }
  if (a.software_version != b.software_version) {
    return fmt::format("wifislam {} wrote it, this is {}", a.software_version, b.software_version);
  }
  return "its study identity differs";
}

std::vector<std::string> result_columns(sqlite3* db, const std::string& schema,
                                        const std::string& table) {
  std::vector<std::string> columns;
  Statement q(db, fmt::format("PRAGMA {}.table_info({})", schema, table));
  while (q.step()) columns.push_back(q.text(1));
  return columns;
}

/// SQLite's own check of every page of a database: a damaged shard is named before a merge
/// reads it (its error would otherwise say "database disk image is malformed" and no file).
void check_integrity(const fs::path& path) {
  sqlite3* db = nullptr;
  try {
    db = open_database(path, SQLITE_OPEN_READONLY);
    Statement q(db, "PRAGMA integrity_check");
    const std::string verdict = q.step() ? q.text(0) : "no answer";
    sqlite3_close(db);
    db = nullptr;
    if (verdict != "ok") {
      throw InvalidInputError(fmt::format("{}: a damaged database ({})", path.string(), verdict));
    }
  } catch (const IoError& e) {
    if (db) sqlite3_close(db);
    throw InvalidInputError(
        fmt::format("{}: not a readable study database ({})", path.string(), e.what()));
  }
}

}  // namespace

StudyIdentity identity_of(const StudyFile& study) {
  StudyIdentity id;
  id.name = study.name;
  id.study_file_hash = study.file_hash;
  id.software_version = WIFISLAM_VERSION;
  id.level = to_string(study.level);
  for (const StudyAxis& a : study.axes) id.axis_keys.push_back(a.key);
  return id;
}

ResultStore::ResultStore(const fs::path& path, const StudyFile& study,
                         const std::vector<std::string>& metric_columns,
                         const std::vector<std::string>& timing_columns, bool replace_existing)
    : lock_(path, "writing"),
      study_(study),
      metric_columns_(metric_columns),
      timing_columns_(timing_columns) {
  if (replace_existing) {
    // Only now, holding the lock: a refused run (another one writing, a bad case) has removed
    // nothing. And only what was checked before the lock: another study's database. A run that
    // replaced it meanwhile (the same --force twice) left this study's, which is resumed.
    const auto now = read_identity(path);
    if (now && !(*now == identity_of(study))) {
      std::error_code ec;
      fs::remove(path);
      fs::remove(path.string() + "-journal", ec);
    } else if (!now && fs::exists(path)) {
      throw InvalidInputError(path.string() +
                              ": is no longer a study database; refusing to replace it");
    }
  }
  db_ = open_database(path, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE);
  try {
    // A rollback journal (the default) and full syncs: a transaction is all there or absent
    // after a crash, on every file system (WAL needs shared memory, which NFS may not give).
    exec("PRAGMA synchronous=FULL");
    const StudyIdentity mine = identity_of(study);
    if (const auto existing = identity_from(db_, path)) {
      if (!(*existing == mine)) {
        throw InvalidInputError(fmt::format("{}: a study database of study '{}', not of {}: {}",
                                            path.string(), existing->name, study.path.string(),
                                            difference(*existing, mine)));
      }
      // The same study by a build with other columns (a metric added since): its rows could not
      // be written, nor compared with this build's.
      std::vector<std::string> expected = {"case_id", "case_index", "variant"};
      for (const StudyAxis& a : study.axes) expected.push_back(column_name(a.key));
      for (const std::string& m : metric_columns) expected.push_back(m);
      expected.push_back("software_version");
      expected.push_back("scene_hash");
      std::vector<std::string> expected_timing = {"case_id", "variant"};
      for (const std::string& t : timing_columns) expected_timing.push_back(t);
      if (result_columns(db_, "main", "results") != expected ||
          result_columns(db_, "main", "timing") != expected_timing) {
        throw InvalidInputError(fmt::format(
            "{}: a database of study '{}' written by a build with other result columns; its "
            "rows cannot be continued by this one: write to a new database",
            path.string(), existing->name));
      }
      return;
    }
    std::string columns =
        "case_id TEXT NOT NULL, case_index INTEGER NOT NULL, variant TEXT NOT NULL";
    for (const StudyAxis& a : study.axes) columns += ", " + quote_identifier(column_name(a.key));
    for (const std::string& m : metric_columns) columns += ", " + quote_identifier(m);
    columns += ", software_version TEXT, scene_hash TEXT, PRIMARY KEY (case_id, variant)";
    std::string timing = "case_id TEXT NOT NULL, variant TEXT NOT NULL";
    for (const std::string& t : timing_columns) timing += ", " + quote_identifier(t);
    timing += ", PRIMARY KEY (case_id, variant)";
    nlohmann::json axes = nlohmann::json::array();
    for (const std::string& k : mine.axis_keys) axes.push_back(k);
    exec("BEGIN");
    exec("CREATE TABLE study (key TEXT PRIMARY KEY, value TEXT)");
    exec("CREATE TABLE results (" + columns + ")");
    exec("CREATE TABLE timing (" + timing + ")");
    Statement insert(db_, "INSERT INTO study (key, value) VALUES (?, ?)");
    for (const auto& [k, v] : std::vector<std::pair<std::string, std::string>>{
             {"name", mine.name},
             {"study_file_hash", mine.study_file_hash},
             {"software_version", mine.software_version},
             {"level", mine.level},
             {"axes", axes.dump()},
             // Every case of the study, whichever shard this is: a merge can tell it is short.
             {"cases", std::to_string(study.cases.size())}}) {
      Statement row(db_, "INSERT INTO study (key, value) VALUES (?, ?)");
      row.bind(1, k);
      row.bind(2, v);
      row.step();
    }
    exec("COMMIT");
  } catch (...) {
    sqlite3_close(db_);
    throw;
  }
}

ResultStore::~ResultStore() { sqlite3_close(db_); }

void ResultStore::exec(const std::string& sql) const { exec_on(db_, sql); }

std::map<std::string, std::string> ResultStore::finished_scene_hashes() const {
  std::map<std::string, std::string> out;
  Statement q(db_, "SELECT case_id, max(coalesce(scene_hash, '')) FROM results GROUP BY case_id");
  while (q.step()) out[q.text(0)] = q.text(1);
  return out;
}

std::set<std::string> ResultStore::finished_cases() const {
  std::set<std::string> ids;
  Statement q(db_, "SELECT DISTINCT case_id FROM results");
  while (q.step()) ids.insert(q.text(0));
  return ids;
}

void ResultStore::write_case(const StudyCase& c, const std::vector<ResultRow>& rows) {
  exec("BEGIN IMMEDIATE");
  try {
    for (const ResultRow& row : rows) {
      std::string names = "case_id, case_index, variant", marks = "?, ?, ?";
      for (const StudyAxis& a : study_.axes) {
        names += ", " + quote_identifier(column_name(a.key));
        marks += ", ?";
      }
      for (const ResultColumn& m : row.metrics) {
        names += ", " + quote_identifier(m.name);
        marks += ", ?";
      }
      names += ", software_version, scene_hash";
      marks += ", ?, ?";
      Statement insert(db_, "INSERT INTO results (" + names + ") VALUES (" + marks + ")");
      int k = 1;
      insert.bind(k++, c.id);
      insert.bind(k++, static_cast<std::int64_t>(c.index));
      insert.bind(k++, row.variant);
      for (const std::string& v : c.values) insert.bind(k++, typed(v));
      for (const ResultColumn& m : row.metrics) insert.bind(k++, m.value);
      insert.bind(k++, std::string(WIFISLAM_VERSION));
      insert.bind(k++, row.scene_hash);
      insert.step();
      std::string tnames = "case_id, variant", tmarks = "?, ?";
      for (const ResultColumn& t : row.timing) {
        tnames += ", " + quote_identifier(t.name);
        tmarks += ", ?";
      }
      Statement timing(db_, "INSERT INTO timing (" + tnames + ") VALUES (" + tmarks + ")");
      k = 1;
      timing.bind(k++, c.id);
      timing.bind(k++, row.variant);
      for (const ResultColumn& t : row.timing) timing.bind(k++, t.value);
      timing.step();
    }
    exec("COMMIT");
  } catch (...) {
    exec_on(db_, "ROLLBACK");
    throw;
  }
}

std::optional<StudyIdentity> ResultStore::read_identity(const fs::path& path) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) return std::nullopt;
  sqlite3* db = open_database(path, SQLITE_OPEN_READONLY);
  std::optional<StudyIdentity> id;
  try {
    id = identity_from(db, path);
  } catch (const IoError&) {
    id.reset();  // not an SQLite database at all
  } catch (...) {
    sqlite3_close(db);
    throw;
  }
  sqlite3_close(db);
  return id;
}

CaseCount count_cases(const fs::path& path) {
  CaseCount count;
  sqlite3* db = open_database(path, SQLITE_OPEN_READONLY);
  try {
    Statement finished(db, "SELECT count(DISTINCT case_id) FROM results");
    finished.step();
    count.with_rows = finished.int64(0);
    Statement cases(db, "SELECT value FROM study WHERE key = 'cases'");
    if (cases.step()) {
      const std::string text = cases.text(0);
      std::int64_t n = 0;
      const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), n);
      if (ec == std::errc() && end == text.data() + text.size()) count.in_study = n;
    }
  } catch (...) {
    sqlite3_close(db);
    throw;
  }
  sqlite3_close(db);
  return count;
}

std::int64_t merge_study_databases(const std::vector<fs::path>& inputs, const fs::path& out) {
  if (inputs.empty()) throw InvalidInputError("study merge: no shard databases given");
  // One shard given twice (another spelling, a link) merges to a database short of the shard
  // that was meant, without a word.
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      std::error_code ec;
      if (fs::equivalent(inputs[i], inputs[j], ec) && !ec) {
        throw InvalidInputError(
            fmt::format("{}: given twice (also as {}); each shard is merged "
                        "once",
                        inputs[i].string(), inputs[j].string()));
      }
    }
  }
  std::optional<StudyIdentity> first;
  for (const fs::path& in : inputs) {
    std::error_code ec;
    if (!fs::exists(in, ec)) throw IoError(in.string() + ": no such shard database");
    check_integrity(in);
    const auto id = ResultStore::read_identity(in);
    if (!id) throw InvalidInputError(in.string() + ": not a study database");
    if (!first) {
      first = id;
    } else if (!(*id == *first)) {
      throw InvalidInputError(fmt::format("{}: {} (the first shard, {}, is of study '{}')",
                                          in.string(), difference(*id, *first),
                                          inputs.front().string(), first->name));
    }
  }
  // A shard a run is still writing would be merged short of its last cases, without a word:
  // each is held shared until the merge is done, so no run writes it meanwhile.
  std::vector<std::unique_ptr<DatabaseLock>> shard_locks;
  for (const fs::path& in : inputs) {
    shard_locks.push_back(std::make_unique<DatabaseLock>(in, "merging", true));
  }
  // Held from here to the rename: a run writing `out` now would lose its rows to the merge.
  const DatabaseLock out_lock(out, "replacing");
  const fs::path partial = out.string() + ".partial";
  std::error_code ec;
  if (fs::is_directory(partial, ec)) {
    throw InvalidInputError(fmt::format(
        "{}: a folder where the merge writes its staging file; move it away", partial.string()));
  }
  fs::remove(partial);
  {
    // The first shard's schema and rows, then every other shard's rows.
    sqlite3* db = open_database(inputs.front(), SQLITE_OPEN_READONLY);
    try {
      Statement vacuum(db, "VACUUM INTO ?");
      vacuum.bind(1, partial.string());
      vacuum.step();
    } catch (...) {
      sqlite3_close(db);
      throw;
    }
    sqlite3_close(db);
  }
  sqlite3* db = open_database(partial, SQLITE_OPEN_READWRITE);
  std::int64_t rows = 0;
  try {
    const std::vector<std::string> columns = result_columns(db, "main", "results");
    for (std::size_t i = 1; i < inputs.size(); ++i) {
      Statement attach(db, "ATTACH DATABASE ? AS shard");
      attach.bind(1, inputs[i].string());
      attach.step();
      if (result_columns(db, "shard", "results") != columns) {
        throw InvalidInputError(inputs[i].string() + ": its results table has other columns");
      }
      std::string differs;
      for (const std::string& c : columns) {
        differs += (differs.empty() ? "" : " OR ") +
                   fmt::format("s.{0} IS NOT m.{0}", quote_identifier(c));
      }
      Statement conflicts(db,
                          "SELECT s.case_id FROM shard.results s JOIN main.results m "
                          "ON s.case_id = m.case_id AND s.variant = m.variant WHERE " +
                              differs);
      if (conflicts.step()) {
        throw InvalidInputError(
            fmt::format("{}: case {} differs from the same case in another shard",
                        inputs[i].string(), conflicts.text(0)));
      }
      // A copy of a shard already merged adds nothing: the same shard twice, most likely.
      std::int64_t held = 0, fresh = 0;
      {
        Statement count_held(db, "SELECT count(*) FROM shard.results");
        count_held.step();
        held = count_held.int64(0);
        Statement count_fresh(db,
                              "SELECT count(*) FROM shard.results s WHERE NOT EXISTS (SELECT 1 "
                              "FROM main.results m WHERE m.case_id = s.case_id AND m.variant = "
                              "s.variant)");
        count_fresh.step();
        fresh = count_fresh.int64(0);
      }
      if (held > 0 && fresh == 0) {
        throw InvalidInputError(
            fmt::format("{}: holds only cases the shards before it already hold (the same shard "
                        "given twice, or a copy?); merge each shard once",
                        inputs[i].string()));
      }
      exec_on(db, "BEGIN");
      exec_on(db, "INSERT OR IGNORE INTO main.results SELECT * FROM shard.results");
      exec_on(db, "INSERT OR IGNORE INTO main.timing SELECT * FROM shard.timing");
      exec_on(db, "COMMIT");
      exec_on(db, "DETACH DATABASE shard");
    }
    Statement count(db, "SELECT count(*) FROM results");
    count.step();
    rows = count.int64(0);
  } catch (...) {
    sqlite3_close(db);
    fs::remove(partial);
    throw;
  }
  sqlite3_close(db);
  // A journal left by a run killed on the old file would be rolled back into the new one.
  std::error_code journal_ec;
  fs::remove(out.string() + "-journal", journal_ec);
  fs::rename(partial, out);
  return rows;
}

int ResultTable::column(const std::string& name) const {
  for (std::size_t i = 0; i < columns.size(); ++i)
    if (columns[i] == name) return static_cast<int>(i);
  return -1;
}

namespace {

/// The results table, with each row's timing columns after it when `with_timing`.
ResultTable read_table(const fs::path& path, bool with_timing) {
  if (std::error_code ec; !fs::exists(path, ec)) {
    throw IoError(path.string() + ": no such study database");
  }
  const auto identity = ResultStore::read_identity(path);
  if (!identity) throw InvalidInputError(path.string() + ": not a study database");
  ResultTable table;
  table.identity = *identity;
  sqlite3* db = open_database(path, SQLITE_OPEN_READONLY);
  try {
    table.columns = result_columns(db, "main", "results");
    std::string select = "SELECT r.*";
    if (with_timing) {
      for (const std::string& t : result_columns(db, "main", "timing")) {
        if (t == "case_id" || t == "variant") continue;
        table.columns.push_back(t);
        select += ", t." + quote_identifier(t);
      }
    }
    Statement q(db, select +
                        (with_timing ? " FROM results r LEFT JOIN timing t ON r.case_id = "
                                       "t.case_id AND r.variant = t.variant"
                                     : " FROM results r") +
                        " ORDER BY r.case_index, r.variant");
    while (q.step()) table.rows.push_back(q.values(table.columns.size()));
  } catch (...) {
    sqlite3_close(db);
    throw;
  }
  sqlite3_close(db);
  return table;
}

}  // namespace

ResultTable read_results(const fs::path& path) { return read_table(path, false); }

ResultTable read_results_and_timing(const fs::path& path) { return read_table(path, true); }

std::vector<std::vector<std::string>> dump_results(const fs::path& path) {
  sqlite3* db = open_database(path, SQLITE_OPEN_READONLY);
  std::vector<std::vector<std::string>> out;
  try {
    const std::size_t n = result_columns(db, "main", "results").size();
    Statement q(db, "SELECT * FROM results ORDER BY case_id, variant");
    while (q.step()) {
      std::vector<std::string> row;
      for (std::size_t c = 0; c < n; ++c) row.push_back(q.as_text(static_cast<int>(c)));
      out.push_back(std::move(row));
    }
  } catch (...) {
    sqlite3_close(db);
    throw;
  }
  sqlite3_close(db);
  return out;
}

}  // namespace wifislam::study
