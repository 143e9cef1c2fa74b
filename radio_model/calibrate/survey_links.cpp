#include "radio_model/calibrate/survey_links.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/error.hpp"
#include "radio_model/propagation_model.hpp"

namespace wifislam::radio_model::calibrate {

std::size_t SurveyLinks::sample_count() const {
  std::size_t n = 0;
  for (const LinkGroup& g : groups) n += g.rss_dbm.size();
  return n;
}

LineOfSightAgreement SurveyLinks::line_of_sight_agreement() const {
  LineOfSightAgreement a;
  for (const LinkGroup& g : groups) {
    if (!g.line_of_sight) continue;
    double walls = 0.0;
    for (double w : g.walls_per_material) walls += w;
    if (*g.line_of_sight) {
      ++a.los_links;
      a.los_clear += walls == 0.0;
    } else {
      ++a.nlos_links;
      a.nlos_blocked += walls > 0.0;
    }
  }
  return a;
}

namespace {

std::string id_list(const std::vector<SurveyAccessPoint>& aps) {
  std::string out;
  for (std::size_t i = 0; i < aps.size(); ++i) out += (i ? ", " : "") + std::to_string(aps[i].id);
  return out;
}

void check_inside(const SurveySite& site, const Eigen::Vector3d& p, const std::string& where,
                  const char* column, const std::string& what) {
  if (!site.in_free_space(p.head<2>())) {
    throw ParseError(
        where, column,
        fmt::format("{} ({:.2f}, {:.2f}) m is not in the free space of scene '{}' "
                    "(inside a wall or outside its plan, which spans ({:.2f}, {:.2f}) "
                    "to ({:.2f}, {:.2f}) m)",
                    what, p.x(), p.y(), site.name, site.bounds_min_m.x(), site.bounds_min_m.y(),
                    site.bounds_max_m.x(), site.bounds_max_m.y()));
  }
  if (!(p.z() >= 0.0 && p.z() <= site.ceiling_m)) {
    throw ParseError(where, "z_m",
                     fmt::format("{} height {} m is not between the floor and the ceiling (0 to "
                                 "{} m)",
                                 what, p.z(), site.ceiling_m));
  }
}

}  // namespace

std::vector<std::string> devices_reference_first(const Survey& survey,
                                                 const std::string& reference) {
  std::vector<std::string> devices = survey.devices();
  if (reference.empty()) return devices;
  const auto it = std::find(devices.begin(), devices.end(), reference);
  if (it == devices.end())
    throw InvalidInputError(fmt::format("{}: no sample of the reference device '{}' (devices: {})",
                                        survey.path, reference, fmt::join(devices, ", ")));
  std::rotate(devices.begin(), it, it + 1);
  return devices;
}

SurveyLinks survey_links(const Survey& survey, const std::vector<SurveyAccessPoint>& aps,
                         const SurveySite& site, std::vector<std::string> devices) {
  SurveyLinks out;
  out.aps = aps;
  out.devices = devices.empty() ? devices_reference_first(survey) : std::move(devices);
  std::map<std::string, std::size_t> index_of_device;
  for (std::size_t d = 0; d < out.devices.size(); ++d) index_of_device[out.devices[d]] = d;
  std::map<int, std::size_t> index_of_id;
  std::vector<radio_model::AccessPoint> model_aps;
  for (std::size_t i = 0; i < aps.size(); ++i) {
    const std::string where = aps[i].where.empty() ? site.access_points_where : aps[i].where;
    check_inside(site, aps[i].position_m, where, "x_m", fmt::format("access point {}", aps[i].id));
    index_of_id[aps[i].id] = i;
    radio_model::AccessPoint ap;
    ap.id = aps[i].id;
    ap.position_m = aps[i].position_m;
    model_aps.push_back(ap);
  }

  // Group by millimetre position, AP and device, in order of first appearance.
  std::map<std::tuple<long long, long long, long long, std::size_t, std::size_t>, std::size_t>
      group_of;
  for (const SurveySample& s : survey.samples) {
    const std::string where = survey.where(s.line);
    const auto ap = index_of_id.find(s.ap_id);
    if (ap == index_of_id.end()) {
      throw ParseError(where, "ap_id",
                       fmt::format("access point {} is not known (known ids: {}; give positions "
                                   "with --aps FILE or the scene's access_points)",
                                   s.ap_id, id_list(aps)));
    }
    const auto device = index_of_device.find(s.device);
    if (device == index_of_device.end()) {
      throw ParseError(where, "device",
                       fmt::format("device '{}' is not among the fitted survey's ({})", s.device,
                                   fmt::join(out.devices, ", ")));
    }
    const auto key =
        std::make_tuple(std::llround(s.position_m.x() * 1e3), std::llround(s.position_m.y() * 1e3),
                        std::llround(s.position_m.z() * 1e3), ap->second, device->second);
    auto [it, fresh] = group_of.emplace(key, out.groups.size());
    if (fresh) {
      check_inside(site, s.position_m, where, "x_m", "the survey position");
      LinkGroup g;
      g.position_m = s.position_m;
      g.ap_index = ap->second;
      g.device_index = device->second;
      g.first_line = s.line;
      g.line_of_sight = s.line_of_sight;
      out.groups.push_back(g);
    }
    out.groups[it->second].rss_dbm.push_back(s.rss_dbm);
  }

  // The simulator's own link geometry; no shadowing (sigma 0 builds no fields).
  PropagationOptions options = site.options;
  options.model = PathLossModel::kItuWalls;
  options.walls = true;
  options.shadowing_sigma_db = 0.0;
  const PropagationModel model(site.walls, site.bounds_min_m, site.bounds_max_m, model_aps, options,
                               site.seed);
  for (LinkGroup& g : out.groups) {
    double sum = 0.0;
    for (double r : g.rss_dbm) sum += r;
    g.mean_dbm = sum / static_cast<double>(g.rss_dbm.size());
    const radio_model::RadioLink link = model.link(g.ap_index, g.position_m);
    g.distance_m = link.distance_m;
    g.walls_per_material = link.walls_per_material;
  }
  return out;
}

}  // namespace wifislam::radio_model::calibrate
