#include "radio_model/embree_wall_scene.hpp"

#include <embree3/rtcore.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <limits>
#include <optional>

#include <fmt/format.h>
#include <Eigen/Geometry>

#include "core/error.hpp"

namespace wifislam::radio_model {

namespace {

/// A ray from `origin` along `direction` (not normalised: t is in its units) over [tnear, tfar],
/// with no hit yet.
RTCRayHit make_ray(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, float tnear,
                   float tfar) {
  RTCRayHit rayhit;
  rayhit.ray.org_x = static_cast<float>(origin.x());
  rayhit.ray.org_y = static_cast<float>(origin.y());
  rayhit.ray.org_z = static_cast<float>(origin.z());
  rayhit.ray.dir_x = static_cast<float>(direction.x());
  rayhit.ray.dir_y = static_cast<float>(direction.y());
  rayhit.ray.dir_z = static_cast<float>(direction.z());
  rayhit.ray.tnear = tnear;
  rayhit.ray.tfar = tfar;
  rayhit.ray.time = 0.0f;
  rayhit.ray.mask = 0xFFFFFFFFu;
  rayhit.ray.id = 0;
  rayhit.ray.flags = 0;
  rayhit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rayhit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  return rayhit;
}

// Fixed-capacity hit buffer living on the caller's stack; a segment through a building crosses a
// few dozen faces at most, more than kMaxHits are ignored (never reached in our worlds: a 100 m
// segment through 4 m rooms crosses ~50 faces).
constexpr int kMaxHits = 256;

// A hit as one integer that sorts as (t, primitive): t >= tnear > 0, and the bit patterns of
// positive floats order as the floats do. Integer keys sort faster than records compared field
// by field, which matters because the occlusion traversal reports hits in no particular order.
using HitKey = std::uint64_t;
HitKey hit_key(float t, unsigned prim) {
  return (static_cast<HitKey>(std::bit_cast<std::uint32_t>(t)) << 32) | prim;
}
float hit_t(HitKey key) { return std::bit_cast<float>(static_cast<std::uint32_t>(key >> 32)); }
unsigned hit_prim(HitKey key) { return static_cast<unsigned>(key & 0xFFFFFFFFu); }

// Embree hands the filter the context pointer we passed to rtcOccluded1; extending the context
// struct is the documented way to carry per-query data into the callback.
struct CollectContext {
  RTCIntersectContext context;
  HitKey* hits;
  int count;
};

void collect_all_hits(const RTCFilterFunctionNArguments* args) {
  auto* collect = reinterpret_cast<CollectContext*>(args->context);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] == 0) continue;
    if (collect->count < kMaxHits) {
      collect->hits[collect->count++] =
          hit_key(RTCRayN_tfar(args->ray, args->N, i), RTCHitN_primID(args->hit, args->N, i));
    }
    args->valid[i] = 0;  // reject: traversal goes on to the next triangle
  }
}

void throw_on_device_error(RTCDevice device, const char* what) {
  const RTCError err = rtcGetDeviceError(device);
  if (err != RTC_ERROR_NONE)
    throw EnvironmentError(
        fmt::format("Embree: {} failed (error code {})", what, static_cast<int>(err)));
}

}  // namespace

struct EmbreeWallScene::Handles {
  RTCDevice device = nullptr;
  RTCScene filtered = nullptr;
  RTCScene plain = nullptr;
  ~Handles() {
    if (filtered) rtcReleaseScene(filtered);
    if (plain) rtcReleaseScene(plain);
    if (device) rtcReleaseDevice(device);
  }
};

