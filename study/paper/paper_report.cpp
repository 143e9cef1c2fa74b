#include "study/paper/paper_report.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/atomic_file.hpp"
#include "core/csv_field.hpp"
#include "study/paper/paper_figures.hpp"
#include "study/paper/paper_folder.hpp"
#include "study/paper/paper_plan.hpp"
#include "study/paper/paper_runner.hpp"

#ifndef WIFISLAM_VERSION
#define WIFISLAM_VERSION "unknown"
#endif

namespace wifislam::study::paper {

namespace {

namespace fs = std::filesystem;

int decimals_of(Quantity q) {
  switch (q) {
    case Quantity::kAteRmseM:
    case Quantity::kLoopClosureTimeS:
    case Quantity::kWifiOverheadS:
      return 3;
    case Quantity::kFrames:
    case Quantity::kKeyframes:
    case Quantity::kAccessPoints:
    case Quantity::kWifiClusters:
      return 0;
    default:
      return 1;
  }
}

std::string ours_text(const ComparedNumber& c) {
  if (c.ours.empty()) return "-";
  // Overhead: the seconds and the share the verdict compared are both in `why`.
  return c.ours.text(decimals_of(c.paper->quantity));
}

std::string verdict_word(Verdict v) {
  switch (v) {
    case Verdict::kReproduced:
      return "**reproduced**";
    case Verdict::kDirectionOnly:
      return "direction only";
    case Verdict::kDeparts:
      return "*departs*";
    case Verdict::kNotApplicable:
      return "n/a";
  }
  return "";
}

std::string cell_text(const std::string& s) {
  std::string out;
  for (char c : s) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

const char* part_title(Part part) {
  switch (part) {
    case Part::kDatasets:
      return "Datasets";
    case Part::kRgbdslam:
      return "RGBD-SLAM";
    case Part::kRtabmap:
      return "RTAB-Map";
    case Part::kOrbslam:
      return "ORB-SLAM";
    case Part::kFabmap:
      return "FAB-MAP";
    case Part::kAbstract:
      return "The abstract";
  }
  return "";
}

/// The paper's table in its layout: one row per building, one column per setting and variant;
/// each cell "paper → ours (verdict)".
std::string table_grid(const PaperTable& table, const std::vector<ComparedNumber>& compared) {
  std::string out = fmt::format(
      "**{}** (`{}`). Each cell: the paper's value → ours (mean over "
      "seeds), and the verdict.\n\n| building |",
      table.caption, table.label);
  std::string rule = "| --- |";
  for (const std::string& s : table.settings) {
    for (Variant v : table.variants) {
      out += fmt::format(" {} {} |", s, v == Variant::kVanilla ? "vanilla" : "Wi-Fi");
      rule += " --- |";
    }
  }
  out += "\n" + rule + "\n";
  for (const std::string& row : table.rows) {
    const std::string hall = row.substr(0, row.find('&') - 1);
    out += "| " + hall + " |";
    for (const std::string& s : table.settings) {
      for (Variant v : table.variants) {
        for (const ComparedNumber& c : compared) {
          const PaperNumber& n = *c.paper;
          if (n.source != table.label || hall_name(n.twin) != hall ||
              n.setting != table.setting_key + "=" + s || n.variant != v) {
            continue;
          }
          out += fmt::format(
              " {} → {} ({}) |", paper_value_text(n),
              c.ours.empty() ? "-" : fmt::format("{:.{}f}", c.ours.mean(), decimals_of(n.quantity)),
              verdict_word(c.judgement.verdict));
        }
      }
    }
    out += "\n";
  }
  return out + "\n";
}

/// Every number of a part, with why.
std::string detail_table(Part part, const std::vector<ComparedNumber>& compared) {
  std::string out =
      "| source | building | setting | variant | quantity | paper | ours | verdict | why | "
      "measured |\n| --- | --- | --- | --- | --- | ---: | ---: | --- | --- | --- |\n";
  for (const ComparedNumber& c : compared) {
    const PaperNumber& n = *c.paper;
    if (n.part != part) continue;
    out += fmt::format(
        "| `{}` | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n", n.source,
        n.twin.empty() ? "all" : hall_name(n.twin), n.setting.empty() ? "-" : n.setting,
        to_string(n.variant), to_string(n.quantity), paper_value_text(n), ours_text(c),
        verdict_word(c.judgement.verdict), cell_text(c.judgement.why), cell_text(c.context));
  }
  return out + "\n";
}

std::string counts_row(const std::string& name, const VerdictCounts& k) {
  return fmt::format("| {} | {} | {} | {} | {} | {} |\n", name, k.total(), k.reproduced,
                     k.direction_only, k.departs, k.not_applicable);
}

std::string quotes(const std::vector<ComparedNumber>& compared, Part part) {
  std::set<std::string> seen;
  std::string out;
  for (const ComparedNumber& c : compared) {
    const PaperNumber& n = *c.paper;
    const bool table_cell = n.source.rfind("table:", 0) == 0 && !n.source.ends_with("caption");
    if (n.part != part || table_cell || !seen.insert(n.words).second) {
      continue;
    }
    out += fmt::format("> {}\n>\n> — the paper, `{}`\n\n", n.words, n.source);
  }
  return out;
}

std::string page_header(Part part, const std::string& lead) {
  return fmt::format(
      "# {}: the paper beside our twins\n\n{}\n\n[Back to the report](report.md)\n\n",
      part_title(part), lead);
}

std::string figure_links(const std::vector<PaperFigure>& figures, Part part) {
  std::string out;
  for (const PaperFigure& f : figures) {
    if (f.part != part) continue;
    out += fmt::format("![{}]({})\n\n*{}*\n\n", f.caption, f.file, f.caption);
  }
  return out;
}

std::string seeds_line(const PaperMeasurements& m, Part part) {
  std::string out;
  for (const std::string& twin : twin_names()) {
    const auto seeds = m.seeds(part, twin);
    if (seeds.empty()) continue;
    out += fmt::format("{}{}: {} seed{} ({}-{})", out.empty() ? "" : "; ", hall_name(twin),
                       seeds.size(), seeds.size() == 1 ? "" : "s", seeds.front(), seeds.back());
  }
  return out.empty() ? "no runs" : out;
}

std::string datasets_page(const PaperMeasurements& m, const std::vector<ComparedNumber>& compared) {
  std::string out = page_header(
      Part::kDatasets,
      "The paper's four datasets as its section \"Datasets\" describes them, and our twins "
      "(scenes/*.yaml). Frames: the paper's are Kinect images at 30 fps; ours are compared as our "
      "route's duration at 30 fps, beside the frames our runs had at their frame rate.");
  out += quotes(compared, Part::kDatasets);
  out +=
      "| building | our frames (at our fps) | route duration (s) | pauses | Wi-Fi scans | APs "
      "heard per pause | pause pairs > 12 m apart that look alike | < 4 m apart that do | "
      "resolution (m) |\n| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n";
  for (const std::string& twin : twin_names()) {
    const auto it = m.datasets().find(twin);
    if (it == m.datasets().end()) continue;
    Measured frames, duration, pauses, scans, heard, far, near, resolution;
    double fps = 0;
    for (const auto& [seed, j] : it->second) {
      frames.per_seed.push_back(j.value("frames", 0.0));
      duration.per_seed.push_back(j.value("duration_s", 0.0));
      pauses.per_seed.push_back(j.value("pauses", 0.0));
      scans.per_seed.push_back(j.value("wifi_scans", 0.0));
      heard.per_seed.push_back(j.value("aps_heard_per_pause_mean", 0.0));
      if (j.contains("far_similar_share")) {
        far.per_seed.push_back(100 * j.value("far_similar_share", 0.0));
        near.per_seed.push_back(100 * j.value("near_similar_share", 0.0));
      }
      if (j.contains("resolution_m") && j["resolution_m"].is_number()) {
        resolution.per_seed.push_back(j["resolution_m"].get<double>());
      }
      fps = j.value("fps", 0.0);
    }
    out += fmt::format("| {} | {} (at {:g} fps) | {} | {} | {} | {} | {} % | {} % | {} |\n",
                       hall_name(twin), frames.text(0), fps, duration.text(0), pauses.text(0),
                       scans.text(0), heard.text(1), far.text(1), near.text(1), resolution.text(1));
  }
  out +=
      "\n\"Look alike\": cosine similarity of the two pauses' signatures at or above the SLAM's "
      "`wifi_similarity` (0.9). A pause far from every other that still looks like them joins "
      "their cluster instead of founding one; the resolution is the distance beyond which pauses "
      "stay told apart (`study/radio_resolution.hpp`).\n";
  out += "\n## Every number\n\n" + detail_table(Part::kDatasets, compared);
  out +=
      "\nWhere the cluster count differs: a cluster is founded whenever a keyframe's signature is "
      "similar to no cluster's representative (cosine similarity below `wifi_similarity`, 0.9 by "
      "default, with RSSI weighted above `wifi_floor_dbm`, -100 dBm). More clusters come from more "
      "access points heard per pause and more walls between pauses; fewer from an open building "
      "where every pause hears the same access points at similar strength. The paper chose its "
      "threshold per environment and does not give the values; we keep one default for every "
      "twin and do not tune it to a count.\n";
  return out;
}

/// The sweep figure's claims, judged on vanilla's means: the value at the axis' lowest setting
/// against its highest, averaged over the other axis, must move the way the paper says (the
/// verdict's "the same" band decides what counts as a move).
std::string rgbdslam_trends(const PaperMeasurements& m) {
  struct Trend {
    const char* words;
    const char* column;
    Quantity quantity;
    bool along_min_matches;  // else along inlier distance
    Direction claimed;       // of the value as the axis grows
  };
  const char* fp_words =
      "increasing min-matches and decreasing inlier-distance decreases the number of false "
      "positives as expected.";
  const char* time_words =
      "The computation time decreases as the number of min-matches increase and inlier-distance "
      "decreases.";
  const std::vector<Trend> trends = {
      {fp_words, "false_positive_pct", Quantity::kFalsePositivePct, true, Direction::kLess},
      {fp_words, "false_positive_pct", Quantity::kFalsePositivePct, false, Direction::kMore},
      {time_words, "paper_loop_closure_s", Quantity::kLoopClosureTimeS, true, Direction::kLess},
      {time_words, "paper_loop_closure_s", Quantity::kLoopClosureTimeS, false, Direction::kMore},
  };
  const std::vector<int> mms = {50, 70, 100, 150}, ids = {2, 3, 4};
  std::string out =
      "## The sweep figure's claims (vanilla, as the paper's figure)\n\n| the paper | as the "
      "axis grows | ours: at the lowest / highest setting (mean over the other axis) | verdict "
      "|\n| --- | --- | --- | --- |\n";
  for (const Trend& t : trends) {
    const auto mean_at = [&](int value) {
      double sum = 0;
      int n = 0;
      for (int other : t.along_min_matches ? ids : mms) {
        const int mm = t.along_min_matches ? value : other;
        const int id = t.along_min_matches ? other : value;
        const Measured v =
            m.column(Part::kRgbdslam, "c_hall",
                     fmt::format("min_matches={} inlier_distance={}", mm, id), false, t.column);
        if (!v.empty()) {
          sum += v.mean();
          ++n;
        }
      }
      return n > 0 ? std::optional<double>(sum / n) : std::nullopt;
    };
    const auto& axis = t.along_min_matches ? mms : ids;
    const auto low = mean_at(axis.front()), high = mean_at(axis.back());
    const std::string name = t.along_min_matches ? "min-matches" : "inlier distance";
    std::string ours = "not run", verdict = verdict_word(Verdict::kNotApplicable);
    if (low && high) {
      // Times as the ratio of the two (the verdict's rule for times); the rest as values.
      const Direction d = t.quantity == Quantity::kLoopClosureTimeS
                              ? direction_of_ratio(*low > 0 ? *high / *low : 1.0)
                              : direction_of(*low, *high, t.quantity);
      ours = fmt::format("{:.2f} / {:.2f} ({})", *low, *high, to_string(d));
      verdict = verdict_word(d == t.claimed ? Verdict::kReproduced : Verdict::kDeparts);
    }
    out += fmt::format("| {} | {}: {} | {} | {} |\n", t.words, name, to_string(t.claimed), ours,
                       verdict);
  }
  return out + "\n";
}

std::string rgbdslam_page(const PaperMeasurements& m, const std::vector<ComparedNumber>& compared,
                          const std::vector<PaperFigure>& figures) {
  std::string out = page_header(
      Part::kRgbdslam,
      fmt::format("C Hall, `rgbdslam` vanilla and with Wi-Fi, min_matches {{50, 70, 100, 150}} x "
                  "inlier_distance {{2, 3, 4}} ({}). The paper's 50/70 comparison is our "
                  "inlier_distance 3 (the default). \"Bounded-module time\" is the paper's "
                  "\"computation time of affected modules\": candidate selection, the long-term "
                  "verifications and optimisation.",
                  seeds_line(m, Part::kRgbdslam)));
  out += quotes(compared, Part::kRgbdslam);
  out += "## The sweep (the paper's 3 x 4 figure)\n\n";
  out +=
      "| min_matches | inlier_distance | wrong place % vanilla / Wi-Fi | bounded-module time (s) "
      "vanilla / Wi-Fi | ATE (m) vanilla / Wi-Fi | keyframes vanilla |\n| ---: | ---: | --- | "
      "--- | --- | ---: |\n";
  for (const std::string& setting : m.settings(Part::kRgbdslam, "c_hall")) {
    const auto fp = m.paired(Part::kRgbdslam, "c_hall", setting, "false_positive_pct");
    const auto t = m.paired(Part::kRgbdslam, "c_hall", setting, "paper_loop_closure_s");
    const auto ate = m.paired(Part::kRgbdslam, "c_hall", setting, "ate_rmse_m");
    const Measured kf = m.column(Part::kRgbdslam, "c_hall", setting, false, "keyframes");
    const auto mm = setting.substr(12, setting.find(' ') - 12);
    const auto id = setting.substr(setting.rfind('=') + 1);
    out += fmt::format("| {} | {} | {} / {} | {} / {} | {} / {} | {} |\n", mm, id, fp.first.text(1),
                       fp.second.text(1), t.first.text(2), t.second.text(2), ate.first.text(2),
                       ate.second.text(2), kf.text(0));
  }
  out += "\n" + rgbdslam_trends(m);
  out += figure_links(figures, Part::kRgbdslam);
  out += "## Where the bounded-module time goes (per run and per keyframe, means over seeds)\n\n";
  out +=
      "| setting | variant | keyframes | loop closures | candidate selection (s) | long-term "
      "comparisons | long-term verifications (s) | optimisation (s) | optimisation per keyframe "
      "(ms) | iterations per optimisation |\n| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: "
      "| ---: | ---: |\n";
  for (const char* setting :
       {"min_matches=50 inlier_distance=3", "min_matches=70 inlier_distance=3"}) {
    for (bool wifi : {false, true}) {
      const auto col = [&](const char* name) {
        return m.column(Part::kRgbdslam, "c_hall", setting, wifi, name);
      };
      Measured per_keyframe_ms, iterations_per_solve;
      for (const RunRow* r : m.runs(Part::kRgbdslam, "c_hall", setting, wifi)) {
        if (r->value("keyframes") > 0) {
          per_keyframe_ms.per_seed.push_back(1e3 * r->value("optimisation_s") /
                                             r->value("keyframes"));
        }
        if (r->value("optimisations") > 0) {
          iterations_per_solve.per_seed.push_back(r->value("optimisation_iterations") /
                                                  r->value("optimisations"));
        }
      }
      out += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n", setting,
                         wifi ? "Wi-Fi" : "vanilla", col("keyframes").text(0),
                         col("scored_closures").text(0), col("candidate_selection_s").text(2),
                         col("long_term_comparisons").text(0),
                         col("long_term_verification_s").text(2), col("optimisation_s").text(2),
                         per_keyframe_ms.text(1), iterations_per_solve.text(1));
    }
  }
  out +=
      "\nEvery keyframe is followed by an optimisation of the whole graph (RGBDSLAMv2's "
      "`optimizer_skip_step` 1), which runs in rounds of 5 iterations until chi^2 improves by less "
      "than 1 % (its `optimizer_iterations` 0.01; `rgbdslam`'s `optimizer_convergence`): a graph "
      "torn between conflicting closures takes more rounds, which is where the paper's \"smoother "
      "map reduces the optimization time\" can show. Loop closures: scored edges online.\n";
  out += "\n## Every number\n\n" + detail_table(Part::kRgbdslam, compared);
  return out;
}

std::string tables_page(Part part, const std::string& lead, const PaperMeasurements& m,
                        const std::vector<ComparedNumber>& compared,
                        const std::vector<PaperFigure>& figures, const std::string& extra) {
  std::string out = page_header(part, lead + " Runs: " + seeds_line(m, part) + ".");
  for (const PaperTable& t : paper_tables()) {
    if (t.part == part) out += table_grid(t, compared);
  }
  out += quotes(compared, part);
  out += extra;
  out += figure_links(figures, part);
  out += "## Every number\n\n" + detail_table(part, compared);
  return out;
}

std::string orbslam_a_hall(const PaperMeasurements& m) {
  const auto runs = m.runs(Part::kOrbslam, "a_hall", "min_matches=20", false);
  if (runs.empty()) return "";
  std::string out =
      "## A Hall\n\n> We were not able to get any result for A Hall in ORB-SLAM due to it having "
      "very low number of features.\n>\n> — the paper, \"ORB-SLAM performance\"\n\nOurs at "
      "min_matches 20 (ORB-SLAM2's):\n\n| variant | ATE (m) | keyframes | loop closures | "
      "frames |\n| --- | ---: | ---: | ---: | ---: |\n";
  for (bool wifi : {false, true}) {
    const auto col = [&](const char* name) {
      return m.column(Part::kOrbslam, "a_hall", "min_matches=20", wifi, name);
    };
    out += fmt::format("| {} | {} | {} | {} | {} |\n", wifi ? "Wi-Fi" : "vanilla",
                       col("ate_rmse_m").text(3), col("keyframes").text(0),
                       col("scored_closures").text(0), col("frames").text(0));
  }
  const Measured ate = m.column(Part::kOrbslam, "a_hall", "min_matches=20", false, "ate_rmse_m");
  // "A result" as the paper means it: a usable trajectory. Ours always ends with one; a seed
  // counts as a result when its error is below a metre on the 186 m route. Seeds are counted one
  // by one: one bad seed does not make the twin defeat ORB-SLAM, nor one good seed save it.
  const auto results = static_cast<std::size_t>(
      std::count_if(ate.per_seed.begin(), ate.per_seed.end(), [](double m) { return m < 1.0; }));
  const std::size_t seeds = ate.per_seed.size();
  if (seeds == 0) return out;
  if (results == seeds) {
    out += fmt::format(
        "\nOurs runs to the end with an ATE of {} m, below a metre on every seed: unlike the "
        "paper's hall, our A Hall twin does not defeat ORB-SLAM.\n\n",
        ate.text(2));
  } else if (results == 0) {
    out += fmt::format(
        "\nOurs runs to the end, but {} m off (ATE), a metre or more on every seed: like the "
        "paper's, the twin's sparse features defeat ORB-SLAM.\n\n",
        ate.text(2));
  } else {
    out += fmt::format(
        "\nOurs runs to the end with an ATE of {} m: below a metre on {} of {} seeds, so the "
        "twin defeats ORB-SLAM on some seeds only.\n\n",
        ate.text(2), results, seeds);
  }
  return out;
}

std::string fabmap_page(const PaperMeasurements& m, const std::vector<ComparedNumber>& compared,
                        const std::vector<PaperFigure>& figures) {
  std::string out = page_header(
      Part::kFabmap,
      "`wifislam localize` on each twin (an image every 2 s, the first 40 % of the route the map, "
      "the rest the queries): visual FAB-MAP, Wi-Fi FAB-MAP (presence words) and ours "
      "(wifi-clusters). Shares of all query images within 1, 2 and 4 m, mean over seeds.");
  out += quotes(compared, Part::kFabmap);
  out +=
      "| building | method | within 1 m | within 2 m | within 4 m | seeds |\n| --- | --- | ---: "
      "| ---: | ---: | ---: |\n";
  for (const std::string& twin : twin_names()) {
    const auto it = m.localisations().find(twin);
    if (it == m.localisations().end()) continue;
    for (const char* method : {"fabmap", "wifi-fabmap", "wifi-clusters"}) {
      Measured w1, w2, w4;
      for (const auto& [seed, summary] : it->second) {
        for (const auto& entry : summary.value("methods", nlohmann::json::array())) {
          if (entry.value("method", "") != method) continue;
          w1.per_seed.push_back(100 * entry["all"].value("within_1m", 0.0));
          w2.per_seed.push_back(100 * entry["all"].value("within_2m", 0.0));
          w4.per_seed.push_back(100 * entry["all"].value("within_4m", 0.0));
        }
      }
      out += fmt::format("| {} | {} | {} | {} | {} | {} |\n", hall_name(twin), method, w1.text(1),
                         w2.text(1), w4.text(1), w4.per_seed.size());
    }
  }
  out += "\n## The paper's comparisons, judged on the share within 4 m\n\n";
  out +=
      "| building | the paper | ours vs Wi-Fi FAB-MAP (within 4 m) | agrees |\n| --- | --- | "
      "--- | --- |\n";
  const std::map<std::string, std::string> claim = {{"c_hall", "ours better"},
                                                    {"b_hall", "ours better"},
                                                    {"j_hall", "similar"},
                                                    {"a_hall", "Wi-Fi FAB-MAP better"}};
  for (const std::string& twin : twin_names()) {
    const auto it = m.localisations().find(twin);
    if (it == m.localisations().end()) continue;
    Measured ours, theirs;
    for (const auto& [seed, summary] : it->second) {
      for (const auto& entry : summary.value("methods", nlohmann::json::array())) {
        const double w4 = 100 * entry["all"].value("within_4m", 0.0);
        if (entry.value("method", "") == "wifi-clusters") ours.per_seed.push_back(w4);
        if (entry.value("method", "") == "wifi-fabmap") theirs.per_seed.push_back(w4);
      }
    }
    const Direction d = direction_of(theirs.mean(), ours.mean(), Quantity::kQueriesWithinPct);
    const std::string measured = d == Direction::kMore   ? "ours better"
                                 : d == Direction::kLess ? "Wi-Fi FAB-MAP better"
                                                         : "similar";
    out += fmt::format("| {} | {} | {:.1f} % against {:.1f} %: {} | {} |\n", hall_name(twin),
                       claim.at(twin), ours.mean(), theirs.mean(), measured,
                       measured == claim.at(twin) ? "yes" : "no");
  }
  out +=
      "\n(\"similar\": within the tolerance of verdict.hpp: 10 % of the larger plus 2 points.)\n\n";
  out += figure_links(figures, Part::kFabmap);
  out += "## Every number\n\n" + detail_table(Part::kFabmap, compared);
  return out;
}

std::string abstract_table(const std::vector<ComparedNumber>& compared) {
  std::string out =
      "| the paper | quantity | paper | ours | verdict | how ours is computed |\n| "
      "--- | --- | ---: | ---: | --- | --- |\n";
  for (const ComparedNumber& c : compared) {
    if (c.paper->part != Part::kAbstract) continue;
    out += fmt::format("| abstract | {} | {} | {} | {} | {} |\n", to_string(c.paper->quantity),
                       paper_value_text(*c.paper), ours_text(c), verdict_word(c.judgement.verdict),
                       cell_text(c.context));
  }
  return out + "\n";
}

std::string timing_footer(const fs::path& folder) {
  const std::map<std::string, double> times = paper_part_times(folder);
  if (times.empty()) return "";
  std::string out =
      "## Time per part\n\nWall-clock of `wifislam paper` in this folder, summed over its runs "
      "(a resumed run adds to it; machine-dependent, unlike everything above):\n\n| part | "
      "wall-clock |\n| --- | ---: |\n";
  double total = 0;
  for (const auto& [part, s] : times) {
    out += fmt::format("| {} | {:.0f} s ({:.1f} min) |\n", part, s, s / 60);
    total += s;
  }
  return out + fmt::format("| all | {:.0f} s ({:.1f} min) |\n", total, total / 60);
}

nlohmann::json number_json(const ComparedNumber& c) {
  const PaperNumber& n = *c.paper;
  nlohmann::json ours = nullptr;
  if (!c.ours.empty()) {
    ours = {{"mean", c.ours.mean()},
            {"sd", c.ours.sd()},
            {"min", c.ours.min()},
            {"max", c.ours.max()},
            {"seeds", c.ours.per_seed.size()},
            // Seed by seed, in the seeds' order, so that any rule can be applied again (a time's
            // Wi-Fi/vanilla ratio pairs the two variants' lists).
            {"per_seed", c.ours.per_seed}};
  }
  return {{"part", to_string(n.part)},
          {"source", n.source},
          {"building", n.twin},
          {"setting", n.setting},
          {"variant", to_string(n.variant)},
          {"quantity", to_string(n.quantity)},
          {"paper", paper_value_text(n)},
          {"paper_value", n.value},
          {"paper_value_high", n.value_high},
          {"ours", ours},
          {"verdict", to_string(c.judgement.verdict)},
          {"why", c.judgement.why},
          {"measured", c.context}};
}

std::string numbers_csv(const std::vector<ComparedNumber>& compared) {
  std::string out =
      "part,source,building,setting,variant,quantity,paper,paper_value,paper_value_high,"
      "ours_mean,ours_sd,ours_min,ours_max,seeds,verdict,why,measured\n";
  for (const ComparedNumber& c : compared) {
    const PaperNumber& n = *c.paper;
    const bool has = !c.ours.empty();
    out += fmt::format(
        "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", to_string(n.part),
        wifislam::csv_field(n.source), wifislam::csv_field(n.twin), wifislam::csv_field(n.setting),
        to_string(n.variant), to_string(n.quantity), wifislam::csv_field(paper_value_text(n)),
        n.value, n.value_high, has ? fmt::format("{}", c.ours.mean()) : "",
        has ? fmt::format("{}", c.ours.sd()) : "", has ? fmt::format("{}", c.ours.min()) : "",
        has ? fmt::format("{}", c.ours.max()) : "", c.ours.per_seed.size(),
        to_string(c.judgement.verdict), wifislam::csv_field(c.judgement.why),
        wifislam::csv_field(c.context));
  }
  return out;
}

}  // namespace

std::map<Part, VerdictCounts> verdict_counts(const std::vector<ComparedNumber>& compared) {
  std::map<Part, VerdictCounts> out;
  for (const ComparedNumber& c : compared) {
    VerdictCounts& k = out[c.paper->part];
    switch (c.judgement.verdict) {
      case Verdict::kReproduced:
        ++k.reproduced;
        break;
      case Verdict::kDirectionOnly:
        ++k.direction_only;
        break;
      case Verdict::kDeparts:
        ++k.departs;
        break;
      case Verdict::kNotApplicable:
        ++k.not_applicable;
        break;
    }
  }
  return out;
}

std::string write_paper_report(const fs::path& folder) {
  const PaperMeasurements m = PaperMeasurements::load(folder);
  const std::vector<ComparedNumber> compared = compare_with_paper(m);
  const std::vector<PaperFigure> figures = draw_paper_figures(m, compared, folder);

  std::string verdicts =
      "| part | numbers | reproduced | direction only | departs | not applicable |\n| --- | ---: "
      "| ---: | ---: | ---: | ---: |\n";
  VerdictCounts all;
  for (const auto& [part, k] : verdict_counts(compared)) {
    verdicts += counts_row(fmt::format("[{}]({}.md)", part_title(part),
                                       part == Part::kAbstract ? "report" : to_string(part)),
                           k);
    all.reproduced += k.reproduced;
    all.direction_only += k.direction_only;
    all.departs += k.departs;
    all.not_applicable += k.not_applicable;
  }
  verdicts += counts_row("all", all);

  std::string report = fmt::format(
      "# The paper beside our twins\n\n"
      "Every number of the paper's evaluation (its eight tables, and the numbers its text and "
      "abstract state: {} in all) beside ours, measured by `wifislam paper` (wifislam {}) on the "
      "twins of its four buildings. Ours are means over seeds with their sd and min-max. The "
      "paper's figures are redrawn from our runs on the part pages.\n\n## Verdicts\n\n{}\n"
      "## The abstract's two numbers\n\n{}"
      "## How a number is judged\n\n{}\n\n"
      "- **reproduced**: the same direction as the paper (Wi-Fi against vanilla) and the paper's "
      "value inside our seeds' range or within the tolerance;\n"
      "- **direction only**: the same direction, another value;\n"
      "- **departs**: the other direction (a number with no direction: another value); the part "
      "page says what our runs did;\n"
      "- **n/a** (not applicable): we have no counterpart (the part was not run, or the twin has "
      "nothing to measure, such as no revisit episode to miss).\n\n"
      "Times are judged as Wi-Fi / vanilla ratios, never in seconds: the paper's seconds are of "
      "30 fps Kinect data on its machine. The rules are in `study/paper/verdict.hpp`, what "
      "\"ours\" is for each number in `study/paper/paper_comparison.hpp`, and the paper's numbers "
      "(entered once, each citing its table) in `study/paper/paper_numbers.cpp`.\n\n"
      "## Pages\n\n- [Datasets](datasets.md): frames, access points and Wi-Fi clusters per "
      "building\n- [RGBD-SLAM](rgbdslam.md): C Hall, the 50/70 comparison and the 3 x 4 sweep\n"
      "- [RTAB-Map](rtabmap.md): four buildings x four real-time thresholds\n- "
      "[ORB-SLAM](orbslam.md): three buildings x five min-matches, and A Hall\n- "
      "[FAB-MAP](fabmap.md): the localisation comparison\n- `paper_vs_ours.csv` and "
      "`paper_vs_ours.json`: every number, with why\n\n{}",
      paper_numbers().size(), WIFISLAM_VERSION, verdicts, abstract_table(compared),
      tolerance_text(), timing_footer(folder));

  write_file_atomic(folder / folder::kReport, report);
  write_file_atomic(folder / "datasets.md", datasets_page(m, compared));
  write_file_atomic(folder / "rgbdslam.md", rgbdslam_page(m, compared, figures));
  write_file_atomic(
      folder / "rtabmap.md",
      tables_page(Part::kRtabmap,
                  "`rtabmap` vanilla and with Wi-Fi on the four twins at Rtabmap/TimeThr {inf, "
                  "70, 100, 200} ms, compared with our deterministic cost model (so which nodes "
                  "move to LTM is the same on any machine). Loop-closure time: likelihood + "
                  "posterior + the loop hypothesis' verification, measured.",
                  m, compared, figures, ""));
  write_file_atomic(
      folder / "orbslam.md",
      tables_page(Part::kOrbslam,
                  "`orbslam` vanilla and with Wi-Fi on B, C and J Hall at min_matches {10, 15, "
                  "20, 50, 100} (the Sim3 RANSAC inliers). Loop-closure time: the loop query + "
                  "the Sim3 verifications + the pose-graph optimisations, measured.",
                  m, compared, figures, orbslam_a_hall(m)));
  write_file_atomic(folder / "fabmap.md", fabmap_page(m, compared, figures));
  write_file_atomic(folder / folder::kTableCsv, numbers_csv(compared));
  nlohmann::json all_json = nlohmann::json::array();
  for (const ComparedNumber& c : compared) all_json.push_back(number_json(c));
  write_file_atomic(folder / folder::kTableJson, all_json.dump(1) + "\n");
  return verdicts;
}

}  // namespace wifislam::study::paper
