#pragma once
// One level of a real floor plan in scene terms: spaces, doors and obstacles in a local metric
// frame, the plan's navigation paths, and what was read and kept (for the import report and the
// tests that check counts against the file's own).

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "floorplan/geos_geometry.hpp"
#include "floorplan/space_partition.hpp"
#include "sim/scene/scene.hpp"

namespace wifislam::floorplan {

enum class PlanFormat { kOsmSit, kWrld, kImdf };
const char* to_string(PlanFormat format);

struct ImportOptions {
  std::optional<PlanFormat> format;  // default: from the file's contents
  std::optional<std::string> level;  // default: the lowest level with walkable space
  double wall_thickness_m = 0.15;    // OSM; WRLD measures its own walls
  double door_width_m = 0.9;         // inferred doors (OSM)
};

/// What the file held on the chosen level and what the scene kept of it.
struct ImportCounts {
  int rooms = 0, corridors = 0, areas = 0;         // features read, by kind
  int walls = 0, doors = 0, windows = 0;           // WRLD features read
  int skipped = 0;                                 // features on the level with no use (stairs ...)
  int spaces = 0, space_doors = 0, obstacles = 0;  // written to the scene
  int rooms_without_door = 0;                      // OSM: rooms touching no corridor or area
  int doors_not_placed = 0;  // WRLD door polygons, IMDF openings on no shared wall
};

struct ImportedPlan {
  PlanFormat format = PlanFormat::kOsmSit;
  std::string source;  // the plan file as given
  std::string level;
  std::vector<std::string> levels;  // every level the file has
  Eigen::Vector2d centre_lon_lat_deg = Eigen::Vector2d::Zero();
  std::string projection;  // PROJ definition of the local frame
  double wall_thickness_m = 0.15;
  std::vector<sim::scene::Space> spaces;
  std::vector<sim::scene::SpaceDoor> doors;
  std::vector<sim::scene::Obstacle> obstacles;
  std::vector<Ring> paths_m;  // navigation paths on the level, if the plan has any
  ImportCounts counts;
  std::vector<std::string> notes;  // choices made, for the scene's header and the report
  // Every file the import read (the plan, and main.json, level, paths or opening files beside
  // it): the scene must not be written over any of them.
  std::vector<std::filesystem::path> input_files;
};

/// A door for the partition's inputs `a` and `b`, with what it joins.
struct PlacedDoor {
  int a = -1, b = -1;
  sim::scene::SpaceDoor door;
};

/// Writes the partition's pieces as spaces (holes as obstacles) and the doors into `plan`;
/// pieces of walkable spaces that no open door joins to the largest walkable group become rooms
/// (the robot's space must be one piece), noted in plan.notes. The strips plan.obstacles cut off
/// the pieces become part of them first (obstacle_strips.hpp).
void finish_plan(const GeosContext& geos, const std::vector<SpaceInput>& inputs,
                 const Partition& partition, const PartitionOptions& partition_options,
                 const std::vector<PlacedDoor>& doors, ImportedPlan& plan);

}  // namespace wifislam::floorplan
