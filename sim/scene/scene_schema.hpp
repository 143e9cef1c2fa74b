#pragma once
// The scene file schema, written once as a list of fields per struct and used twice: by the
// YAML reader (scene_loader.cpp) and by the YAML writer of resolved scenes. Adding a key to the
// schema is one line here (plus its documentation in scenes/README.md).
//
// A visitor `V` provides:
//   number(key, double&, Limits), integer(key, int&, Limits), uint64(key, uint64_t&[, max]),
//   boolean(key, bool&), text(key, std::string&), optional_number(key, std::optional<double>&,
//   Limits), optional_uint64(key, std::optional<uint64_t>&), choice(key, Enum&, names),
//   vec2(key, Eigen::Vector2d&, Limits), vec3(key, Eigen::Vector3d&, Limits xy, Limits z),
//   optional_vec3(key, std::optional<Eigen::Vector3d>&, Limits xy, Limits z),
//   polygon(key, vector<Vector2d>&, Limits),
//   text_list(key, vector<string>&), interval(key, double& lo, double& hi, Limits),
//   object(key, T&), list(key, vector<T>&), device(key, std::optional<ReceiverDevice>&), and
//   `required(key)` to mark the next key mandatory;
//   list_if_any(key, vector<T>&) and points_if_any(key, vector<Vector2d>&, Limits) are a list and
//   a list of at least two points that the writer leaves out when empty (keys added after
//   scenes were first written, so resolved scenes without them stay byte for byte as they were).

#include <array>
#include <cstdint>
#include <limits>
#include <string_view>
#include <utility>
#include <vector>

#include "radio_model/access_point.hpp"
#include "sim/scene/scene.hpp"

