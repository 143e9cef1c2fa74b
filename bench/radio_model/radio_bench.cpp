// Radio model benchmarks on j_hall (docs/benchmarks.md):
//  - wall-crossing segment queries (AP -> receiver, 30 m, every wall counted) per second, next
//    to bare Embree rtcIntersect1 rays on the same walls and segments in the same run (ratio);
//    on random segments and on the radio map's rows (an AP to every cell);
//  - a full 0.25 m radio map of j_hall over all access points (strongest AP per cell), on 1 and
//    2 threads, with every AP ray-cast at every cell and with exact pruning.
#include <benchmark/benchmark.h>

#include <time.h>

#include <cmath>
#include <cstdlib>
#include <memory>

#include "core/rng.hpp"
#include "radio_model/propagation_model.hpp"
#include "sim/scene/scene_loader.hpp"
#include "sim/site/radio_map_over_plan.hpp"
#include "sim/site/site.hpp"
#include "sim/world/plan_queries.hpp"
#include "sim/world/world_types.hpp"

namespace {

using namespace wifislam;

// CPU time of the calling thread: the queries run on it alone, and on a shared machine wall time
// also counts the time other processes held the core.
double thread_cpu_s() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

struct JHall {
  std::unique_ptr<sim::site::Site> site;
  std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> segments;  // 30 m each
};

const JHall& j_hall() {
  static const JHall* hall = [] {
    auto* h = new JHall;
    // WIFISLAM_BENCH_SCENE picks another scene file (e.g. to compare halls).
    const char* other = std::getenv("WIFISLAM_BENCH_SCENE");
    h->site = std::make_unique<sim::site::Site>(sim::scene::load_scene_file(
        other ? std::string(other) : std::string(WIFISLAM_SCENES_DIR) + "/j_hall.yaml"));
    Rng rng = Rng::stream(1, "bench/segments");
    const auto& lo = h->site->world().plan.bounds_min_m;
    const auto& hi = h->site->world().plan.bounds_max_m;
    while (h->segments.size() < 4096) {
      const Eigen::Vector2d a(rng.uniform(lo.x(), hi.x()), rng.uniform(lo.y(), hi.y()));
      const double heading = rng.uniform(0.0, 2.0 * M_PI);
      const Eigen::Vector2d b = a + 30.0 * Eigen::Vector2d(std::cos(heading), std::sin(heading));
      if (b.x() < lo.x() || b.y() < lo.y() || b.x() > hi.x() || b.y() > hi.y()) continue;
      h->segments.emplace_back(Eigen::Vector3d(a.x(), a.y(), 2.5),
                               Eigen::Vector3d(b.x(), b.y(), 1.0));
    }
    return h;
  }();
  return *hall;
}

// Both measured in one loop so machine noise hits both alike; the ratio is the figure to keep.
// Rates are per second of the thread's CPU time (thread_cpu_s).
void BM_WallCrossingVsBareEmbree(benchmark::State& state) {
  const JHall& h = j_hall();
  const radio_model::EmbreeWallScene& walls = h.site->radio().wall_scene();
  std::vector<radio_model::WallCrossing> out;
  double crossing_s = 0, bare_s = 0;
  std::size_t queries = 0, walls_total = 0;
  for (auto _ : state) {
    const double t0 = thread_cpu_s();
    for (const auto& [a, b] : h.segments) {
      walls.walls_crossed(a, b, out);
      walls_total += out.size();
    }
    const double t1 = thread_cpu_s();
    double sink = 0;
    for (const auto& [a, b] : h.segments) sink += walls.first_hit_m(a, b - a, 30.0);
    const double t2 = thread_cpu_s();
    benchmark::DoNotOptimize(sink);
    crossing_s += t1 - t0;
    bare_s += t2 - t1;
    queries += h.segments.size();
  }
  state.counters["segments_per_s"] = queries / crossing_s;
  state.counters["bare_rays_per_s"] = queries / bare_s;
  state.counters["ratio_to_bare"] = (queries / crossing_s) / (queries / bare_s);
  state.counters["walls_per_segment"] = static_cast<double>(walls_total) / queries;
  state.counters["wall_triangles"] = static_cast<double>(walls.triangle_count());
}
BENCHMARK(BM_WallCrossingVsBareEmbree)->Unit(benchmark::kMillisecond);

// The radio map's pattern, next to the random segments above: every AP to every free-space
// 0.25 m cell of its row within 30 m, receivers at 1 m; wall-crossing queries and bare rays on the
// same segments in one loop. Segments from one AP to neighbouring cells are shorter on average
// and cross fewer walls than the random 30 m ones.
void BM_WallCrossingRowsVsBareEmbree(benchmark::State& state) {
  const JHall& h = j_hall();
  const radio_model::EmbreeWallScene& walls = h.site->radio().wall_scene();
  const auto& plan = h.site->world().plan;
  std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> segments;
  for (const auto& ap : h.site->radio().access_points())
    for (double y = plan.bounds_min_m.y() + 0.125; y < plan.bounds_max_m.y(); y += 0.25)
      for (double x = plan.bounds_min_m.x() + 0.125; x < plan.bounds_max_m.x(); x += 0.25) {
        const Eigen::Vector3d cell(x, y, 1.0);
        if ((cell - ap.position_m).norm() <= 30.0 &&
            sim::world::regions_contain(plan.free_space, cell.head<2>()))
          segments.emplace_back(ap.position_m, cell);
      }
  std::vector<radio_model::WallCrossing> out;
  double crossing_s = 0, bare_s = 0;
  std::size_t walls_total = 0;
  for (auto _ : state) {
    const double t0 = thread_cpu_s();
    for (const auto& [a, b] : segments) {
      walls.walls_crossed(a, b, out);
      walls_total += out.size();
    }
    const double t1 = thread_cpu_s();
    double sink = 0;
    for (const auto& [a, b] : segments) sink += walls.first_hit_m(a, b - a, 30.0);
    const double t2 = thread_cpu_s();
    benchmark::DoNotOptimize(sink);
    crossing_s += t1 - t0;
    bare_s += t2 - t1;
  }
  const double queries = static_cast<double>(segments.size()) * state.iterations();
  state.counters["segments"] = static_cast<double>(segments.size());
  state.counters["segments_per_s"] = queries / crossing_s;
  state.counters["bare_rays_per_s"] = queries / bare_s;
  state.counters["ratio_to_bare"] = bare_s / crossing_s;
  state.counters["walls_per_segment"] = static_cast<double>(walls_total) / queries;
}
BENCHMARK(BM_WallCrossingRowsVsBareEmbree)->Unit(benchmark::kMillisecond);

void BM_RadioMapJHallAllAps(benchmark::State& state) {
  const JHall& h = j_hall();
  radio_model::RadioMapOptions options;
  options.resolution_m = 0.25;
  options.threads = static_cast<int>(state.range(0));
  options.prune = state.range(1) != 0;
  std::size_t cells = 0;
  for (auto _ : state) {
    const radio_model::RadioMap map =
        sim::site::compute_radio_map(h.site->radio(), h.site->world().plan, options);
    cells = 0;
    for (float v : map.rssi_dbm) cells += std::isfinite(v);
    benchmark::DoNotOptimize(map.rssi_dbm.data());
  }
  state.counters["free_cells"] = static_cast<double>(cells);
  state.counters["aps"] = static_cast<double>(h.site->radio().access_points().size());
  // Cell x AP pairs covered per second (with pruning most of them need no ray).
  state.counters["cell_aps_per_s"] =
      benchmark::Counter(static_cast<double>(cells * h.site->radio().access_points().size()),
                         benchmark::Counter::kIsIterationInvariantRate);
}
// Args: threads, prune (0: every AP's wall ray at every cell; 1: exact pruning of hopeless APs).
BENCHMARK(BM_RadioMapJHallAllAps)
    ->ArgNames({"threads", "prune"})
    ->Args({1, 0})
    ->Args({2, 0})
    ->Args({1, 1})
    ->Args({2, 1})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
