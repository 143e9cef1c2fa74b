#include "study/paper/paper_numbers.hpp"

#include <charconv>
#include <map>
#include <stdexcept>

#include <fmt/format.h>

namespace wifislam::study::paper {

namespace {

constexpr Variant kV = Variant::kVanilla, kW = Variant::kWifi;

// The paper's tables, their LaTeX rows copied as printed (../shared/paper/, section "Evaluation").
// Threshold "inf" is the paper's $\infty$ (no threshold: Rtabmap/TimeThr off).
const std::vector<PaperTable> kTables = {
    {"table:rtabmap_rmse",
     "RTAB-Map: Trajectory error (m) for different datasets and different real-time thresholds",
     Part::kRtabmap,
     Quantity::kAteRmseM,
     "time_threshold_ms",
     {"inf", "70", "100", "200"},
     {kV, kW},
     {"A Hall & 0.2304 & 0.2284 & 0.4895 & 0.2537 & 0.4894 & 0.2846 & 0.2329 & 0.2074",
      "B Hall & 0.2424 & 0.2262 & 0.1284 & 0.2219 & 0.1284 & 0.2219 & 0.1924 & 0.2200",
      "C Hall & 0.1280 & 0.1100 & 0.1198 & 0.1005 & 0.1198 & 0.1005 & 0.1149 & 0.1416",
      "J Hall & 0.3030 & 0.2113 & 1.3472 & 0.1945 & 1.3472 & 0.1999 & 0.2300 & 0.2132"}},
    {"table:rtabmap_false_negative",
     "RTAB-Map: False negative loop closures for different datasets and different real-time "
     "thresholds",
     Part::kRtabmap,
     Quantity::kFalseNegativePct,
     "time_threshold_ms",
     {"inf", "70", "100", "200"},
     {kV, kW},
     {"A Hall & 0.0000 & 4.4444 & 100.0000 & 17.7778 & 100.0000 & 31.1111 & 11.1111 & 13.3333",
      "B Hall & 8.0000 & 16.0000 & 100.0000 & 0.0000 & 100.0000 & 0.0000 & 6.0000 & 12.0000",
      "C Hall & 6.0606 & 0.0000 & 100.0000 & 9.0909 & 100.0000 & 9.0909 & 27.2727 & 3.0303",
      "J Hall & 9.0909 & 9.0909 & 100.0000 & 13.6364 & 100.0000 & 40.9091 & 0.0000 & 9.0909"}},
    {"table:rtabmap_bounding",
     "RTAB-Map: Loop closure compute time (s) for different datasets with different real-time "
     "thresholds",
     Part::kRtabmap,
     Quantity::kLoopClosureTimeS,
     "time_threshold_ms",
     {"inf", "70", "100", "200"},
     {kV, kW},
     {"A Hall & 7.1138 & 2.3583 & 3.5781 & 5.0573 & 3.7496 & 5.0254 & 6.9523 & 3.9910",
      "B Hall & 2.3625 & 0.6308 & 4.6772 & 1.8588 & 4.9314 & 1.8833 & 2.6194 & 1.6994",
      "C Hall & 1.6906 & 0.6270 & 4.9086 & 1.6675 & 4.7170 & 1.6749 & 3.5015 & 1.3807",
      "J Hall & 4.7277 & 0.8036 & 7.5797 & 2.6016 & 6.7597 & 2.6482 & 4.4986 & 2.8115"}},
    {"table:rtabmap_overhead",
     "RTAB-Map: Compute overheadi (s) of Wi-Fi clustering and cluster management for different "
     "datasets and different real-time thresholds",
     Part::kRtabmap,
     Quantity::kWifiOverheadS,
     "time_threshold_ms",
     {"inf", "70", "100", "200"},
     {kW},
     {"A Hall & 0.3208 & 0.3411 & 0.3432 & 0.3314", "B Hall & 0.2129 & 0.2230 & 0.2203 & 0.2170",
      "C Hall & 0.1701 & 0.1795 & 0.1804 & 0.1683", "J Hall & 0.5633 & 0.6351 & 0.6261 & 0.6261"}},
    {"table:orbslam_rmse",
     "ORB-SLAM: Trajectory error (m) of different datasets and different min-matches values",
     Part::kOrbslam,
     Quantity::kAteRmseM,
     "min_matches",
     {"10", "15", "20", "50", "100"},
     {kV, kW},
     {"B Hall & 10.9616 & 0.2150 & 10.0935 & 0.2322 & 0.2513 & 0.2363 & 0.2111 & 0.2002 & 0.4189 "
      "& 0.4551",
      "C Hall & 12.2219 & 0.1656 & 13.5045 & 0.1552 & 0.1177 & 0.0986 & 0.2129 & 0.2057 & 0.3366 "
      "& 0.3807",
      "J Hall & 0.8638 & 0.8616 & 0.8234 & 0.7394 & 0.7407 & 0.6680 & 0.8564 & 0.7793 & 2.7230 & "
      "2.8420"}},
    {"table:orbslam_bounding",
     "ORB-SLAM: Loop closure compute time (s) for different datasets and different min-matches "
     "values. Our method reduces this time by 15%-25% on average.",
     Part::kOrbslam,
     Quantity::kLoopClosureTimeS,
     "min_matches",
     {"10", "15", "20", "50", "100"},
     {kV, kW},
     {"B Hall & 10.0983 & 7.0450 & 9.6854 & 7.2903 & 9.1030 & 6.5061 & 8.9114 & 7.1104 & 9.2383 & "
      "7.6964",
      "C Hall & 19.0397 & 16.4959 & 19.6789 & 15.9019 & 21.1756 & 18.8478 & 18.2757 & 15.7806 & "
      "18.5043 & 15.5856",
      "J Hall & 25.2880 & 19.6396 & 25.3739 & 20.0801 & 24.9643 & 19.9932 & 25.3299 & 20.3225 & "
      "24.6863 & 19.7924"}},
    {"table:orbslam_overhead",
     "ORB-SLAM:Compute overhead (s) of Wi-Fi Clustering and Cluster Management modules for "
     "different datasets and min-matches values. It is about 3%-8% on average.",
     Part::kOrbslam,
     Quantity::kWifiOverheadS,
     "min_matches",
     {"10", "15", "20", "50", "100"},
     {kW},
     {"B Hall & 0.4231 & 0.4638 & 0.4115 & 0.4543 & 0.5344",
      "C Hall & 0.4929 & 0.3961 & 0.4498 & 0.6529 & 0.4667",
      "J Hall & 1.7542 & 1.6599 & 1.5999 & 1.7060 & 1.7701"}},
    {"table:orbslam_false_positive",
     "ORB-SLAM: Percentage false positive loop closures for different datasets and different "
     "min-matches values. Our method has zero false positives and is therefore not shown in the "
     "table.",
     Part::kOrbslam,
     Quantity::kFalsePositivePct,
     "min_matches",
     {"10", "15", "20", "50", "100"},
     {kV},
     {"B Hall & 40.0000 & 33.3000 & 0.0000 & 0.0000 & 0.0000",
      "C Hall & 50.0000 & 50.0000 & 0.0000 & 0.0000 & 0.0000",
      "J Hall & 0.0000 & 0.0000 & 0.0000 & 0.0000 & 0.0000"}},
};

/// A number the text states: its passage, the paper's words (verbatim, LaTeX markup removed),
/// and what it says.
PaperNumber text_number(Part part, std::string source, std::string words, std::string twin,
                        std::string setting, Variant variant, Quantity quantity, Bound bound,
                        double value, double value_high = 0.0) {
  PaperNumber n;
  n.part = part;
  n.source = std::move(source);
  n.words = std::move(words);
  n.twin = std::move(twin);
  n.setting = std::move(setting);
  n.variant = variant;
  n.quantity = quantity;
  n.bound = bound;
  n.value = value;
  n.value_high = is_range(bound) ? value_high : value;
  return n;
}

/// `n` as a claim of every run (PaperNumber::every_run).
PaperNumber of_every_run(PaperNumber n) {
  n.every_run = true;
  return n;
}

std::vector<PaperNumber> text_numbers() {
  constexpr auto E = Variant::kEither;
  const std::string datasets = "subsec:dataset";
  const char* c_hall =
      "There are 24000 images, less than 40 APs and a total of 7 Wi-Fi clusters in this dataset.";
  const char* b_hall =
      "There are 28000 images, about 40 APs and 13 Wi-Fi clusters in this dataset.";
  const char* j_hall =
      "There are a total of 19 Wi-Fi clusters, around 70 APs and 33000 images in this dataset.";
  const char* a_hall =
      "The number of frames, APs and Wi-Fi clusters are 50000, 45 and 8 respectively.";
  const std::string rgbd = "RGBD SLAM performance";
  const std::string rtab = "RTAB-Map performance";
  const std::string orb = "ORB-SLAM performance";
  const char* rgbd_fp =
      "Results show that our proposed method gets rid of all false loop closures for both "
      "settings.";
  const char* rgbd_time =
      "we reduce the computation time of affected modules by bounding loop closure by more than "
      "50% for min-match=50 and more than 30% for min-match=70.";
  const char* rgbd_rmse =
      "Finally, we also observe a reduction in RMS error of 80% for min-matches \u2208 (50, 70).";
  const char* rtab_nodes =
      "So although B dataset has a higher number of clusters than A dataset, it has a lower "
      "computation overhead due to less number of frames (748 compared to 1270).";
  const char* rtab_fn =
      "For real-time threshold=200 and real-time threshold=\u221e, the percentage of false "
      "negatives of both approaches is less than 20.";
  const char* rtab_fp =
      "Since there are no false positive loop closures detected in either approach in RTAB-Map, "
      "no results are shown.";
  const char* orb_fn =
      "Also, there are no false negatives observed in any settings except for min-match=100 which "
      "is equal for both approaches.";
  const char* orb_saving =
      "we spend less time (15%-25% on average) for loop closure detection resulting in faster "
      "execution.";
  const char* orb_keyframes_j =
      "J dataset has a little more overhead due to more number of keyframes(about 2800) and 19 "
      "Wi-Fi clusters.";
  const char* orb_keyframes_bc =
      "For example for min-matches=50, the respective keyframes of B and C datasets are 1200 and "
      "1500.";
  const char* orb_wifi_fp =
      "Our approach using Wi-Fi does not incur any false positives for loop closure detection and "
      "is therefore not shown in the table.";
  const char* fabmap_a =
      "But we do note that even under these circumstances, more than 90% of the query images are "
      "within 4 meters accuracy which is similar to Wi-Fi augmented FABMAP.";
  const char* abstract =
      "Overall, we show that our approach can improve the accuracy of visual SLAM algorithms by "
      "11% on average and reduce computation time on average by 15% to 25%.";
  return {
      text_number(Part::kDatasets, datasets, c_hall, "c_hall", "", E, Quantity::kFrames,
                  Bound::kEqual, 24000),
      text_number(Part::kDatasets, datasets, c_hall, "c_hall", "", E, Quantity::kAccessPoints,
                  Bound::kLessThan, 40),
      text_number(Part::kDatasets, datasets, c_hall, "c_hall", "", E, Quantity::kWifiClusters,
                  Bound::kEqual, 7),
      text_number(Part::kDatasets, datasets, b_hall, "b_hall", "", E, Quantity::kFrames,
                  Bound::kEqual, 28000),
      text_number(Part::kDatasets, datasets, b_hall, "b_hall", "", E, Quantity::kAccessPoints,
                  Bound::kAbout, 40),
      text_number(Part::kDatasets, datasets, b_hall, "b_hall", "", E, Quantity::kWifiClusters,
                  Bound::kEqual, 13),
      text_number(Part::kDatasets, datasets, j_hall, "j_hall", "", E, Quantity::kWifiClusters,
                  Bound::kEqual, 19),
      text_number(Part::kDatasets, datasets, j_hall, "j_hall", "", E, Quantity::kAccessPoints,
                  Bound::kAbout, 70),
      text_number(Part::kDatasets, datasets, j_hall, "j_hall", "", E, Quantity::kFrames,
                  Bound::kEqual, 33000),
      text_number(Part::kDatasets, datasets, a_hall, "a_hall", "", E, Quantity::kFrames,
                  Bound::kEqual, 50000),
      text_number(Part::kDatasets, datasets, a_hall, "a_hall", "", E, Quantity::kAccessPoints,
                  Bound::kEqual, 45),
      text_number(Part::kDatasets, datasets, a_hall, "a_hall", "", E, Quantity::kWifiClusters,
                  Bound::kEqual, 8),
      of_every_run(text_number(Part::kRgbdslam, rgbd, rgbd_fp, "c_hall", "min_matches=50",
                               Variant::kWifi, Quantity::kFalsePositivePct, Bound::kEqual, 0)),
      of_every_run(text_number(Part::kRgbdslam, rgbd, rgbd_fp, "c_hall", "min_matches=70",
                               Variant::kWifi, Quantity::kFalsePositivePct, Bound::kEqual, 0)),
      text_number(Part::kRgbdslam, rgbd, rgbd_time, "c_hall", "min_matches=50", E,
                  Quantity::kTimeSavingPct, Bound::kMoreThan, 50),
      text_number(Part::kRgbdslam, rgbd, rgbd_time, "c_hall", "min_matches=70", E,
                  Quantity::kTimeSavingPct, Bound::kMoreThan, 30),
      text_number(Part::kRgbdslam, rgbd, rgbd_rmse, "c_hall", "min_matches=50", E,
                  Quantity::kErrorReductionPct, Bound::kEqual, 80),
      text_number(Part::kRgbdslam, rgbd, rgbd_rmse, "c_hall", "min_matches=70", E,
                  Quantity::kErrorReductionPct, Bound::kEqual, 80),
      // The paper calls them frames: RTAB-Map's nodes (frames kept at Rtabmap/DetectionRate).
      text_number(Part::kRtabmap, rtab, rtab_nodes, "b_hall", "", E, Quantity::kKeyframes,
                  Bound::kEqual, 748),
      text_number(Part::kRtabmap, rtab, rtab_nodes, "a_hall", "", E, Quantity::kKeyframes,
                  Bound::kEqual, 1270),
      // Over all four twins: the largest value of a run (per seed) must meet the bound.
      of_every_run(text_number(Part::kRtabmap, rtab, rtab_fn, "", "time_threshold_ms=200",
                               Variant::kVanilla, Quantity::kFalseNegativePct, Bound::kLessThan,
                               20)),
      of_every_run(text_number(Part::kRtabmap, rtab, rtab_fn, "", "time_threshold_ms=200",
                               Variant::kWifi, Quantity::kFalseNegativePct, Bound::kLessThan, 20)),
      of_every_run(text_number(Part::kRtabmap, rtab, rtab_fn, "", "time_threshold_ms=inf",
                               Variant::kVanilla, Quantity::kFalseNegativePct, Bound::kLessThan,
                               20)),
      of_every_run(text_number(Part::kRtabmap, rtab, rtab_fn, "", "time_threshold_ms=inf",
                               Variant::kWifi, Quantity::kFalseNegativePct, Bound::kLessThan, 20)),
      of_every_run(text_number(Part::kRtabmap, rtab, rtab_fp, "", "", Variant::kVanilla,
                               Quantity::kFalsePositivePct, Bound::kEqual, 0)),
      of_every_run(text_number(Part::kRtabmap, rtab, rtab_fp, "", "", Variant::kWifi,
                               Quantity::kFalsePositivePct, Bound::kEqual, 0)),
      text_number(Part::kOrbslam, orb, orb_saving, "", "", E, Quantity::kTimeSavingPct,
                  Bound::kRange, 15, 25),
      text_number(Part::kOrbslam, "table:orbslam_overhead, caption",
                  "It is about 3%-8% on average.", "", "", Variant::kWifi,
                  Quantity::kOverheadSharePct, Bound::kAboutRange, 3, 8),
      text_number(Part::kOrbslam, orb, orb_keyframes_j, "j_hall", "", E, Quantity::kKeyframes,
                  Bound::kAbout, 2800),
      text_number(Part::kOrbslam, orb, orb_keyframes_bc, "b_hall", "min_matches=50", E,
                  Quantity::kKeyframes, Bound::kEqual, 1200),
      text_number(Part::kOrbslam, orb, orb_keyframes_bc, "c_hall", "min_matches=50", E,
                  Quantity::kKeyframes, Bound::kEqual, 1500),
      of_every_run(text_number(Part::kOrbslam, orb, orb_wifi_fp, "", "", Variant::kWifi,
                               Quantity::kFalsePositivePct, Bound::kEqual, 0)),
      // "which is equal for both approaches" at 100 states no number: the pair's own table row.
      of_every_run(text_number(Part::kOrbslam, orb, orb_fn, "", "", Variant::kVanilla,
                               Quantity::kFalseNegativePct, Bound::kEqual, 0)),
      of_every_run(text_number(Part::kOrbslam, orb, orb_fn, "", "", Variant::kWifi,
                               Quantity::kFalseNegativePct, Bound::kEqual, 0)),
      text_number(Part::kFabmap, "Comparison to Wi-Fi augmented FABMAP", fabmap_a, "a_hall", "",
                  Variant::kWifi, Quantity::kQueriesWithinPct, Bound::kMoreThan, 90),
      text_number(Part::kAbstract, "abstract", abstract, "", "", E, Quantity::kAccuracyGainPct,
                  Bound::kEqual, 11),
      text_number(Part::kAbstract, "abstract", abstract, "", "", E, Quantity::kTimeSavingPct,
                  Bound::kRange, 15, 25),
  };
}

/// "A Hall" -> "a_hall".
std::string twin_of_hall(const std::string& hall) {
  if (hall.size() != 6 || hall.substr(1) != " Hall") return "";
  return std::string(1, static_cast<char>(hall[0] - 'A' + 'a')) + "_hall";
}

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(' ');
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(' ') - first + 1);
}

