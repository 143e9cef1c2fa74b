#include "study/localisation_methods.hpp"

#include <algorithm>
#include <chrono>
#include <limits>
#include <map>
#include <set>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/rng.hpp"
#include "core/wall_clock.hpp"
#include "slam/wifi/wifi_cluster_map.hpp"

namespace wifislam::study {

namespace {

using slam::place::BinaryObservation;
using slam::place::FabMap;

/// The images of the map (before the split) and the queries.
struct Split {
  std::vector<int> map, queries;
  Timestamp split_time;
  bool by_session = false;  // a query session: map and queries are two runs
};

/// Whether an image or scan is of the map. With a query session (add_query_session) the map is
/// everything but that session; else the route's floor (0) before the split, and another floor
/// all of it.
Timestamp time_of(const LocalisationImage& image) { return image.time; }
Timestamp time_of(const PositionedScan& scan) { return scan.scan.time; }

template <class Item>
bool in_map(const Item& item, const Split& split) {
  if (split.by_session) return !item.query_session;
  return item.floor != 0 || time_of(item) < split.split_time;
}

Split split_images(const LocalisationData& data, double map_share) {
  Split s;
  s.by_session = data.query_session_images > 0;
  std::vector<std::int64_t> route_ns;
  for (const LocalisationImage& image : data.images)
    if (image.floor == 0 && !image.query_session) route_ns.push_back(image.time.ns);
  if (route_ns.size() < 2) throw InvalidInputError("localize: fewer than two images");
  const std::int64_t t0 = route_ns.front(), t1 = route_ns.back();
  s.split_time = Timestamp::from_ns(t0 + std::llround(map_share * static_cast<double>(t1 - t0)));
  for (int i = 0; i < static_cast<int>(data.images.size()); ++i) {
    const LocalisationImage& image = data.images[static_cast<std::size_t>(i)];
    (in_map(image, s) ? s.map : s.queries).push_back(i);
  }
  if (s.map.empty() || s.queries.empty()) {
    throw InvalidInputError("localize: the route gives no map image or no query image");
  }
  return s;
}

/// Wi-Fi words of a scan: one word per access point heard, or its thermometer code.
class WifiWords {
 public:
  static constexpr int kThermometerBins = 23;  // RSSI + 110 in 5 dB bins: -110 .. 0 dBm

  WifiWords(const std::vector<PositionedScan>& scans, WifiWordEncoding encoding)
      : encoding_(encoding) {
    for (const PositionedScan& s : scans) {
      for (const WifiReading& r : s.scan.readings) ap_index_.emplace(r.bssid.value, 0);
    }
    int i = 0;
    for (auto& [ap, index] : ap_index_) index = i++;
  }
  int word_count() const {
    const int per_ap = encoding_ == WifiWordEncoding::kPresence ? 1 : kThermometerBins;
    return static_cast<int>(ap_index_.size()) * per_ap;
  }
  BinaryObservation of(const WifiScan& scan) const {
    BinaryObservation out;
    for (const WifiReading& r : scan.readings) {
      const auto found = ap_index_.find(r.bssid.value);
      if (found == ap_index_.end()) continue;  // an AP the map never heard
      if (encoding_ == WifiWordEncoding::kPresence) {
        out.present.push_back(found->second);
        continue;
      }
      const int bin = std::clamp((r.rssi_dbm + 110) / 5, 0, kThermometerBins - 1);
      for (int b = 0; b <= bin; ++b) out.present.push_back(found->second * kThermometerBins + b);
    }
    std::sort(out.present.begin(), out.present.end());
    out.present.erase(std::unique(out.present.begin(), out.present.end()), out.present.end());
    return out;
  }

