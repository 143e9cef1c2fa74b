#pragma once
// The three localisation methods of the paper's FAB-MAP comparison, run on the same query images
// (study/localisation_data.hpp): the first `map_share` of the images (by time) are the map, the
// rest the queries, and each query is matched to one map image. Images of another floor
// (add_other_floor) are all map: a query that chooses one is on the wrong floor.
//
//   fabmap         visual FAB-MAP (slam/place/fabmap.hpp) over the map images' word observations
//   wifi-fabmap    Wi-Fi FAB-MAP (Nowakowski et al., IROS 2017): early fusion, Wi-Fi words
//                  appended to each image's visual words and FAB-MAP run on the concatenation. A
//                  map image takes the moving scan spatially closest to it among the map's scans,
//                  a query the one closest to it among the queries' scans (the paper's "scan taken
//                  at the query's location"). Wi-Fi words: one per access point heard (presence),
//                  or the thermometer code of Wietrzykowski et al. 2017 (RSSI + 110 in 5 dB bins,
//                  bits 0..bin set). No Wi-Fi training data exists for the twins, so Wi-Fi words
//                  join the tree as independent words with their marginals over the map images,
//                  and the new-place samples get Wi-Fi parts drawn from those marginals (seeded).
//   wifi-clusters  ours: the map images are grouped by the Wi-Fi cluster of the pause before each
//                  (slam/wifi/wifi_cluster_map.hpp, one representative signature per cluster); a
//                  query takes the signature of the last pause before it, its candidates are the
//                  map images of the similar clusters (all map images when none), and the highest
//                  FAB-MAP visual posterior among them wins: the only difference from `fabmap` is
//                  the Wi-Fi part.

#include <string>
#include <vector>

#include "slam/bow/vocabulary_tree.hpp"
#include "slam/place/fabmap.hpp"
#include "slam/place/fabmap_training.hpp"
#include "slam/wifi/wifi_options.hpp"
#include "study/localisation_data.hpp"

namespace wifislam::study {

enum class LocalisationMethod { kFabmap, kWifiFabmap, kWifiClusters };
const char* to_string(LocalisationMethod method);
/// "fabmap", "wifi-fabmap", "wifi-clusters"; nullopt otherwise.
std::optional<LocalisationMethod> parse_localisation_method(const std::string& text);
bool uses_wifi(LocalisationMethod method);

enum class WifiWordEncoding { kPresence, kThermometer };

struct LocalisationOptions {
  std::vector<LocalisationMethod> methods = {LocalisationMethod::kFabmap,
                                             LocalisationMethod::kWifiFabmap,
                                             LocalisationMethod::kWifiClusters};
  double map_share = 0.4;  // the paper: the first 40 % of the route is the map
  slam::place::FabMapOptions fabmap;
  WifiWordEncoding wifi_words = WifiWordEncoding::kPresence;
  slam::wifi::WifiOptions wifi;  // similarity and floor of our clusters
};

struct QueryResult {
  LocalisationMethod method = LocalisationMethod::kFabmap;
  int query = -1;   // image index
  int chosen = -1;  // the map image matched
  double probability = 0.0;
  double error_m = 0.0;        // true distance between the query and the chosen image
  double nearest_map_m = 0.0;  // true distance to the nearest map image
  int candidates = 0;          // map images the method chose among
  double time_s = 0.0;         // matching time (Wi-Fi part included)
  /// The chosen image is on another floor (add_other_floor): wrong whatever error_m, the
  /// horizontal distance, says.
  bool wrong_floor = false;
  /// Chosen on the query's floor within `limit_m`.
  bool within(double limit_m) const { return !wrong_floor && error_m <= limit_m; }
};

struct LocalisationResult {
  std::string description;
  int map_images = 0, query_images = 0;
  int other_floor_images = 0;             // of the map images, those of another floor
  bool queries_from_another_run = false;  // add_query_session: the input is all map
  std::vector<QueryResult> queries;       // per method, in query order
};

/// Runs every method of `options` on `data`. Throws InvalidInputError when a Wi-Fi method has no
/// scans of its protocol, or when there is no query or no map image.
LocalisationResult run_localisation(const LocalisationData& data,
                                    const slam::bow::VocabularyTree& vocabulary,
                                    const slam::place::FabMapTraining& training,
                                    const LocalisationOptions& options);

}  // namespace wifislam::study
