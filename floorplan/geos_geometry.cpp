#include "floorplan/geos_geometry.hpp"

#include <geos_c.h>

#include <cstdarg>
#include <cstdio>
#include <stdexcept>
#include <utility>

#include "core/error.hpp"

namespace wifislam::floorplan {

namespace {

GEOSContextHandle_t ctx(const GeosContext& c) {
  return static_cast<GEOSContextHandle_t>(c.handle());
}
GEOSGeometry* geom(void* g) { return static_cast<GEOSGeometry*>(g); }

thread_local std::string last_geos_error;

void geos_error(const char* fmt, ...) {
  // GEOS reports errors through this handler and returns null; the null becomes our error.
  char text[512];
  va_list args;
  va_start(args, fmt);
  std::vsnprintf(text, sizeof text, fmt, args);
  va_end(args);
  last_geos_error = text;
}

void geos_notice(const char*, ...) {}

GEOSCoordSequence* sequence(GEOSContextHandle_t h, const Ring& ring, bool closed) {
  const unsigned n = static_cast<unsigned>(ring.size()) + (closed ? 1u : 0u);
  GEOSCoordSequence* seq = GEOSCoordSeq_create_r(h, n, 2);
  for (unsigned i = 0; i < n; ++i) {
    const Eigen::Vector2d& p = ring[i % ring.size()];
    GEOSCoordSeq_setXY_r(h, seq, i, p.x(), p.y());
  }
  return seq;
}

Ring read_sequence(GEOSContextHandle_t h, const GEOSCoordSequence* seq, bool drop_closing) {
  unsigned n = 0;
  GEOSCoordSeq_getSize_r(h, seq, &n);
  Ring out;
  for (unsigned i = 0; i < n; ++i) {
    double x = 0, y = 0;
    GEOSCoordSeq_getXY_r(h, seq, i, &x, &y);
    out.emplace_back(x, y);
  }
  if (drop_closing && out.size() > 1 && out.front() == out.back()) out.pop_back();
  return out;
}

void collect_polygons(GEOSContextHandle_t h, const GEOSGeometry* g,
                      std::vector<PolygonRings>& out) {
  const int type = GEOSGeomTypeId_r(h, g);
  if (type == GEOS_POLYGON) {
    if (GEOSisEmpty_r(h, g)) return;
    PolygonRings rings;
    rings.outer = read_sequence(h, GEOSGeom_getCoordSeq_r(h, GEOSGetExteriorRing_r(h, g)), true);
    for (int i = 0, n = GEOSGetNumInteriorRings_r(h, g); i < n; ++i)
      rings.holes.push_back(
          read_sequence(h, GEOSGeom_getCoordSeq_r(h, GEOSGetInteriorRingN_r(h, g, i)), true));
    out.push_back(std::move(rings));
  } else if (type == GEOS_MULTIPOLYGON || type == GEOS_GEOMETRYCOLLECTION) {
    for (int i = 0, n = GEOSGetNumGeometries_r(h, g); i < n; ++i)
      collect_polygons(h, GEOSGetGeometryN_r(h, g, i), out);
  }
}

void collect_lines(GEOSContextHandle_t h, const GEOSGeometry* g, std::vector<Ring>& out) {
  const int type = GEOSGeomTypeId_r(h, g);
  if (type == GEOS_LINESTRING || type == GEOS_LINEARRING) {
    if (!GEOSisEmpty_r(h, g)) out.push_back(read_sequence(h, GEOSGeom_getCoordSeq_r(h, g), false));
  } else if (type == GEOS_POLYGON) {
    if (GEOSisEmpty_r(h, g)) return;
    collect_lines(h, GEOSGetExteriorRing_r(h, g), out);
    for (int i = 0, n = GEOSGetNumInteriorRings_r(h, g); i < n; ++i)
      collect_lines(h, GEOSGetInteriorRingN_r(h, g, i), out);
  } else if (type >= GEOS_MULTIPOINT) {
    for (int i = 0, n = GEOSGetNumGeometries_r(h, g); i < n; ++i)
      collect_lines(h, GEOSGetGeometryN_r(h, g, i), out);
  }
}

}  // namespace

GeosContext::GeosContext() {
  GEOSContextHandle_t h = GEOS_init_r();
  GEOSContext_setErrorHandler_r(h, geos_error);
  GEOSContext_setNoticeHandler_r(h, geos_notice);
  handle_ = h;
}

GeosContext::~GeosContext() { GEOS_finish_r(static_cast<GEOSContextHandle_t>(handle_)); }

Geometry::Geometry(const GeosContext& context, void* handle) : context_(&context), handle_(handle) {
  if (handle_ == nullptr)
    throw InvalidInputError("a polygon operation failed (GEOS: " + last_geos_error + ")");
}

Geometry::Geometry(Geometry&& other) noexcept
    : context_(other.context_), handle_(std::exchange(other.handle_, nullptr)) {}

Geometry& Geometry::operator=(Geometry&& other) noexcept {
  if (this != &other) {
    release();
    context_ = other.context_;
    handle_ = std::exchange(other.handle_, nullptr);
  }
  return *this;
}

Geometry::~Geometry() { release(); }

void* Geometry::release_handle() { return std::exchange(handle_, nullptr); }

void Geometry::release() {
  if (handle_ != nullptr) GEOSGeom_destroy_r(ctx(*context_), geom(handle_));
  handle_ = nullptr;
}

bool Geometry::empty() const {
  return handle_ == nullptr || GEOSisEmpty_r(ctx(*context_), geom(handle_)) == 1;
}

double Geometry::area_m2() const {
  double a = 0;
  if (handle_ != nullptr) GEOSArea_r(ctx(*context_), geom(handle_), &a);
  return a;
}

double Geometry::length_m() const {
  double l = 0;
  if (handle_ != nullptr) GEOSLength_r(ctx(*context_), geom(handle_), &l);
  return l;
}

std::string Geometry::invalid_reason() const {
  if (GEOSisValid_r(ctx(*context_), geom(handle_)) == 1) return "";
  char* reason = GEOSisValidReason_r(ctx(*context_), geom(handle_));
  std::string out = reason != nullptr ? reason : "invalid geometry";
  GEOSFree_r(ctx(*context_), reason);
  return out;
}

std::vector<PolygonRings> Geometry::polygons() const {
  std::vector<PolygonRings> out;
  if (handle_ != nullptr) collect_polygons(ctx(*context_), geom(handle_), out);
  return out;
}

std::vector<Ring> Geometry::lines() const {
  std::vector<Ring> out;
  if (handle_ != nullptr) collect_lines(ctx(*context_), geom(handle_), out);
  return out;
}

Geometry Geometry::buffer_mitre(double distance_m) const {
  // Mitre limit 2: a right-angle corner stays sharp (ratio sqrt 2), sharper spikes are bevelled.
  return Geometry(*context_, GEOSBufferWithStyle_r(ctx(*context_), geom(handle_), distance_m, 8,
                                                   GEOSBUF_CAP_FLAT, GEOSBUF_JOIN_MITRE, 2.0));
}

Geometry Geometry::united(const Geometry& other) const {
  return Geometry(*context_, GEOSUnion_r(ctx(*context_), geom(handle_), geom(other.handle_)));
}

Geometry Geometry::minus(const Geometry& other) const {
  return Geometry(*context_, GEOSDifference_r(ctx(*context_), geom(handle_), geom(other.handle_)));
}

Geometry Geometry::intersected(const Geometry& other) const {
  return Geometry(*context_,
                  GEOSIntersection_r(ctx(*context_), geom(handle_), geom(other.handle_)));
}

Geometry Geometry::boundary() const {
  return Geometry(*context_, GEOSBoundary_r(ctx(*context_), geom(handle_)));
}

Geometry Geometry::snapped(double grid_m) const {
  return Geometry(*context_, GEOSGeom_setPrecision_r(ctx(*context_), geom(handle_), grid_m, 0));
}

Geometry Geometry::simplified(double tolerance_m) const {
  return Geometry(*context_,
                  GEOSTopologyPreserveSimplify_r(ctx(*context_), geom(handle_), tolerance_m));
}

Geometry Geometry::clone() const {
  return Geometry(*context_, GEOSGeom_clone_r(ctx(*context_), geom(handle_)));
}

Geometry Geometry::polygonal() const {
  GEOSContextHandle_t h = ctx(*context_);
  const int type = GEOSGeomTypeId_r(h, geom(handle_));
  if (type == GEOS_POLYGON || type == GEOS_MULTIPOLYGON) return clone();
  std::vector<GEOSGeometry*> parts;
  for (const PolygonRings& p : polygons())
    parts.push_back(geom(context_->polygon(p).release_handle()));
  return Geometry(*context_, GEOSGeom_createCollection_r(h, GEOS_MULTIPOLYGON, parts.data(),
                                                         static_cast<unsigned>(parts.size())));
}

Geometry GeosContext::polygon(const PolygonRings& rings) const {
  GEOSContextHandle_t h = ctx(*this);
  if (rings.outer.size() < 3) return empty_polygon();
  GEOSGeometry* shell = GEOSGeom_createLinearRing_r(h, sequence(h, rings.outer, true));
  std::vector<GEOSGeometry*> holes;
  for (const Ring& hole : rings.holes)
    if (hole.size() >= 3) holes.push_back(GEOSGeom_createLinearRing_r(h, sequence(h, hole, true)));
  return Geometry(
      *this, GEOSGeom_createPolygon_r(h, shell, holes.data(), static_cast<unsigned>(holes.size())));
}

Geometry GeosContext::line(const Ring& points) const {
  GEOSContextHandle_t h = ctx(*this);
  return Geometry(*this, GEOSGeom_createLineString_r(h, sequence(h, points, false)));
}

Geometry GeosContext::empty_polygon() const {
  return Geometry(*this, GEOSGeom_createEmptyPolygon_r(ctx(*this)));
}

Geometry GeosContext::union_all(const std::vector<const Geometry*>& parts) const {
  GEOSContextHandle_t h = ctx(*this);
  if (parts.empty()) return empty_polygon();
  std::vector<GEOSGeometry*> clones;
  for (const Geometry* p : parts) clones.push_back(GEOSGeom_clone_r(h, geom(p->get())));
  GEOSGeometry* collection = GEOSGeom_createCollection_r(h, GEOS_GEOMETRYCOLLECTION, clones.data(),
                                                         static_cast<unsigned>(clones.size()));
  GEOSGeometry* u = GEOSUnaryUnion_r(h, collection);
  GEOSGeom_destroy_r(h, collection);
  return Geometry(*this, u);
}

}  // namespace wifislam::floorplan
