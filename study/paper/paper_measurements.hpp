#pragma once
// Our side of the paper's numbers: everything a paper folder (paper_folder.hpp) holds, read back
// as rows to look numbers up in. The report reads only this; nothing is recomputed.

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "study/paper/paper_numbers.hpp"
#include "study/paper/verdict.hpp"

namespace wifislam::study::paper {

/// One run: a row of a study database (results and timing).
struct RunRow {
  Part part = Part::kRgbdslam;
  std::string twin;
  std::uint64_t seed = 0;
  /// The swept options as "key=value", space-separated in axis order ("time_threshold_ms=70",
  /// "min_matches=50 inlier_distance=3").
  std::string setting;
  bool wifi = false;
  std::map<std::string, double> values;           // every numeric column (NULL ones absent)
  double value(const std::string& column) const;  // NaN when absent
};

class PaperMeasurements {
 public:
  /// Reads every study database, dataset record and localisation of `folder`. Throws
  /// InvalidInputError naming a file that is not what the folder's layout says.
  static PaperMeasurements load(const std::filesystem::path& folder);
  /// Runs alone, no dataset record or localisation: what a study database's rows make of them.
  static PaperMeasurements from_rows(std::vector<RunRow> rows);

  const std::vector<RunRow>& rows() const { return rows_; }
  /// The rows of one part, twin, setting and variant, in seed order.
  std::vector<const RunRow*> runs(Part part, const std::string& twin, const std::string& setting,
                                  bool wifi) const;
  /// One column of those rows, one value per seed.
  Measured column(Part part, const std::string& twin, const std::string& setting, bool wifi,
                  const std::string& name) const;
  /// The same for both variants, paired: only the seeds that have both.
  std::pair<Measured, Measured> paired(Part part, const std::string& twin,
                                       const std::string& setting, const std::string& name) const;
  /// The seeds with rows of a part on a twin (any setting).
  std::vector<std::uint64_t> seeds(Part part, const std::string& twin) const;
  /// The settings a part ran on a twin, in the order first met.
  std::vector<std::string> settings(Part part, const std::string& twin) const;

  /// datasets/<twin>-seed<s>.json, by twin then seed.
  const std::map<std::string, std::map<std::uint64_t, nlohmann::json>>& datasets() const {
    return datasets_;
  }
  /// localize/<twin>-seed<s>/summary.json, by twin then seed.
  const std::map<std::string, std::map<std::uint64_t, nlohmann::json>>& localisations() const {
    return localisations_;
  }
  const std::filesystem::path& folder() const { return folder_; }

 private:
  std::filesystem::path folder_;
  std::vector<RunRow> rows_;
  std::map<std::string, std::map<std::uint64_t, nlohmann::json>> datasets_, localisations_;
};

}  // namespace wifislam::study::paper
