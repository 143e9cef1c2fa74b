#pragma once
// The in-memory form of a scene file (scenes/README.md documents every key, unit and default).
// The YAML loader (scene_loader.hpp) fills these structs and validates them; everything
// downstream (world generator, renderer, radio model, robot) reads only these structs.
// Defaults live here, next to the field, with what they trade off.

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/camera_intrinsics.hpp"
#include "core/dataset_format.hpp"
#include "radio_model/path_loss_choice.hpp"
#include "radio_model/radio_defaults.hpp"
#include "radio_model/receiver_device.hpp"
#include "radio_model/wall_material.hpp"

namespace wifislam::sim::scene {

/// The radio model's vocabulary, as the scene file names it.
using radio_model::PathLossModel;
using radio_model::RadioEnvironment;
using radio_model::wall_material_from_string;
using radio_model::WallMaterial;

/// One storey of a building of several (scene key `levels:`). Every piece of the plan (node,
/// open area, space, door, obstacle, listed access point) names its level in its `level` key;
/// corridors are on their nodes' level. A scene without `levels:` has one level, at 0 m, and
/// its pieces name none. Coordinates are the building's: x and y shared by every level, z up.
struct Level {
  std::string id;
  /// Height of the level's floor (top of its slab). Default: the level below's elevation plus
  /// its storey height, 0 m for the first.
  std::optional<double> elevation_m;
  /// Floor to the next level's floor. Default: building.wall_height_m plus the slab thickness
  /// of the next level in the file (of this one for the last), walls reaching the slab above.
  std::optional<double> storey_height_m;
  /// The slab under the level's floor, between it and the level below: its material costs a
  /// floor's loss to a link that crosses it (radio_model/propagation_model.hpp).
  double slab_thickness_m = 0.3;
  WallMaterial slab_material = WallMaterial::kConcrete;
};

struct SceneNode {
  std::string id;
  Eigen::Vector2d position_m = Eigen::Vector2d::Zero();
  std::string level = {};  // empty: the first level
};

/// A row of rooms along one side of a corridor, between `from_m` and `to_m` measured along
/// the corridor from its `from` node. Each room is `room_length_m` long (the last one takes what
/// is left if that is at least half a room), `depth_m` deep, separated from the corridor by a
/// wall of `material` with one door `door_width_m` wide whose near edge is `door_offset_m` from
/// the room's start.
struct RoomRow {
  enum class Side { kLeft, kRight, kBoth };
  Side side = Side::kBoth;  // left/right as seen walking from the corridor's `from` node
  double from_m = 0.0;
  std::optional<double> to_m;  // default: the corridor's length
  double room_length_m = 4.0;
  double depth_m = 4.0;
  double door_offset_m = 1.5;
  double door_width_m = 0.9;
  bool doors_open = false;  // closed doors are wooden leaves in the opening
  WallMaterial material = WallMaterial::kBrick;
};

struct Corridor {
  std::string id;
  std::string from, to;  // node ids
  double width_m = 2.0;
  WallMaterial material = WallMaterial::kPlasterboard;
  std::vector<RoomRow> rooms;
};

/// An open area (hall, atrium, track): free space given as a simple polygon (counter-clockwise
/// or clockwise, at least 3 vertices), with optional square pillars inside.
struct OpenArea {
  std::string id;
  std::string level = {};  // empty: the first level
  std::vector<Eigen::Vector2d> polygon_m;
  WallMaterial material = WallMaterial::kConcrete;
  struct Pillar {
    Eigen::Vector2d center_m = Eigen::Vector2d::Zero();
    double size_m = 0.6;
  };
  std::vector<Pillar> pillars;
};

/// What a space given as a polygon is (spaces: floor plans imported from real buildings).
enum class SpaceKind {
  kCorridor,  // walkable, its walls take its material unless a room is on their other side
  kArea,      // walkable open space (a hall, a lobby), lowest rank for wall materials
  kRoom,      // free space the robot does not enter; rooms' walls take the room's material
};
const char* to_string(SpaceKind kind);

/// A piece of free space given directly as a simple polygon, as `wifislam import` writes from a
/// real floor plan. Walls of `building.wall_thickness_m` grow around it as around corridors, so
/// two spaces meant to share a wall must lie exactly one wall thickness apart.
struct Space {
  std::string id;
  std::string level = {};  // empty: the first level
  SpaceKind kind = SpaceKind::kRoom;
  std::vector<Eigen::Vector2d> polygon_m;
  WallMaterial material = WallMaterial::kBrick;
  std::string name;  // the plan's own name for it, if any (for people; not used)
};

/// A doorway through the wall between two spaces, from one jamb to the other along the wall's
/// centre line. Its opening is one wall thickness deep; a closed door is a wooden leaf in it.
struct SpaceDoor {
  Eigen::Vector2d from_m = Eigen::Vector2d::Zero();
  Eigen::Vector2d to_m = Eigen::Vector2d::Zero();
  bool open = false;
  std::string level = {};  // empty: the first level
};

/// A solid block inside free space (a column, a shaft, a stair core), as a simple polygon.
struct Obstacle {
  std::vector<Eigen::Vector2d> polygon_m;
  std::string level = {};  // empty: the first level
};

struct Building {
  double wall_height_m = 2.8;
  double wall_thickness_m = 0.15;
};

/// Texture themes by name; the renderer maps each name to a procedural recipe.
struct AppearanceThemes {
  std::string wall = "painted";
  std::string door = "wood";
  std::string floor = "tiles";
  std::string ceiling = "panels";
};

/// A poster or other landmark placed explicitly on the wall nearest to (x, y).
struct Landmark {
  Eigen::Vector2d position_m = Eigen::Vector2d::Zero();
  double height_m = 1.5;  // centre height
  double width_m = 0.6;
  std::string kind = "poster";
};

/// What the shared look of aliased segments is shared over.
enum class AliasingScope {
  /// One look for every aliased segment: neighbouring segments of a wall repeat each other, so a
  /// corridor is self-similar every `segment_length_m` (the hardest case for any place
  /// recognition, Wi-Fi included).
  kSegment,
  /// One look per position along a wall (1st segment, 2nd, ...) of a given length: walls of equal
  /// length are copies of one another while a wall never repeats within itself, i.e. corridors
  /// that all look alike but are distinct inside. Look-alike places are then a corridor apart.
  kPosition,
};

struct Appearance {
  /// 1 = every wall segment looks identical (same paint, same posters, same lights); 0 = every
  /// segment visually unique. Segments are `segment_length_m` pieces of wall; each segment
  /// independently uses the shared look with probability `aliasing`, else its own.
  double aliasing = 0.5;
  AliasingScope aliasing_scope = AliasingScope::kSegment;
  double segment_length_m = 4.0;
  AppearanceThemes themes;
  double posters_per_10m = 1.5;  // expected posters per 10 m of corridor wall
  double light_spacing_m = 3.0;  // ceiling lights along corridors
  std::vector<Landmark> landmarks;
};

enum class ApPlacement { kExplicit, kGrid, kRandom, kRooms, kColinear };
const char* to_string(ApPlacement placement);

struct AccessPointSpec {
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();  // z: height above its level's floor
  std::optional<double> tx_power_dbm;
  std::string level = {};  // empty: the first level
};

/// Generated placements (all but explicit) place `count` access points on every level, each
/// level's from its own plan and its own stream (sim/site/ap_placement.hpp).
enum class AccessPointChangeKind { kOff, kMoved, kPower, kNew };
const char* to_string(AccessPointChangeKind kind);

/// A change to the building's access points from one session on (sim/site/ap_changes.hpp): the
/// AP `ap` (its id, access_points.csv's ap_id) is switched off, moved to `position_m` or stepped
/// by `tx_power_step_db`, or a new AP is installed at `position_m`. It holds in session `session`
/// and every later one.
struct AccessPointChange {
  int session = 1;
  AccessPointChangeKind change = AccessPointChangeKind::kOff;
  std::optional<std::uint64_t> ap;            // off, moved, power
  std::optional<Eigen::Vector3d> position_m;  // moved, new (z above the AP's level's floor)
  double tx_power_step_db = 0.0;              // power
  std::optional<double> tx_power_dbm;         // new; default access_points.tx_power_dbm
  std::string level = {};                     // new, in a building of several levels
};

struct AccessPoints {
  ApPlacement placement = ApPlacement::kRooms;
  int count = 0;
  std::optional<std::uint64_t> seed;  // default: derived from the scene seed
  double height_m = 2.5;
  double tx_power_dbm = 20.0;
  int ssids_per_radio = 3;     // BSSIDs per radio (2.4 GHz and 5 GHz radios per AP)
  double min_spacing_m = 3.0;  // random/rooms placements keep APs at least this far apart
  std::vector<AccessPointSpec> explicit_list;  // placement: explicit
  // placement: colinear — APs evenly spaced on the segment from `line_from_m` to `line_to_m`
  Eigen::Vector2d line_from_m = Eigen::Vector2d::Zero();
  Eigen::Vector2d line_to_m = Eigen::Vector2d::Zero();
  /// Changes by session (the building as it is in later sessions), in the order they happen.
  std::vector<AccessPointChange> changes;
};

struct PauseSpec {
  double spacing_min_m = 3.0;  // distance travelled between pauses, drawn per pause
  double spacing_max_m = 4.0;
  double duration_s = 10.0;
  bool scan_while_moving = false;
};

struct Route {
  std::vector<std::string> nodes;  // consecutive nodes must share a corridor
  /// Instead of nodes: the route as points in walkable space (scenes of imported plans, whose
  /// spaces have no corridor graph). Legs are straight; corners are rounded as for nodes.
  std::vector<Eigen::Vector2d> waypoints_m;
  double speed_mps = 0.5;
  double max_yaw_rate_radps = 0.6;
  double turn_radius_m = 0.6;  // corners are rounded with this radius
  double min_wall_clearance_m = 0.3;
  PauseSpec pause;
  /// The level the route runs on (empty: the first level). A route stays on one level.
  std::string level;
};

/// The frame rates a scene's camera (and every --fps) may have. The schedule counts frames over
/// the route, so an unbounded rate would count for ever.
inline constexpr double kMinCameraFps = 0.1;
inline constexpr double kMaxCameraFps = 1000.0;

struct CameraSpec {
  CameraIntrinsics intrinsics;  // default Kinect v1
  double fps = 30.0;
  double height_m = 0.5;   // above the floor (Kinect on a TurtleBot)
  double pitch_deg = 0.0;  // positive looks up
};

struct DepthSensorSpec {
  double min_range_m = 0.8;
  double max_range_m = 4.0;
  bool noise = true;         // axial noise growing with depth squared
  bool quantisation = true;  // disparity-style steps
  bool dropouts = true;      // grazing angles and depth edges
  // Parameters of the parts above (sim/render/depth_sensor_model.hpp explains each model).
  double axial_noise_coeff_per_m = 1.425e-3;  // sigma_z = coeff * z^2 (Khoshelham & Elberink 2012)
  double baseline_m = 0.075;                  // projector-camera baseline for disparity d = f b / z
  double disparity_step_px = 0.125;           // disparity resolution (Kinect v1: 1/8 pixel)
  double grazing_dropout_deg = 82.0;  // no reading when the ray meets the surface steeper than this
  double edge_jump_fraction = 0.05;   // a neighbour farther by this fraction of z marks an edge
  // Lateral noise, off by default (scenes/README.md says why): each pixel reads the depth at a
  // random whole-pixel shift with sigma_L = base + coeff theta / (pi/2 - theta) px per axis
  // (Nguyen, Izadi and Lovell 2012: 0.8 and 0.035), theta capped at grazing_dropout_deg.
  bool lateral_noise = false;
  double lateral_noise_base_px = 0.8;
  double lateral_noise_angle_coeff_px = 0.035;
};

/// The colour camera's sensor (sim/render/color_sensor_model.hpp explains each model). Both
/// parts are off by default (scenes/README.md says why).
struct ColorSensorSpec {
  // Shot + read noise per channel: variance (DN^2) = conversion_gain x I + read_noise^2, I the
  // exposed intensity in 8-bit digital numbers (the Poissonian-Gaussian model of EMVA 1288).
  bool noise = false;
  double conversion_gain_dn_per_e = 0.05;  // 20 electrons per DN: 255 DN ~ 5100 e- full well
  double read_noise_dn = 0.5;              // 10 e- rms
  // A global gain that moves the frame's mean brightness toward a target, first order in log
  // gain with a time constant in seconds, starting at gain 1.
  bool auto_exposure = false;
  double exposure_target_dn = 118.0;  // 18 % grey in sRGB (0.46 x 255)
  double exposure_time_constant_s = 0.5;
  double exposure_min_gain = 0.25, exposure_max_gain = 4.0;  // +-2 stops
};

/// The Wi-Fi scanner: the device that scans and how often the app asks it to.
struct WifiScannerSpec {
  /// The receiver (radio_model/receiver_device.hpp): a shipped device by name, a device file or
  /// an inline mapping. None: the reference receiver with the two keys below, which a scene that
  /// names a device must leave to its device.
  std::optional<radio_model::ReceiverDevice> device;
  double sensitivity_dbm = radio_model::defaults::kSensitivityDbm;
  double dwell_per_channel_s = radio_model::defaults::kDwellPerChannelS;
  double scan_interval_s = 2.0;  // time from one scan request's start to the next's
};

/// The device a scene's scanner is: its named device, or the reference receiver with the
/// block's sensitivity and dwell.
radio_model::ReceiverDevice receiver_device(const WifiScannerSpec& spec);

struct OdometrySpec {
  double rate_hz = 50.0;
  double noise_per_m = 0.02;      // std dev of distance error per metre travelled (m/m)
  double noise_per_rad = 0.03;    // std dev of heading error per radian turned (rad/rad)
  double scale_error = 0.01;      // systematic multiplicative error on distance
  double yaw_bias_radpm = 0.002;  // systematic heading drift per metre (rad/m)
};

/// The IMU (sim/robot/imu_model.hpp): rigidly mounted on the robot base, its axes those of the
/// base (x forward, y left, z up), at `position_m` in the base frame. Noise parameters are
/// continuous-time, in the Kalibr/Allan convention; the defaults are the EuRoC MAV dataset's
/// VI-Sensor IMU (ADIS16448, imu0/sensor.yaml), a common MEMS IMU many VIO systems ship settings
/// for.
struct ImuSpec {
  bool enabled = true;  // false: no imu.csv
  double rate_hz = 200.0;
  Eigen::Vector3d position_m{0.0, 0.0, 0.1};    // on the base plate, under the camera
  double gyroscope_noise_density = 1.6968e-4;   // rad / s / sqrt(Hz)
  double gyroscope_random_walk = 1.9393e-5;     // rad / s^2 / sqrt(Hz)
  double accelerometer_noise_density = 2.0e-3;  // m / s^2 / sqrt(Hz)
  double accelerometer_random_walk = 3.0e-3;    // m / s^3 / sqrt(Hz)
};

struct Sensors {
  CameraSpec camera;
  DepthSensorSpec depth;
  ColorSensorSpec color;
  WifiScannerSpec wifi;
  OdometrySpec odometry;
  ImuSpec imu;
  /// Unix time (whole seconds) of the route's start: every time a dataset or the in-memory
  /// stream carries is route time plus this (core/dataset_format.hpp). The simulation itself
  /// runs on route time, so the origin changes no pixel, pose or RSSI. 0 = times from 0 s.
  std::uint64_t time_origin_s = dataset::kDefaultTimeOriginS;
};

/// Measured per-wall losses by material (`radio calibrate` writes them), indexed like
/// WallMaterial. A set value replaces that material's default loss law (wall_materials.hpp) by
/// this loss at every frequency: a survey measures one band, so no frequency law is fitted.
struct WallLossOverrides {
  std::array<std::optional<double>, 5> by_material_db;
};

struct RadioSpec {
  PathLossModel model = PathLossModel::kItuWalls;
  RadioEnvironment environment = RadioEnvironment::kOffice;
  std::optional<double> distance_coefficient;  // N; default chosen by the radio model
  std::optional<double> shadowing_sigma_db;    // default chosen by the radio model
  // Defaults: the radio model's (radio_model/radio_defaults.hpp).
  double shadowing_decorrelation_m = radio_model::defaults::kShadowingDecorrelationM;
  double fast_fading_sigma_db = radio_model::defaults::kFastFadingSigmaDb;     // per radio
  double fading_coherence_s = radio_model::defaults::kFadingCoherenceS;        // still receiver
  double bssid_spread_db = radio_model::defaults::kBssidSpreadDb;              // per BSSID and scan
  double people_disturbance_db = radio_model::defaults::kPeopleDisturbanceDb;  // open halls
  WallLossOverrides wall_loss_db;  // itu_walls only; unset materials keep their laws
};

struct Scene {
  int version = 1;
  std::string name;
  std::string description;
  std::uint64_t seed = 1;
  /// Which visit of the building this is (`generate --session K`): the building (walls,
  /// appearance, access points as changed by then, shadowing) is the same in every session; the
  /// robot's pauses, every sensor's noise and the Wi-Fi draws are a session's own (session_seed).
  /// Unset: session 0.
  std::optional<std::uint64_t> session;
  Building building;
  std::vector<Level> levels;  // empty: one level at 0 m (sim/scene/scene_levels.hpp)
  std::vector<SceneNode> nodes;
  std::vector<Corridor> corridors;
  std::vector<OpenArea> open_areas;
  std::vector<Space> spaces;
  std::vector<SpaceDoor> doors;
  std::vector<Obstacle> obstacles;
  Appearance appearance;
  AccessPoints access_points;
  Route route;
  Sensors sensors;
  RadioSpec radio;

