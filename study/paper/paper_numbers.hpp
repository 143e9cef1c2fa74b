#pragma once
// Every number the paper's evaluation gives (../shared/paper/, "Evaluation", its tables and the
// numbers its text and abstract state), entered once, each with the table or passage it comes
// from. The report (paper_report.hpp) sets ours beside each one and judges it (verdict.hpp).
//
// The tables are kept as the paper's own LaTeX rows ("A Hall & 0.2304 & 0.2284 & ..."), parsed
// here, so that a number can be checked against the paper by eye and is never typed twice.

#include <optional>
#include <string>
#include <vector>

namespace wifislam::study::paper {

/// The report's parts: one page each.
enum class Part { kDatasets, kRgbdslam, kRtabmap, kOrbslam, kFabmap, kAbstract };
const char* to_string(Part part);  // "datasets", "rgbdslam", ...
std::optional<Part> parse_part(const std::string& text);

/// What a number measures, and so which of our measurements stands beside it.
enum class Quantity {
  kAteRmseM,           // trajectory error: ATE RMSE after rigid alignment (m)
  kFalseNegativePct,   // loop closures missed, % of those a good map has
  kFalsePositivePct,   // wrong loop closures, % of those detected
  kLoopClosureTimeS,   // loop-closure compute time of a run (s)
  kWifiOverheadS,      // Wi-Fi clustering + cluster management of a run (s)
  kFrames,             // images in the dataset
  kKeyframes,          // keyframes of a run (RTAB-Map: its nodes)
  kAccessPoints,       // access points of the building
  kWifiClusters,       // Wi-Fi clusters of a run
  kTimeSavingPct,      // Wi-Fi's saving of a time, % of vanilla's
  kErrorReductionPct,  // Wi-Fi's reduction of the trajectory error, % of vanilla's
  kOverheadSharePct,   // Wi-Fi overhead, % of vanilla's loop-closure time
  kAccuracyGainPct,    // the abstract's accuracy improvement, mean over the paper's runs
  kQueriesWithinPct,   // localisation: % of query images within a distance
};
const char* to_string(Quantity quantity);  // "ate_rmse_m", ...
/// The unit printed after a value ("m", "%", "s", "").
const char* unit_of(Quantity quantity);

enum class Variant { kVanilla, kWifi, kEither };
const char* to_string(Variant variant);  // "vanilla", "wifi", ""

/// How the paper states it: a value, or a bound in words ("more than 50 %", "less than 40",
/// "15%-25%", "about 3%-8%"). An approximate range is judged as a range.
enum class Bound { kEqual, kAbout, kMoreThan, kLessThan, kRange, kAboutRange };
/// Whether the bound has an upper end (`value_high`).
inline bool is_range(Bound bound) { return bound == Bound::kRange || bound == Bound::kAboutRange; }

struct PaperNumber {
  Part part = Part::kDatasets;
  /// The table's LaTeX label ("table:rtabmap_rmse") or the passage's section ("sec:eval,
  /// Datasets"): where to find it in the paper.
  std::string source;
  /// The table's caption, or the paper's words that state the number (verbatim).
  std::string words;
  std::string twin;     // "a_hall", "b_hall", "c_hall", "j_hall"; "" for an aggregate
  std::string setting;  // the swept option and its value ("time_threshold_ms=70"); "" for none
  Variant variant = Variant::kEither;
  Quantity quantity = Quantity::kAteRmseM;
  Bound bound = Bound::kEqual;
  double value = 0.0;
  double value_high = 0.0;  // a range's upper end (is_range); else `value`
  /// A table cell as printed ("0.2304"); empty for a number of the text.
  std::string printed;
  /// A claim of every run ("no false positives in either approach", "less than 20", "gets rid
  /// of all false loop closures"): judged on the worst seed, whose value is already the largest
  /// of its runs, not on the mean (one seed against the claim misses it).
  bool every_run = false;
  /// A short stable key: source, twin, setting and variant ("table:rtabmap_rmse/a_hall/
  /// time_threshold_ms=70/wifi").
  std::string key() const;
};

/// A table of the paper as printed: one LaTeX row per building, and per column the setting and
/// variant it holds.
struct PaperTable {
  std::string label, caption;
  Part part = Part::kDatasets;
  Quantity quantity = Quantity::kAteRmseM;
  std::string setting_key;            // "time_threshold_ms", "min_matches"
  std::vector<std::string> settings;  // the column groups, in the paper's order
  std::vector<Variant> variants;      // the columns of each group
  std::vector<std::string> rows;      // "A Hall & 0.2304 & ...", verbatim
};

/// The paper's eight tables (RTAB-Map: 4, ORB-SLAM: 4), as printed.
const std::vector<PaperTable>& paper_tables();

/// Every number: the tables' cells, then the numbers of the text and abstract. Throws
/// std::logic_error when a table row does not parse (a typing error in this file).
const std::vector<PaperNumber>& paper_numbers();

/// The paper's name of a twin's building ("A Hall") and back.
std::string hall_name(const std::string& twin);

}  // namespace wifislam::study::paper