std::vector<PaperNumber> table_numbers(const PaperTable& table) {
  std::vector<PaperNumber> out;
  for (const std::string& row : table.rows) {
    std::vector<std::string> cells;
    std::size_t start = 0;
    while (true) {
      const std::size_t amp = row.find('&', start);
      cells.push_back(trim(row.substr(start, amp == std::string::npos ? amp : amp - start)));
      if (amp == std::string::npos) break;
      start = amp + 1;
    }
    const std::string twin = twin_of_hall(cells.front());
    if (twin.empty() || cells.size() != 1 + table.settings.size() * table.variants.size()) {
      throw std::logic_error(fmt::format("{}: malformed row '{}'", table.label, row));
    }
    for (std::size_t s = 0; s < table.settings.size(); ++s) {
      for (std::size_t v = 0; v < table.variants.size(); ++v) {
        const std::string& text = cells[1 + s * table.variants.size() + v];
        PaperNumber n;
        n.part = table.part;
        n.source = table.label;
        n.words = table.caption;
        n.twin = twin;
        n.setting = table.setting_key + "=" + table.settings[s];
        n.variant = table.variants[v];
        n.quantity = table.quantity;
        const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), n.value);
        if (ec != std::errc() || end != text.data() + text.size()) {
          throw std::logic_error(fmt::format("{}: '{}' is not a number", table.label, text));
        }
        n.value_high = n.value;
        n.printed = text;
        out.push_back(std::move(n));
      }
    }
  }
  return out;
}

}  // namespace

