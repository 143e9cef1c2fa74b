#include "radio_model/embree_wall_scene.hpp"

#include <embree3/rtcore.h>

#include <algorithm>
#include <limits>

#include <fmt/format.h>

#include "core/error.hpp"

namespace wifislam {

namespace {

// Fixed-capacity hit buffer living on the caller's stack; a segment through a building crosses a
// few dozen faces at most, more than kMaxHits are ignored (never reached in our worlds: a 100 m
// segment through 4 m rooms crosses ~50 faces).
constexpr int kMaxHits = 256;

struct HitRecord {
  unsigned prim = 0;
  float t = 0.0f;
};

// Embree hands the filter the context pointer we passed to rtcIntersect1; extending the context
// struct is the documented way to carry per-query data into the callback.
struct CollectContext {
  RTCIntersectContext context;
  HitRecord* hits;
  int count;
};

void collect_all_hits(const RTCFilterFunctionNArguments* args) {
  auto* collect = reinterpret_cast<CollectContext*>(args->context);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] == 0) continue;
    if (collect->count < kMaxHits) {
      collect->hits[collect->count++] = {RTCHitN_primID(args->hit, args->N, i),
                                         RTCRayN_tfar(args->ray, args->N, i)};
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

EmbreeWallScene::EmbreeWallScene(const Mesh& mesh) : handles_(std::make_unique<Handles>()) {
  std::vector<std::uint32_t> indices;
  for (const Triangle& tri : mesh.triangles) {
    if (tri.wall_id < 0) continue;
    for (int k = 0; k < 3; ++k) {
      if (tri.v[k] >= mesh.positions_m.size())
        throw InvalidInputError(
            fmt::format("mesh triangle refers to vertex {} but the mesh has {} vertices", tri.v[k],
                        mesh.positions_m.size()));
      indices.push_back(tri.v[k]);
    }
    wall_ids_.push_back(tri.wall_id);
    materials_.push_back(tri.material);
  }

  Handles& h = *handles_;
  h.device = rtcNewDevice(nullptr);
  if (!h.device) throw EnvironmentError("Embree: rtcNewDevice failed (is libembree3 usable?)");

  auto build = [&](bool with_filter) {
    RTCScene scene = rtcNewScene(h.device);
    throw_on_device_error(h.device, "rtcNewScene");
    rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_HIGH);
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
      if (with_filter) rtcSetGeometryIntersectFilterFunction(geom, collect_all_hits);
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

  HitRecord hits[kMaxHits];
  CollectContext collect;
  rtcInitIntersectContext(&collect.context);
  collect.hits = hits;
  collect.count = 0;

  RTCRayHit rayhit;
  rayhit.ray.org_x = static_cast<float>(from.x());
  rayhit.ray.org_y = static_cast<float>(from.y());
  rayhit.ray.org_z = static_cast<float>(from.z());
  // Unnormalised direction: t runs over [0, 1] along the segment. The ends are excluded by a
  // millimetre so a receiver standing exactly on a face does not count that wall.
  rayhit.ray.dir_x = static_cast<float>(dir.x());
  rayhit.ray.dir_y = static_cast<float>(dir.y());
  rayhit.ray.dir_z = static_cast<float>(dir.z());
  const double eps = std::min(1e-3 / length, 1e-3);
  rayhit.ray.tnear = static_cast<float>(eps);
  rayhit.ray.tfar = static_cast<float>(1.0 - eps);
  rayhit.ray.time = 0.0f;
  rayhit.ray.mask = 0xFFFFFFFFu;
  rayhit.ray.id = 0;
  rayhit.ray.flags = 0;
  rayhit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rayhit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(handles_->filtered, &collect.context, &rayhit);

  // Merge hits per wall_id, keeping the nearest (traversal order is not distance order).
  for (int i = 0; i < collect.count; ++i) {
    const int wall = wall_ids_[hits[i].prim];
    const double d = static_cast<double>(hits[i].t) * length;
    auto it = std::find_if(out.begin(), out.end(),
                           [wall](const WallCrossing& c) { return c.wall_id == wall; });
    if (it == out.end()) {
      out.push_back({wall, materials_[hits[i].prim], d});
    } else if (d < it->distance_m) {
      it->distance_m = d;
      it->material = materials_[hits[i].prim];
    }
  }
  std::sort(out.begin(), out.end(), [](const WallCrossing& a, const WallCrossing& b) {
    return a.distance_m != b.distance_m ? a.distance_m < b.distance_m : a.wall_id < b.wall_id;
  });
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
  RTCRayHit rayhit;
  rayhit.ray.org_x = static_cast<float>(origin.x());
  rayhit.ray.org_y = static_cast<float>(origin.y());
  rayhit.ray.org_z = static_cast<float>(origin.z());
  rayhit.ray.dir_x = static_cast<float>(d.x());
  rayhit.ray.dir_y = static_cast<float>(d.y());
  rayhit.ray.dir_z = static_cast<float>(d.z());
  rayhit.ray.tnear = 0.0f;
  rayhit.ray.tfar = static_cast<float>(max_distance_m);
  rayhit.ray.time = 0.0f;
  rayhit.ray.mask = 0xFFFFFFFFu;
  rayhit.ray.id = 0;
  rayhit.ray.flags = 0;
  rayhit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rayhit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(handles_->plain, &context, &rayhit);
  if (rayhit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return -1.0;
  return rayhit.ray.tfar;
}

}  // namespace wifislam
