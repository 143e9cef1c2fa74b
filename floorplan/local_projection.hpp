#pragma once
// Longitude/latitude (WGS 84) to a local metric frame and back, through PROJ (via GDAL's OGR
// spatial references): a transverse Mercator centred on the plan, scale 1 on its central meridian,
// origin at the centre, x east and y north in metres. Over a building (< 1 km) its scale error is
// below 1e-8, so distances and angles in the scene are the building's own.

#include <string>

#include <Eigen/Core>

namespace wifislam::floorplan {

class LocalProjection {
 public:
  /// The frame centred at (lon, lat) in degrees.
  LocalProjection(double centre_lon_deg, double centre_lat_deg);
  ~LocalProjection();
  LocalProjection(const LocalProjection&) = delete;
  LocalProjection& operator=(const LocalProjection&) = delete;
  LocalProjection(LocalProjection&&) noexcept;
  LocalProjection& operator=(LocalProjection&&) noexcept;

  Eigen::Vector2d to_local_m(const Eigen::Vector2d& lon_lat_deg) const;
  Eigen::Vector2d to_lon_lat_deg(const Eigen::Vector2d& local_m) const;
  /// The PROJ definition, written into imported scenes so that anyone can map back.
  const std::string& proj_definition() const { return definition_; }
  Eigen::Vector2d centre_lon_lat_deg() const { return centre_; }

 private:
  struct Transforms;
  Eigen::Vector2d centre_;
  std::string definition_;
  Transforms* transforms_ = nullptr;
};

}  // namespace wifislam::floorplan