EmbreeWallScene::EmbreeWallScene(const WallMesh& mesh) : handles_(std::make_unique<Handles>()) {
  std::vector<std::uint32_t> indices;
  for (const WallMesh::Face& face : mesh.faces) {
    if (face.wall_id < 0)
      throw InvalidInputError(fmt::format("wall face with wall id {}", face.wall_id));
    for (int k = 0; k < 3; ++k) {
      if (face.v[k] >= mesh.positions_m.size())
        throw InvalidInputError(
            fmt::format("mesh triangle refers to vertex {} but the mesh has {} vertices", face.v[k],
                        mesh.positions_m.size()));
      indices.push_back(face.v[k]);
    }
    wall_ids_.push_back(face.wall_id);
    materials_.push_back(face.material);
    slabs_.push_back(face.slab ? 1 : 0);
    has_slabs_ = has_slabs_ || face.slab;
    // The side the material lies on: the geometric normal, turned to agree with the mesh's
    // shading normal (which points to free space); the winding alone is not a promise.
    const Eigen::Vector3f& p0 = mesh.positions_m[face.v[0]];
    Eigen::Vector3f n = (mesh.positions_m[face.v[1]] - p0).cross(mesh.positions_m[face.v[2]] - p0);
    if (n.dot(face.free_side) < 0.0f) n = -n;
    normals_.push_back(n);
  }

  Handles& h = *handles_;
  h.device = rtcNewDevice(nullptr);
  if (!h.device) throw EnvironmentError("Embree: rtcNewDevice failed (is libembree3 usable?)");

  auto build = [&](bool with_filter) {
    RTCScene scene = rtcNewScene(h.device);
    throw_on_device_error(h.device, "rtcNewScene");
    rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_HIGH);
    // Robust traversal: watertight triangle tests, so a segment through an edge or a vertex that
    // faces share meets at least one of them (the fast mode can miss both).
    rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
    if (!wall_ids_.empty()) {
      RTCGeometry geom = rtcNewGeometry(h.device, RTC_GEOMETRY_TYPE_TRIANGLE);
      auto* vertices = static_cast<float*>(
          rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                  3 * sizeof(float), mesh.positions_m.size()));
      for (std::size_t i = 0; i < mesh.positions_m.size(); ++i) {
        vertices[3 * i + 0] = mesh.positions_m[i].x();
        vertices[3 * i + 1] = mesh.positions_m[i].y();
        vertices[3 * i + 2] = mesh.positions_m[i].z();
      }
      auto* tris = static_cast<std::uint32_t*>(
          rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                  3 * sizeof(std::uint32_t), wall_ids_.size()));
      std::copy(indices.begin(), indices.end(), tris);
      // An occlusion query with a filter that rejects every hit visits the same triangles as
      // an intersection query would and reports the same (primitive, t) pairs, in another order
      // (sorted below), but its traversal skips the closest-hit bookkeeping: ~25 % faster.
      if (with_filter) rtcSetGeometryOccludedFilterFunction(geom, collect_all_hits);
      rtcCommitGeometry(geom);
      rtcAttachGeometry(scene, geom);
      rtcReleaseGeometry(geom);
    }
    rtcCommitScene(scene);
    throw_on_device_error(h.device, "building the wall scene");
    return scene;
  };
  h.filtered = build(true);
  h.plain = build(false);
}

EmbreeWallScene::~EmbreeWallScene() = default;