  /// The file it was loaded from (empty for scenes built in code); used in error messages.
  std::string source_path;
  /// "file:line:column" of every key path the loader read (e.g. "route.nodes[2]"), so that
  /// problems found after loading (the floor plan, the route, AP placement) are located too.
  std::map<std::string, std::string> key_locations;
  /// In one level's part of a scene (scene_on_level): the list items renumbered, new key path to
  /// the file's ("spaces[0]" -> "spaces[7]"), so that messages name the keys the file has.
  std::map<std::string, std::string> key_paths_in_file;

  /// Where `key_path`, or its closest parent key found in the file, is written:
  /// "file:line:column", else the file, else "scene" (built in code).
  std::string where(std::string key_path) const;
  /// Throws ParseError at `key_path` (exit 2 on the command line): bad input found after loading.
  /// For a scene built in code, InvalidInputError naming the key (as validate_scene does).
  [[noreturn]] void reject(const std::string& key_path, const std::string& message) const;
  /// `key_path` as the file writes it (key_paths_in_file; unchanged outside a level's part).
  std::string key_path_in_file(const std::string& key_path) const;

  const SceneNode* find_node(const std::string& id) const;
  const Corridor* find_corridor(const std::string& id) const;
  /// The corridor joining nodes a and b (either direction), or nullptr.
  const Corridor* corridor_between(const std::string& a, const std::string& b) const;
};

/// The seed of what differs between sessions (the robot's pauses, sensor noise, Wi-Fi draws):
/// the scene's seed in session 0, so a scene without `session` is what it always was; a stream
/// of its own for each later session, independent of the others.
std::uint64_t session_seed(const Scene& scene);
int session_of(const Scene& scene);

}  // namespace wifislam::sim::scene
