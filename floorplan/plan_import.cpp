#include "floorplan/plan_import.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "core/error.hpp"
#include "floorplan/local_projection.hpp"
#include "sim/scene/scene_schema.hpp"

namespace wifislam::floorplan {

namespace {

bool looks_like_wrld(const std::vector<PlanFeature>& features) {
  for (const PlanFeature& f : features) {
    const std::string type = f.tag("type");
    if (type == "wall" || type == "building_outline" || type == "door") return true;
  }
  return false;
}

bool looks_like_imdf(const std::vector<PlanFeature>& features) {
  for (const PlanFeature& f : features)
    if (!f.tag("level_id").empty() && !f.tag("category").empty()) return true;
  return false;
}

bool looks_like_osm_sit(const std::vector<PlanFeature>& features) {
  for (const PlanFeature& f : features)
    if (!f.tag("indoor").empty()) return true;
  return false;
}

}  // namespace

Eigen::Vector2d plan_centre_lon_lat(const std::vector<PlanFeature>& features) {
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(1e300), hi = Eigen::Vector2d::Constant(-1e300);
  auto add = [&](const Ring& r) {
    for (const auto& p : r) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  };
  for (const PlanFeature& f : features) {
    for (const PolygonRings& p : f.polygons_lon_lat) add(p.outer);
    for (const Ring& l : f.lines_lon_lat) add(l);
  }
  if (lo.x() > hi.x()) return Eigen::Vector2d::Zero();
  return 0.5 * (lo + hi);
}

std::vector<PolygonRings> projected_polygons(const GeosContext& geos, const PlanFeature& feature,
                                             const LocalProjection& projection) {
  std::vector<PolygonRings> out;
  for (const PolygonRings& p : feature.polygons_lon_lat) {
    PolygonRings m;
    for (const auto& v : p.outer) m.outer.push_back(projection.to_local_m(v));
    for (const Ring& hole : p.holes) {
      Ring h;
      for (const auto& v : hole) h.push_back(projection.to_local_m(v));
      m.holes.push_back(std::move(h));
    }
    if (m.outer.size() < 3)
      throw ParseError(feature.where, "geometry",
                       "a polygon ring with fewer than 3 corners (in an OSM file, a way loses the "
                       "nodes the file does not hold: check its nd refs)");
    const std::string reason = geos.polygon(m).invalid_reason();
    if (!reason.empty())
      throw ParseError(feature.where, "geometry",
                       "not a valid polygon (" + reason +
                           "): rings must not cross or touch themselves; fix the plan's drawing");
    out.push_back(std::move(m));
  }
  return out;
}

void add_projected_lines(const PlanFeature& feature, const LocalProjection& projection,
                         std::vector<Ring>& out) {
  for (const Ring& line : feature.lines_lon_lat) {
    Ring m;
    for (const auto& p : line) m.push_back(projection.to_local_m(p));
    out.push_back(std::move(m));
  }
}

ImportedPlan import_plan(const std::filesystem::path& given, const ImportOptions& options) {
  // An IMDF archive unpacked: the folder stands for its unit.geojson.
  const std::filesystem::path plan_file =
      std::filesystem::is_directory(given) ? given / "unit.geojson" : given;
  const std::vector<PlanFeature> features = read_plan_features(plan_file);
  PlanFormat format;
  if (options.format) {
    format = *options.format;
  } else if (looks_like_wrld(features)) {
    format = PlanFormat::kWrld;
  } else if (looks_like_imdf(features)) {
    format = PlanFormat::kImdf;
  } else if (looks_like_osm_sit(features)) {
    format = PlanFormat::kOsmSit;
  } else {
    throw ParseError(plan_file.string(), "",
                     "cannot tell the plan's format: no feature has an OSM indoor=* tag, a "
                     "WRLD type (wall, door, building_outline) or an IMDF category and "
                     "level_id; give --format");
  }
  ImportedPlan plan = format == PlanFormat::kWrld   ? import_wrld(plan_file, features, options)
                      : format == PlanFormat::kImdf ? import_imdf(plan_file, features, options)
                                                    : import_osm_sit(plan_file, features, options);
  plan.input_files.insert(plan.input_files.begin(), plan_file);
  if (plan.spaces.empty())
    throw ParseError(plan_file.string(), "",
                     fmt::format("level '{}' has no usable polygon (no room, corridor or area, or "
                                 "walls enclosing no space)",
                                 plan.level));
  // A scene keeps its coordinates within 10 km of the plan's centre (kCoordinateM). Checked
  // here, before the scene is built: a plan spread over more (a stray feature far away, a
  // building across the antimeridian) would otherwise take minutes and gigabytes first.
  double farthest_m = 0.0;
  for (const sim::scene::Space& s : plan.spaces)
    for (const Eigen::Vector2d& p : s.polygon_m)
      farthest_m = std::max(farthest_m, p.cwiseAbs().maxCoeff());
  if (!(farthest_m <= sim::scene::schema::kCoordinateM.hi))
    throw ParseError(plan_file.string(), "",
                     fmt::format("level '{}' reaches {:.0f} m from the plan's centre; a scene "
                                 "keeps within {:.0f} m (is a feature far from the rest, or does "
                                 "the plan cross longitude 180?)",
                                 plan.level, farthest_m, sim::scene::schema::kCoordinateM.hi));
  return plan;
}

}  // namespace wifislam::floorplan
