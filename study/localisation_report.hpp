#pragma once
// What `wifislam localize` writes (a folder the caller commits atomically):
//   queries.csv    per method and query: time, true position, the chosen map image, its match
//                  probability, the error, the distance to the nearest map image, candidates, time
//   cdf.csv        per method, the share of queries within each error (the paper's CDF figure)
//   cdf.png, .svg  the CDF, one curve per method
//   pr.csv, pr.png, .svg  precision and recall of each method's match probability as a threshold (a
//                  match is true within 2 m; recall over the queries with a map image within 2 m),
//                  the measure FAB-MAP papers report
//   summary.json, summary.md  shares within 1, 2, 4 and 5 m over all queries and over those with
//                  a map image within 2 m, and the median matching time per query

#include <filesystem>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "study/localisation_methods.hpp"

namespace wifislam::study {

inline constexpr double kTrueMatchM = 2.0;

nlohmann::ordered_json localisation_summary(const LocalisationResult& result,
                                            const LocalisationOptions& options);

/// Writes the files above into `dir` (which must exist).
void write_localisation_report(const std::filesystem::path& dir, const LocalisationResult& result,
                               const LocalisationData& data, const LocalisationOptions& options);

}  // namespace wifislam::study
