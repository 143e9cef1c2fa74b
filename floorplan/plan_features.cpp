#include "floorplan/plan_features.hpp"

#include <cpl_conv.h>
#include <gdal.h>
#include <ogrsf_frmts.h>

#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <memory>
#include <regex>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "core/error.hpp"
#include "floorplan/osm_node_check.hpp"

namespace wifislam::floorplan {

namespace {

Ring read_line(const OGRSimpleCurve& curve) {
  Ring out;
  for (int i = 0; i < curve.getNumPoints(); ++i) out.emplace_back(curve.getX(i), curve.getY(i));
  if (out.size() > 1 && out.front() == out.back() && curve.get_IsClosed()) out.pop_back();
  return out;
}

void collect(const OGRGeometry* g, PlanFeature& feature) {
  if (g == nullptr) return;
  switch (wkbFlatten(g->getGeometryType())) {
    case wkbPolygon: {
      const auto* poly = g->toPolygon();
      if (poly->getExteriorRing() == nullptr) return;
      PolygonRings rings;
      rings.outer = read_line(*poly->getExteriorRing());
      for (int i = 0; i < poly->getNumInteriorRings(); ++i)
        rings.holes.push_back(read_line(*poly->getInteriorRing(i)));
      feature.polygons_lon_lat.push_back(std::move(rings));
      return;
    }
    case wkbLineString:
      feature.lines_lon_lat.push_back(read_line(*g->toLineString()));
      return;
    case wkbMultiPolygon:
    case wkbMultiLineString:
    case wkbGeometryCollection:
      for (const OGRGeometry* part : *g->toGeometryCollection()) collect(part, feature);
      return;
    default:
      return;  // points (door nodes without geometry of their own) carry nothing we use
  }
}

/// GDAL's OSM driver keeps the tags it has no column for in one hstore text, `"k"=>"v","k2"=>"v2"`.
void add_other_tags(const std::string& hstore, std::map<std::string, std::string>& tags) {
  static const std::regex pair(R"re("((?:[^"\\]|\\.)*)"=>"((?:[^"\\]|\\.)*)")re");
  for (auto it = std::sregex_iterator(hstore.begin(), hstore.end(), pair);
       it != std::sregex_iterator(); ++it)
    tags.emplace((*it)[1].str(), (*it)[2].str());
}

/// GDAL's OSM driver turns a closed way into a polygon only for the keys its osmconf.ini lists,
/// and indoor=* is not among them (it gives such ways as broken lines). For .osm/.pbf plans: a
/// copy of GDAL's own osmconf.ini with indoor added, in a temporary file removed after reading.
class IndoorOsmConfig {
 public:
  explicit IndoorOsmConfig(const std::filesystem::path& plan) {
    const std::string ext = plan.extension().string();
    if (ext != ".osm" && ext != ".pbf") return;
    const char* found = CPLFindFile("GDAL", "osmconf.ini");
    if (found == nullptr) return;
    std::ifstream in(found);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string key = "closed_ways_are_polygons=";
    const std::size_t at = text.find("\n" + key);
    if (at == std::string::npos) return;
    text.insert(at + 1 + key.size(), "indoor,");
    path_ = std::filesystem::temp_directory_path() /
            fmt::format("wifislam_osmconf_{}_{}.ini", ::getpid(),
                        reinterpret_cast<std::uintptr_t>(this));
    std::ofstream(path_) << text;
    option_ = "CONFIG_FILE=" + path_.string();
  }
  ~IndoorOsmConfig() {
    std::error_code ec;
    if (!path_.empty()) std::filesystem::remove(path_, ec);
  }
  /// Open options for GDALDataset::Open (null-terminated), or null.
  const char* const* open_options() {
    if (option_.empty()) return nullptr;
    options_[0] = option_.c_str();
    return options_;
  }

 private:
  std::filesystem::path path_;
  std::string option_;
  const char* options_[2] = {nullptr, nullptr};
};

/// Every point a longitude and latitude in degrees: 1e308, NaN or lon 200 reached PROJ and GDAL
/// (their unlocated "ERROR 1" and a 300-digit projection string) instead of a located error.
void check_lon_lat(const PlanFeature& feature) {
  const auto check = [&](const Ring& ring) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const double lon = ring[i].x(), lat = ring[i].y();
      if (!std::isfinite(lon) || !std::isfinite(lat) || std::abs(lon) > 180 || std::abs(lat) > 90) {
        throw ParseError(feature.where, "coordinates",
                         fmt::format("point {} is ({}, {}): expected a longitude in [-180, 180] "
                                     "and a latitude in [-90, 90] degrees (WGS 84)",
                                     i, lon, lat));
      }
    }
  };
  for (const PolygonRings& p : feature.polygons_lon_lat) {
    check(p.outer);
    for (const Ring& hole : p.holes) check(hole);
  }
  for (const Ring& line : feature.lines_lon_lat) check(line);
}

struct DatasetCloser {
  void operator()(GDALDataset* d) const { GDALClose(d); }
};

}  // namespace

std::vector<PlanFeature> read_plan_features(const std::filesystem::path& file) {
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) {
    throw IoError(fmt::format("{}: no such plan file", file.string()));
  }
  if (!std::filesystem::is_regular_file(file, ec)) {
    throw ParseError(file.string(), "", "is not a plan file (a folder, a device or a pipe)");
  }
  if (file.extension() == ".osm") check_osm_nodes(file);
  GDALAllRegister();
  // GDAL's warnings (an unclosed ring it closes itself) would go to stderr unasked; its errors
  // still reach CPLGetLastErrorMsg and our message.
  CPLPushErrorHandler(CPLQuietErrorHandler);
  struct PopHandler {
    ~PopHandler() { CPLPopErrorHandler(); }
  } pop;
  CPLErrorReset();
  IndoorOsmConfig osm_config(file);
  std::unique_ptr<GDALDataset, DatasetCloser> dataset(
      GDALDataset::Open(file.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY | GDAL_OF_VERBOSE_ERROR,
                        nullptr, osm_config.open_options(), nullptr));
  if (!dataset) {
    const std::string why = CPLGetLastErrorMsg();
    throw ParseError(file.string(), "",
                     "GDAL cannot read it as a vector floor plan (GeoJSON or OSM XML)" +
                         (why.empty() ? std::string() : ": " + why));
  }
  std::vector<PlanFeature> features;
  for (OGRLayer* layer : dataset->GetLayers()) {
    int index = 0;
    for (const auto& f : *layer) {
      PlanFeature feature;
      for (const auto& field : *f) {
        if (field.IsNull() || field.IsUnset()) continue;
        feature.tags[field.GetName()] = field.GetAsString();
      }
      if (auto other = feature.tags.find("other_tags"); other != feature.tags.end())
        add_other_tags(other->second, feature.tags);
      // The OSM driver's ids: nodes and lines osm_id, (multi)polygons osm_id or osm_way_id.
      for (const char* key : {"osm_id", "osm_way_id"})
        if (auto osm_id = feature.tags.find(key); osm_id != feature.tags.end())
          feature.tags.emplace("@id", osm_id->second);
      const std::string id = feature.tag("@id").empty() ? feature.tag("id") : feature.tag("@id");
      feature.where = fmt::format("{}: feature {}{}", file.string(), index,
                                  id.empty() ? std::string() : " (" + id + ")");
      collect(f->GetGeometryRef(), feature);
      check_lon_lat(feature);
      features.push_back(std::move(feature));
      ++index;
    }
  }
  return features;
}

}  // namespace wifislam::floorplan