void EmbreeWallScene::walls_crossed(const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                                    std::vector<WallCrossing>& out) const {
  out.clear();
  const Eigen::Vector3d dir = to - from;
  const double length = dir.norm();
  if (length <= 0.0 || wall_ids_.empty()) return;

  HitKey hits[kMaxHits];
  CollectContext collect;
  rtcInitIntersectContext(&collect.context);
  collect.hits = hits;
  collect.count = 0;

  // Unnormalised direction: t runs over [0, 1] along the segment. The ends are excluded by a
  // millimetre so a receiver standing exactly on a face does not count that wall.
  const double eps = std::min(1e-3 / length, 1e-3);
  RTCRayHit rayhit = make_ray(from, dir, static_cast<float>(eps), static_cast<float>(1.0 - eps));
  rtcOccluded1(handles_->filtered, &collect.context, &rayhit.ray);

  // The hits in order along the segment. Sorting by t orders them as by distance: t * length is
  // monotonic and keeps distinct floats distinct.
  std::sort(hits, hits + collect.count);

  // Faces in order along the segment: +1 where the segment enters material (runs against the
  // face's normal), -1 where it leaves; a hit in the face's plane (0) says nothing.
  struct Face {
    double at_m;
    int side;
    unsigned prim;
  };
  Face faces[kMaxHits];
  std::size_t n = 0;
  const Eigen::Vector3f dir_f = dir.cast<float>();
  for (int i = 0; i < collect.count; ++i) {
    const unsigned prim = hit_prim(hits[i]);
    const float along = normals_[prim].dot(dir_f);
    if (along == 0.0f) continue;
    faces[n++] = {static_cast<double>(hit_t(hits[i])) * length, along < 0.0f ? +1 : -1, prim};
  }

  // Pieces between consecutive faces (and the segment's ends). A piece after an entered face and
  // before a left one is inside; after a left face (or the start) and before an entered one (or
  // the end) it is outside; anything else (two entries in a row where solids touch, a face Embree
  // did not report where the segment passes exactly through an edge) is decided by probing the
  // piece's midpoint (inside_material). Pieces shorter than kTouchGapM are skipped: they are the
  // gap between coincident faces or a touch of an edge, and neither start nor end a crossing.
  const double start_m = eps * length, end_m = (1.0 - eps) * length;
  const Eigen::Vector3d unit = dir / length;
  std::optional<WallCrossing> current;
  auto close = [&] {
    if (current && current->length_m >= kMinCrossingM) out.push_back(*current);
    current.reset();
  };
  for (std::size_t k = 0; k <= n; ++k) {
    const Face* before = k > 0 ? &faces[k - 1] : nullptr;
    const Face* after = k < n ? &faces[k] : nullptr;
    const double from_m = before ? before->at_m : start_m;
    const double to_m = after ? after->at_m : end_m;
    if (to_m - from_m < kTouchGapM) continue;
    const bool entered = before && before->side > 0, left = after && after->side < 0;
    const bool inside =
        entered == left ? entered : inside_material(from + (0.5 * (from_m + to_m)) * unit, unit);
    if (!inside) {
      close();
      continue;
    }
    if (!current) {
      // Named after the face where the material starts (or, when the segment starts inside, the
      // face where it ends).
      const unsigned prim = before ? before->prim : after ? after->prim : 0;
      current = WallCrossing{wall_ids_[prim],  materials_[prim], materials_[prim], from_m, 0.0,
                             slabs_[prim] != 0};
    }
    if (after) current->exit_material = materials_[after->prim];
    current->length_m = to_m - current->distance_m;
  }
  close();
}

bool EmbreeWallScene::inside_material(const Eigen::Vector3d& point,
                                      const Eigen::Vector3d& along) const {
  // Four horizontal probes (along the segment, back, and both sides): each votes inside when the
  // first face it meets is one it leaves. Walls are vertical, so horizontal probes always meet
  // the faces that bound the material around the point; a majority outvotes one probe that
  // meets a face coincident with another solid's.
  Eigen::Vector3d forward(along.x(), along.y(), 0.0);
  if (forward.norm() < 1e-9) forward = Eigen::Vector3d::UnitX();
  forward.normalize();
  const Eigen::Vector3d side(-forward.y(), forward.x(), 0.0);
  int inside_votes = 0;
  for (const Eigen::Vector3d& probe :
       {forward, Eigen::Vector3d(-forward), side, Eigen::Vector3d(-side)}) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rayhit = make_ray(point, probe, 0.0f, std::numeric_limits<float>::infinity());
    rtcIntersect1(handles_->plain, &context, &rayhit);
    if (rayhit.hit.geomID == RTC_INVALID_GEOMETRY_ID) continue;
    inside_votes += normals_[rayhit.hit.primID].dot(probe.cast<float>()) > 0.0f;
  }
  return inside_votes > 2;
}

std::vector<WallCrossing> EmbreeWallScene::walls_crossed(const Eigen::Vector3d& from,
                                                         const Eigen::Vector3d& to) const {
  std::vector<WallCrossing> out;
  walls_crossed(from, to, out);
  return out;
}

double EmbreeWallScene::first_hit_m(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                                    double max_distance_m) const {
  const Eigen::Vector3d d = direction.normalized();
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rayhit = make_ray(origin, d, 0.0f, static_cast<float>(max_distance_m));
  rtcIntersect1(handles_->plain, &context, &rayhit);
  if (rayhit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return -1.0;
  return rayhit.ray.tfar;
}

}  // namespace wifislam::radio_model