 private:
  WifiWordEncoding encoding_;
  std::map<std::uint64_t, int> ap_index_;
};

/// The scan among `scans` on the image's floor (restricted to the map's or the queries')
/// closest to the image.
const PositionedScan* closest_scan(const std::vector<PositionedScan>& scans,
                                   const LocalisationImage& image, const Split& split, bool map) {
  const PositionedScan* best = nullptr;
  double best_m = std::numeric_limits<double>::infinity();
  for (const PositionedScan& s : scans) {
    if (s.floor != image.floor || in_map(s, split) != map) continue;
    const double d = (s.position_m - image.position_m).norm();
    if (d < best_m) {
      best_m = d;
      best = &s;
    }
  }
  return best;
}

/// The most probable map place among a posterior (new place first): its index and probability.
std::pair<int, double> best_place(const std::vector<slam::place::PlaceMatch>& posterior) {
  std::pair<int, double> best = {-1, -1.0};
  for (std::size_t i = 1; i < posterior.size(); ++i) {
    if (posterior[i].probability > best.second)
      best = {posterior[i].place, posterior[i].probability};
  }
  return best;
}

struct Context {
  const LocalisationData& data;
  const Split& split;
  const std::vector<BinaryObservation>& visual;  // per image
  const slam::place::FabMapTraining& training;
  const LocalisationOptions& options;
};

void record(const Context& c, LocalisationMethod method, int query, int map_place, double p,
            int candidates, WallClock::time_point start, LocalisationResult& out) {
  QueryResult r;
  r.method = method;
  r.query = query;
  r.chosen = c.split.map[static_cast<std::size_t>(map_place)];
  r.probability = p;
  const LocalisationImage& asked = c.data.images[static_cast<std::size_t>(query)];
  const LocalisationImage& chosen = c.data.images[static_cast<std::size_t>(r.chosen)];
  r.error_m = (chosen.position_m - asked.position_m).norm();
  r.wrong_floor = chosen.floor != asked.floor;
  r.nearest_map_m = std::numeric_limits<double>::infinity();
  for (int m : c.split.map) {
    const LocalisationImage& place = c.data.images[static_cast<std::size_t>(m)];
    if (place.floor != asked.floor) continue;
    r.nearest_map_m = std::min(r.nearest_map_m, (place.position_m - asked.position_m).norm());
  }
  r.candidates = candidates;
  r.time_s = seconds_since(start);
  out.queries.push_back(r);
}

void run_visual(const Context& c, const FabMap& fabmap, LocalisationResult& out) {
  for (int q : c.split.queries) {
    const auto start = WallClock::now();
    const auto [place, p] = best_place(fabmap.match(c.visual[static_cast<std::size_t>(q)]));
    record(c, LocalisationMethod::kFabmap, q, place, p, fabmap.place_count(), start, out);
  }
}

void run_wifi_fabmap(const Context& c, LocalisationResult& out) {
  const std::vector<PositionedScan>& scans = c.data.moving_scans;
  std::vector<PositionedScan> map_scans;  // the words are the access points the map heard
  for (const PositionedScan& s : scans) {
    if (in_map(s, c.split)) map_scans.push_back(s);
  }
  const WifiWords words(map_scans, c.options.wifi_words);
  const int visual_words = c.training.tree.word_count();
  std::vector<BinaryObservation> map_wifi;
  for (int m : c.split.map) {
    const auto& image = c.data.images[static_cast<std::size_t>(m)];
    const PositionedScan* scan = closest_scan(scans, image, c.split, true);
    map_wifi.push_back(scan ? words.of(scan->scan) : BinaryObservation{});
  }
  // Wi-Fi words are independent in the tree, with their marginals over the map images.
  const slam::place::ChowLiuTree wifi_tree =
      slam::place::independent_words(map_wifi, words.word_count());
  slam::place::ChowLiuTree tree = c.training.tree;
  tree.append_independent(wifi_tree.p_present);
  Rng rng = Rng::stream(c.options.fabmap.seed, "localize/wifi_words_of_new_place_samples");
  std::vector<BinaryObservation> samples;
  for (const BinaryObservation& o : c.training.observations) {
    BinaryObservation wifi;
    for (int w = 0; w < words.word_count(); ++w) {
      if (rng.bernoulli(wifi_tree.p_present[static_cast<std::size_t>(w)]))
        wifi.present.push_back(w);
    }
    samples.push_back(slam::place::concatenate(o, wifi, visual_words));
  }
  FabMap fabmap(tree, c.options.fabmap, samples);
  for (std::size_t i = 0; i < c.split.map.size(); ++i) {
    fabmap.add_place(slam::place::concatenate(c.visual[static_cast<std::size_t>(c.split.map[i])],
                                              map_wifi[i], visual_words));
  }
  for (int q : c.split.queries) {
    const auto start = WallClock::now();
    const auto& image = c.data.images[static_cast<std::size_t>(q)];
    const PositionedScan* scan = closest_scan(scans, image, c.split, false);
    const BinaryObservation query =
        slam::place::concatenate(c.visual[static_cast<std::size_t>(q)],
                                 scan ? words.of(scan->scan) : BinaryObservation{}, visual_words);
    const auto [place, p] = best_place(fabmap.match(query));
    record(c, LocalisationMethod::kWifiFabmap, q, place, p, fabmap.place_count(), start, out);
  }
}

void run_wifi_clusters(const Context& c, const FabMap& fabmap, LocalisationResult& out) {
  slam::wifi::WifiClusterMap clusters(c.options.wifi.similarity, c.options.wifi.floor_dbm);
  std::map<const slam::wifi::WifiSignature*, slam::wifi::ClusterId> cluster_of_pause;
  std::vector<slam::wifi::ClusterId> cluster_of_place;  // per map place
  for (std::size_t i = 0; i < c.split.map.size(); ++i) {
    const auto& signature = c.data.images[static_cast<std::size_t>(c.split.map[i])].pause_signature;
    slam::wifi::ClusterId id = -1;
    if (signature) {
      const auto known = cluster_of_pause.find(signature.get());
      if (known != cluster_of_pause.end()) {
        id = known->second;
      } else {  // a new pause: cluster management as the SLAM Wi-Fi module does it
        id = clusters.assign(static_cast<slam::graph::KeyframeId>(i), signature,
                             clusters.similar_clusters(*signature), {});
        cluster_of_pause.emplace(signature.get(), id);
      }
    }
    cluster_of_place.push_back(id);
  }
  for (int q : c.split.queries) {
    const auto start = WallClock::now();
    const auto& signature = c.data.images[static_cast<std::size_t>(q)].pause_signature;
    std::set<slam::wifi::ClusterId> similar;
    if (signature) {
      for (const slam::wifi::SimilarCluster& s : clusters.similar_clusters(*signature))
        similar.insert(s.cluster);
    }
    std::vector<int> candidates;
    for (std::size_t i = 0; i < cluster_of_place.size(); ++i) {
      if (similar.count(cluster_of_place[i])) candidates.push_back(static_cast<int>(i));
    }
    // No similar cluster (or no pause yet): the query is matched against the whole map.
    const auto [place, p] =
        best_place(fabmap.match(c.visual[static_cast<std::size_t>(q)], candidates));
    record(c, LocalisationMethod::kWifiClusters, q, place, p,
           candidates.empty() ? fabmap.place_count() : static_cast<int>(candidates.size()), start,
           out);
  }
}

}  // namespace

const char* to_string(LocalisationMethod method) {
  switch (method) {
    case LocalisationMethod::kFabmap:
      return "fabmap";
    case LocalisationMethod::kWifiFabmap:
      return "wifi-fabmap";
    case LocalisationMethod::kWifiClusters:
      return "wifi-clusters";
  }
  return "?";
}

std::optional<LocalisationMethod> parse_localisation_method(const std::string& text) {
  for (auto m : {LocalisationMethod::kFabmap, LocalisationMethod::kWifiFabmap,
                 LocalisationMethod::kWifiClusters}) {
    if (text == to_string(m)) return m;
  }
  return std::nullopt;
}

bool uses_wifi(LocalisationMethod method) { return method != LocalisationMethod::kFabmap; }

LocalisationResult run_localisation(const LocalisationData& data,
                                    const slam::bow::VocabularyTree& vocabulary,
                                    const slam::place::FabMapTraining& training,
                                    const LocalisationOptions& options) {
  const Split split = split_images(data, options.map_share);
  for (LocalisationMethod m : options.methods) {
    const auto& scans = m == LocalisationMethod::kWifiFabmap ? data.moving_scans : data.pause_scans;
    if (uses_wifi(m) && scans.empty()) {
      throw InvalidInputError(fmt::format(
          "{}: no Wi-Fi scans, and localize --method {} needs them (--method fabmap needs none)",
          data.wifi_source, to_string(m)));
    }
  }
  std::vector<BinaryObservation> visual;
  for (const LocalisationImage& image : data.images) {
    visual.push_back(slam::place::visual_words(vocabulary, image.descriptors));
  }
  LocalisationResult out;
  out.description = data.description;
  out.map_images = static_cast<int>(split.map.size());
  out.query_images = static_cast<int>(split.queries.size());
  out.other_floor_images = data.other_floor_images;
  out.queries_from_another_run = split.by_session;
  const Context context{data, split, visual, training, options};
  FabMap fabmap(training.tree, options.fabmap, training.observations);
  for (int m : split.map) fabmap.add_place(visual[static_cast<std::size_t>(m)]);
  for (LocalisationMethod m : options.methods) {
    if (m == LocalisationMethod::kFabmap) run_visual(context, fabmap, out);
    if (m == LocalisationMethod::kWifiFabmap) run_wifi_fabmap(context, out);
    if (m == LocalisationMethod::kWifiClusters) run_wifi_clusters(context, fabmap, out);
  }
  return out;
}

}  // namespace wifislam::study