const char* to_string(Part part) {
  switch (part) {
    case Part::kDatasets:
      return "datasets";
    case Part::kRgbdslam:
      return "rgbdslam";
    case Part::kRtabmap:
      return "rtabmap";
    case Part::kOrbslam:
      return "orbslam";
    case Part::kFabmap:
      return "fabmap";
    case Part::kAbstract:
      return "abstract";
  }
  return "";
}

std::optional<Part> parse_part(const std::string& text) {
  for (Part p : {Part::kDatasets, Part::kRgbdslam, Part::kRtabmap, Part::kOrbslam, Part::kFabmap,
                 Part::kAbstract}) {
    if (text == to_string(p)) return p;
  }
  return std::nullopt;
}

const char* to_string(Quantity quantity) {
  switch (quantity) {
    case Quantity::kAteRmseM:
      return "ate_rmse_m";
    case Quantity::kFalseNegativePct:
      return "false_negative_pct";
    case Quantity::kFalsePositivePct:
      return "false_positive_pct";
    case Quantity::kLoopClosureTimeS:
      return "loop_closure_time_s";
    case Quantity::kWifiOverheadS:
      return "wifi_overhead_s";
    case Quantity::kFrames:
      return "frames";
    case Quantity::kKeyframes:
      return "keyframes";
    case Quantity::kAccessPoints:
      return "access_points";
    case Quantity::kWifiClusters:
      return "wifi_clusters";
    case Quantity::kTimeSavingPct:
      return "time_saving_pct";
    case Quantity::kErrorReductionPct:
      return "error_reduction_pct";
    case Quantity::kOverheadSharePct:
      return "overhead_share_pct";
    case Quantity::kAccuracyGainPct:
      return "accuracy_gain_pct";
    case Quantity::kQueriesWithinPct:
      return "queries_within_4m_pct";
  }
  return "";
}

