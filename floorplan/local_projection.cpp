#include "floorplan/local_projection.hpp"

#include <ogr_spatialref.h>

#include <utility>

#include <fmt/format.h>

#include "core/error.hpp"

namespace wifislam::floorplan {

struct LocalProjection::Transforms {
  OGRSpatialReference wgs84, local;
  OGRCoordinateTransformation* forward = nullptr;
  OGRCoordinateTransformation* inverse = nullptr;
  ~Transforms() {
    OGRCoordinateTransformation::DestroyCT(forward);
    OGRCoordinateTransformation::DestroyCT(inverse);
  }
};

LocalProjection::LocalProjection(double centre_lon_deg, double centre_lat_deg)
    : centre_(centre_lon_deg, centre_lat_deg),
      definition_(fmt::format("+proj=tmerc +lat_0={:.9f} +lon_0={:.9f} +k=1 +x_0=0 +y_0=0 "
                              "+ellps=WGS84 +units=m +no_defs",
                              centre_lat_deg, centre_lon_deg)),
      transforms_(new Transforms) {
  transforms_->wgs84.SetWellKnownGeogCS("WGS84");
  // GeoJSON is lon/lat; GDAL 3 otherwise follows the EPSG axis order (lat first).
  transforms_->wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  if (transforms_->local.importFromProj4(definition_.c_str()) != OGRERR_NONE)
    throw InvalidInputError("cannot build the local projection " + definition_);
  transforms_->local.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  transforms_->forward =
      OGRCreateCoordinateTransformation(&transforms_->wgs84, &transforms_->local);
  transforms_->inverse =
      OGRCreateCoordinateTransformation(&transforms_->local, &transforms_->wgs84);
  if (transforms_->forward == nullptr || transforms_->inverse == nullptr)
    throw InvalidInputError("PROJ cannot transform WGS 84 to " + definition_);
}

LocalProjection::~LocalProjection() { delete transforms_; }

LocalProjection::LocalProjection(LocalProjection&& other) noexcept
    : centre_(other.centre_),
      definition_(std::move(other.definition_)),
      transforms_(std::exchange(other.transforms_, nullptr)) {}

LocalProjection& LocalProjection::operator=(LocalProjection&& other) noexcept {
  if (this != &other) {
    delete transforms_;
    centre_ = other.centre_;
    definition_ = std::move(other.definition_);
    transforms_ = std::exchange(other.transforms_, nullptr);
  }
  return *this;
}

Eigen::Vector2d LocalProjection::to_local_m(const Eigen::Vector2d& lon_lat_deg) const {
  double x = lon_lat_deg.x(), y = lon_lat_deg.y();
  if (!transforms_->forward->Transform(1, &x, &y))
    throw InvalidInputError(
        fmt::format("cannot project lon {} lat {}", lon_lat_deg.x(), lon_lat_deg.y()));
  return {x, y};
}

Eigen::Vector2d LocalProjection::to_lon_lat_deg(const Eigen::Vector2d& local_m) const {
  double x = local_m.x(), y = local_m.y();
  if (!transforms_->inverse->Transform(1, &x, &y))
    throw InvalidInputError(fmt::format("cannot unproject ({}, {}) m", local_m.x(), local_m.y()));
  return {x, y};
}

}  // namespace wifislam::floorplan
