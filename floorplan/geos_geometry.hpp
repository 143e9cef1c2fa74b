#pragma once
// Planar polygon operations for imported floor plans, through GEOS (the library GDAL/OGR uses):
// buffers with mitred joins (OGR 3.6 offers only round ones, which would round every corner a
// plan's walls make), unions, differences, validity and precision snapping.
//
// One GeosContext per thread; geometries are owned by `Geometry` handles.

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace wifislam::floorplan {

using Ring = std::vector<Eigen::Vector2d>;

/// A polygon with holes in metres; rings are closed implicitly (first point not repeated).
struct PolygonRings {
  Ring outer;
  std::vector<Ring> holes;
};

class GeosContext;

/// An owned GEOS geometry (a polygon, multipolygon, line or collection; maybe empty).
class Geometry {
 public:
  Geometry() = default;
  Geometry(const GeosContext& context, void* handle);
  Geometry(Geometry&& other) noexcept;
  Geometry& operator=(Geometry&& other) noexcept;
  ~Geometry();
  void* get() const { return handle_; }
  /// Gives up ownership (for building collections).
  void* release_handle();
  bool empty() const;
  double area_m2() const;
  double length_m() const;
  /// The GEOS validity reason ("Self-intersection[x y]") or "" when valid.
  std::string invalid_reason() const;
  /// Its polygons (a polygon, or the polygons of a multipolygon/collection).
  std::vector<PolygonRings> polygons() const;
  /// Its line pieces as point lists (lines, multilines, or polygon boundaries).
  std::vector<Ring> lines() const;

  Geometry buffer_mitre(double distance_m) const;
  Geometry united(const Geometry& other) const;
  Geometry minus(const Geometry& other) const;
  Geometry intersected(const Geometry& other) const;
  Geometry boundary() const;
  /// Vertices snapped to a grid of `grid_m`, kept valid (GEOSGeom_setPrecision).
  Geometry snapped(double grid_m) const;
  /// Douglas-Peucker keeping the topology, within `tolerance_m`.
  Geometry simplified(double tolerance_m) const;
  Geometry clone() const;
  /// Only its polygons, as one (multi)polygon: overlays of touching polygons also give lines and
  /// points, which further polygon overlays refuse.
  Geometry polygonal() const;

 private:
  void release();
  const GeosContext* context_ = nullptr;
  void* handle_ = nullptr;
};

class GeosContext {
 public:
  GeosContext();
  ~GeosContext();
  GeosContext(const GeosContext&) = delete;
  GeosContext& operator=(const GeosContext&) = delete;
  void* handle() const { return handle_; }

  Geometry polygon(const PolygonRings& rings) const;
  Geometry line(const Ring& points) const;
  Geometry empty_polygon() const;
  /// Union of many (cascaded; empty input gives an empty polygon).
  Geometry union_all(const std::vector<const Geometry*>& parts) const;

 private:
  void* handle_ = nullptr;
};

}  // namespace wifislam::floorplan
