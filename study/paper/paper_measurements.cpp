#include "study/paper/paper_measurements.hpp"

#include <cmath>
#include <fstream>
#include <limits>
#include <regex>
#include <set>
#include <sstream>

#include <fmt/format.h>

#include "core/error.hpp"
#include "study/paper/paper_folder.hpp"
#include "study/result_store.hpp"

namespace wifislam::study::paper {

namespace {

namespace fs = std::filesystem;

std::string as_text(const SqlValue& v) {
  if (const auto* i = std::get_if<std::int64_t>(&v)) return std::to_string(*i);
  if (const auto* d = std::get_if<double>(&v)) return fmt::format("{}", *d);
  if (const auto* s = std::get_if<std::string>(&v)) return *s;
  return "";
}

nlohmann::json read_json(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  nlohmann::json j = nlohmann::json::parse(buffer.str(), nullptr, false);
  if (!j.is_object()) throw InvalidInputError(file.string() + ": not a JSON object");
  return j;
}

/// "<part>-<twin>-seed<seed>" (a study's name, a database's stem) or "<twin>-seed<seed>".
struct Named {
  std::optional<Part> part;
  std::string twin;
  std::uint64_t seed = 0;
};

std::optional<Named> parse_name(const std::string& stem, bool with_part) {
  static const std::regex with(R"(^([a-z]+)-([a-z]_hall)-seed([0-9]{1,19})$)");
  static const std::regex without(R"(^([a-z]_hall)-seed([0-9]{1,19})$)");
  std::smatch m;
  Named n;
  if (with_part) {
    if (!std::regex_match(stem, m, with)) return std::nullopt;
    n.part = parse_part(m[1]);
    if (!n.part) return std::nullopt;
    n.twin = m[2];
    n.seed = std::stoull(m[3]);
  } else {
    if (!std::regex_match(stem, m, without)) return std::nullopt;
    n.twin = m[1];
    n.seed = std::stoull(m[2]);
  }
  return n;
}

std::vector<fs::path> sorted_entries(const fs::path& dir) {
  std::vector<fs::path> out;
  if (!fs::is_directory(dir)) return out;
  for (const auto& e : fs::directory_iterator(dir)) out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

double RunRow::value(const std::string& column) const {
  const auto it = values.find(column);
  return it == values.end() ? std::numeric_limits<double>::quiet_NaN() : it->second;
}

PaperMeasurements PaperMeasurements::load(const fs::path& folder) {
  PaperMeasurements m;
  m.folder_ = folder;
  for (const fs::path& db : sorted_entries(folder / folder::kResults)) {
    if (db.extension() != ".sqlite") continue;
    const auto name = parse_name(db.stem().string(), true);
    if (!name) continue;  // not one of ours: the report does not guess
    const ResultTable table = read_results_and_timing(db);
    std::vector<int> axes;
    std::vector<std::string> axis_names;
    for (const std::string& key : table.identity.axis_keys) {
      axes.push_back(table.column(column_name(key)));
      axis_names.push_back(key.rfind("slam.", 0) == 0 ? key.substr(5) : key);
    }
    const int variant = table.column("variant");
    for (const auto& row : table.rows) {
      RunRow r;
      r.part = *name->part;
      r.twin = name->twin;
      r.seed = name->seed;
      for (std::size_t a = 0; a < axes.size(); ++a) {
        r.setting += (a ? " " : "") + axis_names[a] + "=" +
                     (axes[a] >= 0 ? as_text(row[static_cast<std::size_t>(axes[a])]) : "");
      }
      r.wifi = variant >= 0 && as_text(row[static_cast<std::size_t>(variant)]) == "wifi";
      for (std::size_t c = 0; c < table.columns.size(); ++c) {
        if (const auto* i = std::get_if<std::int64_t>(&row[c])) {
          r.values[table.columns[c]] = static_cast<double>(*i);
        } else if (const auto* d = std::get_if<double>(&row[c])) {
          r.values[table.columns[c]] = *d;
        }
      }
      m.rows_.push_back(std::move(r));
    }
  }
  for (const fs::path& file : sorted_entries(folder / folder::kDatasets)) {
    if (file.extension() != ".json") continue;
    if (const auto name = parse_name(file.stem().string(), false)) {
      m.datasets_[name->twin][name->seed] = read_json(file);
    }
  }
  for (const fs::path& dir : sorted_entries(folder / folder::kLocalize)) {
    const auto name = parse_name(dir.filename().string(), false);
    if (name && fs::exists(dir / "summary.json")) {
      m.localisations_[name->twin][name->seed] = read_json(dir / "summary.json");
    }
  }
  return m;
}

PaperMeasurements PaperMeasurements::from_rows(std::vector<RunRow> rows) {
  PaperMeasurements m;
  m.rows_ = std::move(rows);
  return m;
}

std::vector<const RunRow*> PaperMeasurements::runs(Part part, const std::string& twin,
                                                   const std::string& setting, bool wifi) const {
  std::map<std::uint64_t, const RunRow*> by_seed;
  for (const RunRow& r : rows_) {
    if (r.part == part && r.twin == twin && r.setting == setting && r.wifi == wifi) {
      by_seed[r.seed] = &r;
    }
  }
  std::vector<const RunRow*> out;
  for (const auto& [seed, row] : by_seed) out.push_back(row);
  return out;
}

Measured PaperMeasurements::column(Part part, const std::string& twin, const std::string& setting,
                                   bool wifi, const std::string& name) const {
  Measured out;
  for (const RunRow* r : runs(part, twin, setting, wifi)) {
    const double v = r->value(name);
    if (!std::isnan(v)) out.per_seed.push_back(v);
  }
  return out;
}

std::pair<Measured, Measured> PaperMeasurements::paired(Part part, const std::string& twin,
                                                        const std::string& setting,
                                                        const std::string& name) const {
  std::map<std::uint64_t, double> vanilla;
  for (const RunRow* r : runs(part, twin, setting, false)) {
    const double v = r->value(name);
    if (!std::isnan(v)) vanilla[r->seed] = v;
  }
  std::pair<Measured, Measured> out;
  for (const RunRow* r : runs(part, twin, setting, true)) {
    const double w = r->value(name);
    const auto v = vanilla.find(r->seed);
    if (std::isnan(w) || v == vanilla.end()) continue;
    out.first.per_seed.push_back(v->second);
    out.second.per_seed.push_back(w);
  }
  return out;
}

std::vector<std::uint64_t> PaperMeasurements::seeds(Part part, const std::string& twin) const {
  std::set<std::uint64_t> seeds;
  for (const RunRow& r : rows_)
    if (r.part == part && r.twin == twin) seeds.insert(r.seed);
  return {seeds.begin(), seeds.end()};
}

std::vector<std::string> PaperMeasurements::settings(Part part, const std::string& twin) const {
  std::vector<std::string> out;
  for (const RunRow& r : rows_) {
    if (r.part == part && r.twin == twin &&
        std::find(out.begin(), out.end(), r.setting) == out.end()) {
      out.push_back(r.setting);
    }
  }
  return out;
}

}  // namespace wifislam::study::paper