namespace wifislam::sim::scene::schema {

/// Allowed range of a number; `open_low` excludes the lower bound (for "must be > 0").
struct Limits {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool open_low = false;
};
inline constexpr Limits kAny{};
inline constexpr Limits kPositive{0.0, std::numeric_limits<double>::infinity(), true};
inline constexpr Limits kNonNegative{0.0, std::numeric_limits<double>::infinity(), false};
inline constexpr Limits kUnit{0.0, 1.0, false};
/// Every coordinate in a scene: within 10 km of the origin. Larger numbers describe no building
/// and only overflow the floor-plan geometry (exact CGAL arithmetic) and the radio ray casts.
inline constexpr Limits kCoordinateM{-10000.0, 10000.0, false};
/// A height above the floor, up to the highest ceiling a scene may have (building.wall_height_m);
/// the scene validation compares it with the scene's own ceiling.
inline constexpr Limits kHeightM{0.0, 10.0, false};
/// A camera image's width or height in pixels (and so of every image a dataset holds).
inline constexpr Limits kImageSidePx{16, 8192, false};
/// An access point's transmit power: a Wi-Fi radio's range (radio_model/access_point.hpp).
inline constexpr Limits kTxPowerDbm{radio_model::kMinTxPowerDbm, radio_model::kMaxTxPowerDbm,
                                    false};

template <class E>
using Names = std::vector<std::pair<E, std::string_view>>;

inline Names<WallMaterial> material_names() {
  return {{WallMaterial::kPlasterboard, "plasterboard"},
          {WallMaterial::kBrick, "brick"},
          {WallMaterial::kConcrete, "concrete"},
          {WallMaterial::kGlass, "glass"},
          {WallMaterial::kWoodDoor, "wood_door"}};
}

template <class V>
void visit(V& v, Building& b) {
  v.number("wall_height_m", b.wall_height_m, Limits{1.8, 10.0});
  v.number("wall_thickness_m", b.wall_thickness_m, Limits{0.02, 1.0});
}

template <class V>
void visit(V& v, Level& l) {
  v.required();
  v.text("id", l.id);
  v.optional_number("elevation_m", l.elevation_m, Limits{-1000.0, 1000.0});
  v.optional_number("storey_height_m", l.storey_height_m, Limits{1.8, 50.0});
  v.number("slab_thickness_m", l.slab_thickness_m, Limits{0.02, 3.0});
  v.choice("slab_material", l.slab_material, material_names());
}

template <class V>
void visit(V& v, SceneNode& n) {
  v.required();
  v.text("id", n.id);
  v.required();
  v.vec2("position_m", n.position_m, kCoordinateM);
  v.text("level", n.level);
}

template <class V>
void visit(V& v, RoomRow& r) {
  v.choice("side", r.side,
           Names<RoomRow::Side>{{RoomRow::Side::kLeft, "left"},
                                {RoomRow::Side::kRight, "right"},
                                {RoomRow::Side::kBoth, "both"}});
  v.number("from_m", r.from_m, kNonNegative);
  v.optional_number("to_m", r.to_m, kPositive);
  v.number("room_length_m", r.room_length_m, Limits{1.0, 100.0});
  v.number("depth_m", r.depth_m, Limits{1.0, 100.0});
  v.number("door_offset_m", r.door_offset_m, kNonNegative);
  v.number("door_width_m", r.door_width_m, Limits{0.5, 3.0});
  v.boolean("doors_open", r.doors_open);
  v.choice("material", r.material, material_names());
}

template <class V>
void visit(V& v, Corridor& c) {
  v.required();
  v.text("id", c.id);
  v.required();
  v.text("from", c.from);
  v.required();
  v.text("to", c.to);
  v.number("width_m", c.width_m, Limits{0.8, 50.0});
  v.choice("material", c.material, material_names());
  v.list("rooms", c.rooms);
}

template <class V>
void visit(V& v, OpenArea::Pillar& p) {
  v.required();
  v.vec2("center_m", p.center_m, kCoordinateM);
  v.number("size_m", p.size_m, Limits{0.1, 5.0});
}

template <class V>
void visit(V& v, OpenArea& a) {
  v.required();
  v.text("id", a.id);
  v.text("level", a.level);
  v.required();
  v.polygon("polygon_m", a.polygon_m, kCoordinateM);
  v.choice("material", a.material, material_names());
  v.list("pillars", a.pillars);
}

template <class V>
void visit(V& v, Space& s) {
  v.required();
  v.text("id", s.id);
  v.text("level", s.level);
  v.choice("kind", s.kind,
           Names<SpaceKind>{{SpaceKind::kCorridor, "corridor"},
                            {SpaceKind::kArea, "area"},
                            {SpaceKind::kRoom, "room"}});
  v.required();
  v.polygon("polygon_m", s.polygon_m, kCoordinateM);
  v.choice("material", s.material, material_names());
  v.text("name", s.name);
}

template <class V>
void visit(V& v, SpaceDoor& d) {
  v.required();
  v.vec2("from_m", d.from_m, kCoordinateM);
  v.required();
  v.vec2("to_m", d.to_m, kCoordinateM);
  v.boolean("open", d.open);
  v.text("level", d.level);
}

template <class V>
void visit(V& v, Obstacle& o) {
  v.required();
  v.polygon("polygon_m", o.polygon_m, kCoordinateM);
  v.text("level", o.level);
}

template <class V>
void visit(V& v, AppearanceThemes& t) {
  v.text("wall", t.wall);
  v.text("door", t.door);
  v.text("floor", t.floor);
  v.text("ceiling", t.ceiling);
}

template <class V>
void visit(V& v, Landmark& l) {
  v.required();
  v.vec2("position_m", l.position_m, kCoordinateM);
  v.number("height_m", l.height_m, Limits{0.2, 5.0});
  v.number("width_m", l.width_m, Limits{0.1, 5.0});
  v.text("kind", l.kind);
}

template <class V>
void visit(V& v, Appearance& a) {
  v.number("aliasing", a.aliasing, kUnit);
  v.choice("aliasing_scope", a.aliasing_scope,
           Names<AliasingScope>{{AliasingScope::kSegment, "segment"},
                                {AliasingScope::kPosition, "position"}});
  v.number("segment_length_m", a.segment_length_m, Limits{0.5, 100.0});
  v.object("themes", a.themes);
  v.number("posters_per_10m", a.posters_per_10m, Limits{0.0, 20.0});
  v.number("light_spacing_m", a.light_spacing_m, Limits{0.5, 50.0});
  v.list("landmarks", a.landmarks);
}

template <class V>
void visit(V& v, AccessPointSpec& s) {
  v.required();
  v.vec3("position_m", s.position_m, kCoordinateM, kHeightM);
  v.optional_number("tx_power_dbm", s.tx_power_dbm, kTxPowerDbm);
  v.text("level", s.level);
}

template <class V>
void visit(V& v, AccessPointChange& c) {
  v.required();
  v.integer("session", c.session, Limits{1, 1000000});
  v.required();
  v.choice("change", c.change,
           Names<AccessPointChangeKind>{{AccessPointChangeKind::kOff, "off"},
                                        {AccessPointChangeKind::kMoved, "moved"},
                                        {AccessPointChangeKind::kPower, "power"},
                                        {AccessPointChangeKind::kNew, "new"}});
  v.optional_uint64("ap", c.ap);
  v.optional_vec3("position_m", c.position_m, kCoordinateM, kHeightM);
  v.number("tx_power_step_db", c.tx_power_step_db, Limits{-60.0, 60.0});
  v.optional_number("tx_power_dbm", c.tx_power_dbm, kTxPowerDbm);
  v.text("level", c.level);
}

template <class V>
void visit(V& v, AccessPoints& a) {
  v.choice("placement", a.placement,
           Names<ApPlacement>{{ApPlacement::kExplicit, "explicit"},
                              {ApPlacement::kGrid, "grid"},
                              {ApPlacement::kRandom, "random"},
                              {ApPlacement::kRooms, "rooms"},
                              {ApPlacement::kColinear, "colinear"}});
  v.integer("count", a.count, Limits{0, 10000});
  v.optional_uint64("seed", a.seed);
  v.number("height_m", a.height_m, kHeightM);
  v.number("tx_power_dbm", a.tx_power_dbm, kTxPowerDbm);
  v.integer("ssids_per_radio", a.ssids_per_radio, Limits{1, 16});
  // Up to the diagonal of the largest site the coordinate limits allow (2 x 10 km x sqrt 2).
  v.number("min_spacing_m", a.min_spacing_m, Limits{0.0, 30000.0});
  v.list("list", a.explicit_list);
  v.vec2("line_from_m", a.line_from_m, kCoordinateM);
  v.vec2("line_to_m", a.line_to_m, kCoordinateM);
  v.list_if_any("changes", a.changes);
}

template <class V>
void visit(V& v, PauseSpec& p) {
  v.interval("spacing_m", p.spacing_min_m, p.spacing_max_m, Limits{0.5, 1000.0});
  v.number("duration_s", p.duration_s, Limits{0.0, 3600.0});
  v.boolean("scan_while_moving", p.scan_while_moving);
}

template <class V>
void visit(V& v, Route& r) {
  v.text_list("nodes", r.nodes);
  v.points_if_any("waypoints_m", r.waypoints_m, kCoordinateM);
  v.number("speed_mps", r.speed_mps, Limits{0.05, 5.0});
  v.number("max_yaw_rate_radps", r.max_yaw_rate_radps, Limits{0.05, 10.0});
  v.number("turn_radius_m", r.turn_radius_m, Limits{0.0, 20.0});
  v.number("min_wall_clearance_m", r.min_wall_clearance_m, Limits{0.0, 25.0});
  v.object("pause", r.pause);
  v.text("level", r.level);
}

template <class V>
void visit(V& v, CameraSpec& c) {
  v.integer("width_px", c.intrinsics.width_px, kImageSidePx);
  v.integer("height_px", c.intrinsics.height_px, kImageSidePx);
  v.number("fx_px", c.intrinsics.fx_px, kPositive);
  v.number("fy_px", c.intrinsics.fy_px, kPositive);
  v.number("cx_px", c.intrinsics.cx_px, kAny);
  v.number("cy_px", c.intrinsics.cy_px, kAny);
  v.number("fps", c.fps, Limits{kMinCameraFps, kMaxCameraFps});
  v.number("height_m", c.height_m, Limits{0.05, 5.0});
  v.number("pitch_deg", c.pitch_deg, Limits{-60.0, 60.0});
}

template <class V>
void visit(V& v, DepthSensorSpec& d) {
  v.number("min_range_m", d.min_range_m, kNonNegative);
  v.number("max_range_m", d.max_range_m, kPositive);
  v.boolean("noise", d.noise);
  v.boolean("quantisation", d.quantisation);
  v.boolean("dropouts", d.dropouts);
  v.number("axial_noise_coeff_per_m", d.axial_noise_coeff_per_m, kNonNegative);
  v.number("baseline_m", d.baseline_m, kPositive);
  v.number("disparity_step_px", d.disparity_step_px, kPositive);
  v.number("grazing_dropout_deg", d.grazing_dropout_deg, Limits{0.0, 90.0});
  v.number("edge_jump_fraction", d.edge_jump_fraction, kPositive);
  v.boolean("lateral_noise", d.lateral_noise);
  v.number("lateral_noise_base_px", d.lateral_noise_base_px, Limits{0.0, 10.0});
  v.number("lateral_noise_angle_coeff_px", d.lateral_noise_angle_coeff_px, Limits{0.0, 10.0});
}

template <class V>
void visit(V& v, ColorSensorSpec& c) {
  v.boolean("noise", c.noise);
  v.number("conversion_gain_dn_per_e", c.conversion_gain_dn_per_e, Limits{0.0, 255.0});
  v.number("read_noise_dn", c.read_noise_dn, Limits{0.0, 255.0});
  v.boolean("auto_exposure", c.auto_exposure);
  v.number("exposure_target_dn", c.exposure_target_dn, Limits{1.0, 254.0});
  v.number("exposure_time_constant_s", c.exposure_time_constant_s, Limits{0.0, 3600.0, true});
  v.interval("exposure_gain_range", c.exposure_min_gain, c.exposure_max_gain, Limits{0.01, 100.0});
}

inline constexpr Limits kSensitivityDbm{-120.0, -40.0};
inline constexpr Limits kDwellPerChannelS{0.001, 1.0};

/// A receiver device, inline in a scene (sensors.wifi.device) or in a device file of its own.
template <class V>
void visit(V& v, radio_model::ReceiverDevice& d) {
  using radio_model::DeviceBands;
  using radio_model::ScanThrottle;
  v.required();
  v.text("name", d.name);
  v.text("source", d.source);
  v.number("rss_offset_db", d.rss_offset_db, Limits{-40.0, 40.0});
  // A gain far from 1 folds the range over itself; measured device maps stay near 1.
  v.number("rss_gain", d.rss_gain, Limits{0.5, 1.5});
  v.number("sensitivity_dbm", d.sensitivity_dbm, kSensitivityDbm);
  v.integer("quantisation_db", d.quantisation_db, Limits{1.0, 10.0});
  v.number("dwell_per_channel_s", d.dwell_per_channel_s, kDwellPerChannelS);
  v.choice("bands", d.bands,
           Names<DeviceBands>{{DeviceBands::kBoth, to_string(DeviceBands::kBoth)},
                              {DeviceBands::k2_4GHzOnly, to_string(DeviceBands::k2_4GHzOnly)},
                              {DeviceBands::k5GHzOnly, to_string(DeviceBands::k5GHzOnly)}});
  v.choice("scan_throttle", d.scan_throttle,
           Names<ScanThrottle>{
               {ScanThrottle::kNone, to_string(ScanThrottle::kNone)},
               {ScanThrottle::kAndroidForeground, to_string(ScanThrottle::kAndroidForeground)},
               {ScanThrottle::kAndroidBackground, to_string(ScanThrottle::kAndroidBackground)}});
}

/// `device` is a visitor call of its own: the reader takes a shipped name or a file path as well
/// as a mapping, and the writer writes the device in full (a resolved scene needs no file).
template <class V>
void visit(V& v, WifiScannerSpec& w) {
  v.device("device", w.device);
  v.number("sensitivity_dbm", w.sensitivity_dbm, kSensitivityDbm);
  v.number("dwell_per_channel_s", w.dwell_per_channel_s, kDwellPerChannelS);
  v.number("scan_interval_s", w.scan_interval_s, Limits{0.1, 60.0});
}

template <class V>
void visit(V& v, OdometrySpec& o) {
  v.number("rate_hz", o.rate_hz, Limits{1.0, 1000.0});
  v.number("noise_per_m", o.noise_per_m, Limits{0.0, 1.0});
  v.number("noise_per_rad", o.noise_per_rad, Limits{0.0, 1.0});
  v.number("scale_error", o.scale_error, Limits{-0.5, 0.5});
  v.number("yaw_bias_radpm", o.yaw_bias_radpm, Limits{-1.0, 1.0});
}

template <class V>
void visit(V& v, ImuSpec& i) {
  v.boolean("enabled", i.enabled);
  v.number("rate_hz", i.rate_hz, Limits{10.0, 2000.0});
  v.vec3("position_m", i.position_m, Limits{-2.0, 2.0}, Limits{0.0, 5.0});
  v.number("gyroscope_noise_density", i.gyroscope_noise_density, Limits{0.0, 1.0});
  v.number("gyroscope_random_walk", i.gyroscope_random_walk, Limits{0.0, 1.0});
  v.number("accelerometer_noise_density", i.accelerometer_noise_density, Limits{0.0, 10.0});
  v.number("accelerometer_random_walk", i.accelerometer_random_walk, Limits{0.0, 10.0});
}

template <class V>
void visit(V& v, Sensors& s) {
  v.object("camera", s.camera);
  v.object("depth", s.depth);
  v.object("color", s.color);
  v.object("wifi", s.wifi);
  v.object("odometry", s.odometry);
  v.object("imu", s.imu);
  v.uint64("time_origin_s", s.time_origin_s, dataset::kMaxTimeOriginS);
}

template <class V>
void visit(V& v, WallLossOverrides& w) {
  for (const auto& [material, name] : material_names())
    v.optional_number(name.data(), w.by_material_db[static_cast<int>(material)],
                      Limits{0.0, 100.0});  // names are literals: null-terminated
}

template <class V>
void visit(V& v, RadioSpec& r) {
  v.choice("model", r.model,
           Names<PathLossModel>{{PathLossModel::kItuWalls, "itu_walls"},
                                {PathLossModel::kItuSiteGeneral, "itu_site_general"},
                                {PathLossModel::kItuSiteGeneralFit, "itu_site_general_fit"}});
  v.choice("environment", r.environment,
           Names<RadioEnvironment>{{RadioEnvironment::kResidential, "residential"},
                                   {RadioEnvironment::kOffice, "office"},
                                   {RadioEnvironment::kCommercial, "commercial"}});
  v.optional_number("distance_coefficient", r.distance_coefficient, Limits{10.0, 60.0});
  v.optional_number("shadowing_sigma_db", r.shadowing_sigma_db, Limits{0.0, 30.0});
  // Gudmundson distances are metres indoors; the field's grid cell is a quarter of this, so a
  // tiny value asked for more cells than memory holds.
  v.number("shadowing_decorrelation_m", r.shadowing_decorrelation_m, Limits{0.5, 1000.0});
  v.number("fast_fading_sigma_db", r.fast_fading_sigma_db, Limits{0.0, 30.0});
  v.number("fading_coherence_s", r.fading_coherence_s, Limits{0.01, 3600.0});
  v.number("bssid_spread_db", r.bssid_spread_db, Limits{0.0, 10.0});
  v.number("people_disturbance_db", r.people_disturbance_db, Limits{0.0, 100.0});
  v.object("wall_loss_db", r.wall_loss_db);
}

template <class V>
void visit(V& v, Scene& s) {
  v.required();
  v.integer("version", s.version, Limits{1, 1});
  v.text("name", s.name);
  v.text("description", s.description);
  v.uint64("seed", s.seed);
  v.optional_uint64("session", s.session);
  v.object("building", s.building);
  v.list_if_any("levels", s.levels);
  // A scene has corridors (on nodes) or spaces, or both (validate_scene checks).
  v.list("nodes", s.nodes);
  v.list("corridors", s.corridors);
  v.list("open_areas", s.open_areas);
  v.list_if_any("spaces", s.spaces);
  v.list_if_any("doors", s.doors);
  v.list_if_any("obstacles", s.obstacles);
  v.object("appearance", s.appearance);
  v.object("access_points", s.access_points);
  v.required();
  v.object("route", s.route);
  v.object("sensors", s.sensors);
  v.object("radio", s.radio);
}

}  // namespace wifislam::sim::scene::schema