const char* unit_of(Quantity quantity) {
  switch (quantity) {
    case Quantity::kAteRmseM:
      return "m";
    case Quantity::kLoopClosureTimeS:
    case Quantity::kWifiOverheadS:
      return "s";
    case Quantity::kFrames:
    case Quantity::kKeyframes:
    case Quantity::kAccessPoints:
    case Quantity::kWifiClusters:
      return "";
    default:
      return "%";
  }
}

const char* to_string(Variant variant) {
  switch (variant) {
    case Variant::kVanilla:
      return "vanilla";
    case Variant::kWifi:
      return "wifi";
    case Variant::kEither:
      return "";
  }
  return "";
}

std::string PaperNumber::key() const {
  std::string k = source;
  for (const std::string* part : {&twin, &setting}) k += "/" + *part;
  k += std::string("/") + to_string(variant) + "/" + to_string(quantity);
  return k;
}

const std::vector<PaperTable>& paper_tables() { return kTables; }

const std::vector<PaperNumber>& paper_numbers() {
  static const std::vector<PaperNumber> numbers = [] {
    std::vector<PaperNumber> all;
    for (const PaperTable& table : kTables) {
      for (PaperNumber& n : table_numbers(table)) all.push_back(std::move(n));
    }
    for (PaperNumber& n : text_numbers()) all.push_back(std::move(n));
    return all;
  }();
  return numbers;
}

std::string hall_name(const std::string& twin) {
  if (twin.size() == 6 && twin.substr(1) == "_hall") {
    return std::string(1, static_cast<char>(twin[0] - 'a' + 'A')) + " Hall";
  }
  return twin;
}

}  // namespace wifislam::study::paper
