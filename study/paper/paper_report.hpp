#pragma once
// The paper beside our numbers, written from a paper folder (paper_folder.hpp):
//
//   report.md           the verdicts per part, the abstract's two numbers, how numbers are judged,
//                       the time per part, links to the pages
//   datasets.md, rgbdslam.md, rtabmap.md, orbslam.md, fabmap.md
//                       one page per part: the paper's tables in its layout with ours and the
//                       verdict in each cell, its figures redrawn from our runs, and every number
//                       with why it was judged so
//   paper_vs_ours.csv, paper_vs_ours.json   every number: the paper's, ours (mean, sd, min, max,
//                       seeds), verdict, why
//   figures/            PNG and SVG
//
// Ours are the means over the seeds the folder holds, with sd and min-max. Written from what is
// in the folder: parts not run are "not applicable: not run". Everything but the time footer is
// the same for the same runs.

#include <filesystem>
#include <map>
#include <string>

#include "study/paper/paper_comparison.hpp"

namespace wifislam::study::paper {

struct VerdictCounts {
  int reproduced = 0, direction_only = 0, departs = 0, not_applicable = 0;
  int total() const { return reproduced + direction_only + departs + not_applicable; }
};
/// Counts per part, in Part order.
std::map<Part, VerdictCounts> verdict_counts(const std::vector<ComparedNumber>& compared);

/// Writes the files above into `folder` (each atomically). Returns the verdict table (Markdown)
/// that report.md opens with.
std::string write_paper_report(const std::filesystem::path& folder);

}  // namespace wifislam::study::paper
