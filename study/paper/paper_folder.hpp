#pragma once
// The folder `wifislam paper -o DIR` keeps (one place for its names). It is a work folder that a
// second run continues, not an output replaced whole: every file in it is written atomically, and
// a study database gains a case's rows in one transaction.
//
//   .wifislam-output            the marker (core/output_folder.hpp): --force may replace DIR
//   paper.json                  what DIR is made with (frame rate); a rerun must match it
//   scenes/<twin>.yaml          the twins as this build has them
//   studies/<study>.yaml        one study per experiment, twin and seed (paper_plan.hpp)
//   results/<study>.sqlite      its rows (study/result_store.hpp)
//   datasets/<twin>-seed<s>.json  what each twin's dataset held (frames, duration, scans)
//   localize/<twin>-seed<s>/    the FAB-MAP comparison (`wifislam localize`'s files)
//   runs/<study>/<setting>/<variant>/  the runs the figures draw (trajectory.txt, eval/)
//   timing.json                 wall-clock per part, summed over every run of `paper`
//   report.md, <part>.md, paper_vs_ours.csv, paper_vs_ours.json, figures/

#include <filesystem>
#include <string>

namespace wifislam::study::paper::folder {

inline constexpr const char* kIdentity = "paper.json";
inline constexpr const char* kFormatName = "wifislam-paper";
inline constexpr const char* kScenes = "scenes";
inline constexpr const char* kStudies = "studies";
inline constexpr const char* kResults = "results";
inline constexpr const char* kDatasets = "datasets";
inline constexpr const char* kLocalize = "localize";
inline constexpr const char* kRuns = "runs";
inline constexpr const char* kFigures = "figures";
inline constexpr const char* kTiming = "timing.json";
inline constexpr const char* kReport = "report.md";
inline constexpr const char* kTableCsv = "paper_vs_ours.csv";
inline constexpr const char* kTableJson = "paper_vs_ours.json";
/// Scratch space of the twin and seed being run (removed once its runs are in the databases).
inline constexpr const char* kWork = "work";

inline std::string twin_seed(const std::string& twin, unsigned long long seed) {
  return twin + "-seed" + std::to_string(seed);
}

}  // namespace wifislam::study::paper::folder
