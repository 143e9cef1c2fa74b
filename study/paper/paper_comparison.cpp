#include "study/paper/paper_comparison.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>

#include <fmt/format.h>

#include "study/paper/paper_plan.hpp"

namespace wifislam::study::paper {

namespace {

const char* column_of(Quantity q) {
  switch (q) {
    case Quantity::kAteRmseM:
      return "ate_rmse_m";
    case Quantity::kFalseNegativePct:
      return "false_negative_pct";
    case Quantity::kFalsePositivePct:
      return "false_positive_pct";
    case Quantity::kLoopClosureTimeS:
      return "paper_loop_closure_s";
    case Quantity::kWifiOverheadS:
      return "wifi_overhead_s";
    case Quantity::kKeyframes:
      return "keyframes";
    case Quantity::kWifiClusters:
      return "wifi_clusters";
    default:
      return "";
  }
}

/// A cell of one of the paper's tables (not a number of its text or of a table's caption).
bool is_table(const PaperNumber& n) {
  for (const PaperTable& t : paper_tables())
    if (t.label == n.source) return !n.twin.empty();
  return false;
}

/// The paper's number of the same table (or `source`), twin and setting, of `variant`.
const PaperNumber* find_number(const std::string& source, const std::string& twin,
                               const std::string& setting, Variant variant) {
  for (const PaperNumber& n : paper_numbers()) {
    if (n.source == source && n.twin == twin && n.setting == setting && n.variant == variant) {
      return &n;
    }
  }
  return nullptr;
}

/// The seed's index among a twin's seeds (its own seed is 0): runs of different twins with the
/// same index belong to the same repetition of the experiment.
std::int64_t seed_index(const std::string& twin, std::uint64_t seed) {
  return static_cast<std::int64_t>(seed) - static_cast<std::int64_t>(twin_scene(twin).seed);
}

/// Per seed index, the mean over `cells` of `value(vanilla row, wifi row)` (NaN skipped).
Measured mean_over_cells(
    const PaperMeasurements& m, Part part, const std::vector<std::string>& twins,
    const std::function<double(const RunRow& vanilla, const RunRow& wifi)>& value) {
  std::map<std::int64_t, std::pair<double, int>> sums;
  for (const std::string& twin : twins) {
    for (const std::string& setting : m.settings(part, twin)) {
      const auto vanilla = m.runs(part, twin, setting, false);
      for (const RunRow* w : m.runs(part, twin, setting, true)) {
        for (const RunRow* v : vanilla) {
          if (v->seed != w->seed) continue;
          const double x = value(*v, *w);
          if (std::isnan(x)) continue;
          auto& [sum, n] = sums[seed_index(twin, w->seed)];
          sum += x;
          ++n;
        }
      }
    }
  }
  Measured out;
  for (const auto& [k, sum_n] : sums) out.per_seed.push_back(sum_n.first / sum_n.second);
  return out;
}

/// 100 (1 - wifi / vanilla) of one column: Wi-Fi's relative saving.
std::function<double(const RunRow&, const RunRow&)> saving_pct(const std::string& column) {
  return [column](const RunRow& v, const RunRow& w) {
    const double a = v.value(column), b = w.value(column);
    return a > 0 ? 100.0 * (1.0 - b / a) : std::nan("");
  };
}

std::string mean_text(const Measured& m, int decimals) {
  return m.empty() ? "-" : fmt::format("{:.{}f}", m.mean(), decimals);
}

/// What the runs of a cell did, for the reader of a departure.
std::string cell_context(const PaperMeasurements& m, Part part, const std::string& twin,
                         const std::string& setting) {
  const auto [ev, ew] = m.paired(part, twin, setting, "revisit_episodes");
  if (ev.empty()) return "not run";
  const auto [cv, cw] = m.paired(part, twin, setting, "scored_closures");
  const auto [wv, ww] = m.paired(part, twin, setting, "wrong_place_closures");
  const auto [fv, fw] = m.paired(part, twin, setting, "false_negatives");
  return fmt::format(
      "revisit episodes {}; loop closures vanilla {} / Wi-Fi {} (wrong place {} / {}); episodes "
      "missed {} / {} (means over {} seed{})",
      mean_text(ev, 1), mean_text(cv, 1), mean_text(cw, 1), mean_text(wv, 1), mean_text(ww, 1),
      mean_text(fv, 1), mean_text(fw, 1), ev.per_seed.size(), ev.per_seed.size() == 1 ? "" : "s");
}

ComparedNumber table_cell(const PaperNumber& n, const PaperMeasurements& m) {
  ComparedNumber c;
  c.paper = &n;
  const std::string setting = run_setting(n);
  c.context = cell_context(m, n.part, n.twin, setting);
  if (n.quantity == Quantity::kWifiOverheadS) {
    // Share of vanilla's loop-closure time, paired by seed; the paper's from its bounding table.
    const std::string bounding = fmt::format("table:{}_bounding", to_string(n.part));
    const PaperNumber* pv = find_number(bounding, n.twin, n.setting, Variant::kVanilla);
    const PaperNumber* pw = find_number(bounding, n.twin, n.setting, Variant::kWifi);
    const auto [vanilla_lc, wifi_lc] = m.paired(n.part, n.twin, setting, "paper_loop_closure_s");
    c.ours = m.column(n.part, n.twin, setting, true, "wifi_overhead_s");
    Measured share;
    for (std::size_t i = 0; i < std::min(c.ours.per_seed.size(), vanilla_lc.per_seed.size()); ++i) {
      if (vanilla_lc.per_seed[i] > 0) {
        share.per_seed.push_back(c.ours.per_seed[i] / vanilla_lc.per_seed[i]);
      }
    }
    if (pv == nullptr || pw == nullptr || share.empty()) {
      c.judgement = {Verdict::kNotApplicable, "not measured"};
      return c;
    }
    const bool our_below = c.ours.mean() < vanilla_lc.mean() - wifi_lc.mean();
    c.judgement =
        judge_overhead(n.value / pv->value, n.value < pv->value - pw->value, share, our_below);
    return c;
  }
  const std::string column = column_of(n.quantity);
  if (n.quantity == Quantity::kFalsePositivePct && n.variant == Variant::kVanilla &&
      find_number(n.source, n.twin, n.setting, Variant::kWifi) == nullptr) {
    c.ours = m.column(n.part, n.twin, setting, false, column);
    c.judgement = judge_value(n, c.ours);
    return c;
  }
  const PaperNumber* vanilla = find_number(n.source, n.twin, n.setting, Variant::kVanilla);
  const PaperNumber* wifi = find_number(n.source, n.twin, n.setting, Variant::kWifi);
  const auto [ours_v, ours_w] = m.paired(n.part, n.twin, setting, column);
  c.ours = n.variant == Variant::kWifi ? ours_w : ours_v;
  if (n.quantity == Quantity::kFalseNegativePct) {
    const Measured episodes = m.column(n.part, n.twin, setting, false, "revisit_episodes");
    if (!episodes.empty() && episodes.max() == 0) {
      c.judgement = {Verdict::kNotApplicable,
                     "no revisit episode on our twin's route: nothing to miss"};
      return c;
    }
  }
  c.judgement = judge_pair(n, vanilla->value, wifi->value, ours_v, ours_w);
  return c;
}

/// Per seed index, the largest value of `column` over the runs of `variant` on `twins` whose
/// setting `counts`: the paper's "none in any setting" and "less than 20 in both". With
/// `episodes_only`, a run on a route without a revisit episode (nothing to miss) is left out.
Measured largest_over_runs(const PaperMeasurements& m, Part part,
                           const std::vector<std::string>& twins,
                           const std::function<bool(const std::string& setting)>& counts, bool wifi,
                           const std::string& column, bool episodes_only) {
  std::map<std::int64_t, double> largest;
  for (const std::string& twin : twins) {
    for (const std::string& setting : m.settings(part, twin)) {
      if (!counts(setting)) continue;
      for (const RunRow* r : m.runs(part, twin, setting, wifi)) {
        if (episodes_only && !(r->value("revisit_episodes") > 0)) continue;
        const double x = r->value(column);
        if (std::isnan(x)) continue;
        auto [it, added] = largest.emplace(seed_index(twin, r->seed), x);
        if (!added) it->second = std::max(it->second, x);
      }
    }
  }
  Measured out;
  for (const auto& [k, x] : largest) out.per_seed.push_back(x);
  return out;
}

/// A per-seed value of one twin's dataset record.
Measured dataset_value(const PaperMeasurements& m, const std::string& twin,
                       const std::function<double(const nlohmann::json&)>& value) {
  Measured out;
  const auto it = m.datasets().find(twin);
  if (it == m.datasets().end()) return out;
  for (const auto& [seed, facts] : it->second) out.per_seed.push_back(value(facts));
  return out;
}

/// The Wi-Fi clusters of a twin: RTAB-Map's Wi-Fi run at no threshold, else any Wi-Fi run.
Measured clusters_of(const PaperMeasurements& m, const std::string& twin, std::string& which) {
  Measured out = m.column(Part::kRtabmap, twin, "time_threshold_ms=inf", true, "wifi_clusters");
  which = "RTAB-Map's Wi-Fi runs at no time threshold";
  if (!out.empty()) return out;
  for (Part part : {Part::kOrbslam, Part::kRgbdslam}) {
    for (const std::string& setting : m.settings(part, twin)) {
      out = m.column(part, twin, setting, true, "wifi_clusters");
      if (!out.empty()) {
        which = fmt::format("{}'s Wi-Fi runs at {}", to_string(part), setting);
        return out;
      }
    }
  }
  return out;
}

ComparedNumber text_number(const PaperNumber& n, const PaperMeasurements& m) {
  ComparedNumber c;
  c.paper = &n;
  const std::string setting = run_setting(n);
  const std::vector<std::string> bcj = {"b_hall", "c_hall", "j_hall"};
  const std::vector<std::string> all_twins = {"a_hall", "b_hall", "c_hall", "j_hall"};
  switch (n.part) {
    case Part::kDatasets:
      if (n.quantity == Quantity::kFrames) {
        c.ours = dataset_value(
            m, n.twin, [](const nlohmann::json& j) { return j.value("duration_s", 0.0) * 30.0; });
        c.context = "our route's duration x 30 fps (the paper's Kinect rate)";
      } else if (n.quantity == Quantity::kAccessPoints) {
        c.ours = dataset_value(
            m, n.twin, [](const nlohmann::json& j) { return j.value("access_points", 0.0); });
      } else {
        std::string which;
        c.ours = clusters_of(m, n.twin, which);
        c.context = which;
      }
      break;
    case Part::kRgbdslam: {
      const auto [ate_v, ate_w] = m.paired(n.part, n.twin, setting, "ate_rmse_m");
      c.context = cell_context(m, n.part, n.twin, setting);
      if (n.quantity == Quantity::kFalsePositivePct) {
        c.ours = m.column(n.part, n.twin, setting, true, "false_positive_pct");
      } else {
        const std::string column =
            n.quantity == Quantity::kTimeSavingPct ? "paper_loop_closure_s" : "ate_rmse_m";
        const auto [v, w] = m.paired(n.part, n.twin, setting, column);
        for (std::size_t i = 0; i < v.per_seed.size(); ++i) {
          if (v.per_seed[i] > 0)
            c.ours.per_seed.push_back(100.0 * (1 - w.per_seed[i] / v.per_seed[i]));
        }
      }
      break;
    }
    case Part::kRtabmap:
      if (n.quantity == Quantity::kKeyframes) {
        c.ours = m.column(n.part, n.twin, "time_threshold_ms=inf", false, "keyframes");
        c.context = "our vanilla run's nodes at no time threshold; the paper's datasets are longer";
      } else if (n.quantity == Quantity::kFalsePositivePct) {
        c.ours = largest_over_runs(
            m, n.part, all_twins, [](const std::string&) { return true; },
            n.variant == Variant::kWifi, "false_positive_pct", false);
        c.context = fmt::format("the largest {} wrong-place % over the twins and thresholds",
                                n.variant == Variant::kWifi ? "Wi-Fi" : "vanilla");
      } else {  // false negatives at one threshold
        c.ours = largest_over_runs(
            m, n.part, all_twins, [&](const std::string& s) { return s == setting; },
            n.variant == Variant::kWifi, "false_negative_pct", true);
        c.context = fmt::format(
            "the largest {} false negative % over the twins at {}, of runs whose route revisits "
            "a place",
            n.variant == Variant::kWifi ? "Wi-Fi" : "vanilla", setting);
      }
      break;
    case Part::kOrbslam:
      if (n.quantity == Quantity::kTimeSavingPct) {
        c.ours = mean_over_cells(m, Part::kOrbslam, bcj, saving_pct("paper_loop_closure_s"));
        c.context = "mean over B, C and J Hall and min-matches of Wi-Fi's relative saving";
      } else if (n.quantity == Quantity::kOverheadSharePct) {
        c.ours = mean_over_cells(m, Part::kOrbslam, bcj, [](const RunRow& v, const RunRow& w) {
          const double lc = v.value("paper_loop_closure_s");
          return lc > 0 ? 100.0 * w.value("wifi_overhead_s") / lc : std::nan("");
        });
        c.context = "mean over B, C and J Hall and min-matches of overhead / vanilla's time";
      } else if (n.quantity == Quantity::kFalsePositivePct) {
        c.ours = largest_over_runs(
            m, Part::kOrbslam, bcj, [](const std::string&) { return true; }, true,
            "false_positive_pct", false);
        c.context = "the largest Wi-Fi wrong-place % over B, C and J Hall and min-matches";
      } else if (n.quantity == Quantity::kFalseNegativePct) {
        // "except for min-match=100": the settings below it.
        c.ours = largest_over_runs(
            m, Part::kOrbslam, bcj, [](const std::string& s) { return s != "min_matches=100"; },
            n.variant == Variant::kWifi, "false_negative_pct", true);
        c.context = fmt::format(
            "the largest {} false negative % over B, C and J Hall and min-matches below 100, of "
            "runs whose route revisits a place",
            n.variant == Variant::kWifi ? "Wi-Fi" : "vanilla");
      } else {  // keyframes
        std::map<std::int64_t, std::pair<double, int>> sums;
        for (const std::string& s : m.settings(Part::kOrbslam, n.twin)) {
          if (!setting.empty() && s != setting) continue;
          for (bool wifi : {false, true}) {
            for (const RunRow* r : m.runs(Part::kOrbslam, n.twin, s, wifi)) {
              auto& [sum, count] = sums[seed_index(n.twin, r->seed)];
              sum += r->value("keyframes");
              ++count;
            }
          }
        }
        for (const auto& [k, sn] : sums) c.ours.per_seed.push_back(sn.first / sn.second);
        c.context = "mean of our vanilla and Wi-Fi runs' keyframes; the paper's runs are at 30 fps";
      }
      break;
    case Part::kFabmap: {
      const auto it = m.localisations().find(n.twin);
      if (it != m.localisations().end()) {
        for (const auto& [seed, summary] : it->second) {
          for (const auto& method : summary.value("methods", nlohmann::json::array())) {
            if (method.value("method", "") == "wifi-clusters") {
              c.ours.per_seed.push_back(100.0 * method["all"].value("within_4m", 0.0));
            }
          }
        }
      }
      c.context = "ours (wifi-clusters): share of every query image within 4 m";
      break;
    }
    case Part::kAbstract:
      if (n.quantity == Quantity::kAccuracyGainPct) {
        c.ours = mean_over_cells(m, Part::kRtabmap, all_twins, saving_pct("ate_rmse_m"));
        c.context =
            "mean over RTAB-Map's twin x threshold cells of Wi-Fi's relative reduction of "
            "the trajectory error";
      } else {
        c.ours = mean_over_cells(m, Part::kOrbslam, bcj, saving_pct("paper_loop_closure_s"));
        c.context = "ORB-SLAM's mean relative saving of loop-closure time (B, C, J Hall)";
      }
      break;
  }
  c.judgement = judge_value(n, c.ours);
  return c;
}

}  // namespace

std::string run_setting(const PaperNumber& number) {
  if (number.part == Part::kRgbdslam && !number.setting.empty()) {
    return number.setting + " inlier_distance=3";
  }
  return number.setting;
}

std::vector<ComparedNumber> compare_with_paper(const PaperMeasurements& ours) {
  std::vector<ComparedNumber> out;
  for (const PaperNumber& n : paper_numbers()) {
    out.push_back(is_table(n) ? table_cell(n, ours) : text_number(n, ours));
    if (out.back().ours.empty() && out.back().judgement.verdict != Verdict::kNotApplicable) {
      out.back().judgement = {Verdict::kNotApplicable, "not run"};
    }
    if (out.back().ours.empty() && out.back().judgement.why == "not measured") {
      out.back().judgement.why = "not run";
    }
  }
  return out;
}

}  // namespace wifislam::study::paper
