// Readers of the run folder's files and the options: good files parse, bad ones name the file,
// the line and the column/key.
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "eval/eval_options.hpp"
#include "eval/loop_closure_csv.hpp"
#include "eval/run_divergence.hpp"
#include "eval/timing_table.hpp"
#include "eval/wifi_clusters_csv.hpp"
#include "tests/support/scratch_folder.hpp"

namespace wifislam::eval {
namespace {

namespace fs = std::filesystem;

fs::path write_temp(const std::string& name, const std::string& text) {
  const fs::path dir = test::scratch_folder(name);
  std::ofstream(dir / name) << text;
  return dir / name;
}

template <typename F>
std::string error_of(F f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

const char* kHeader =
    "from_keyframe,to_keyframe,from_frame,to_frame,from_time,to_time,role,inliers,"
    "rms_reprojection_px,tx,ty,tz,qx,qy,qz,qw\n";

TEST(LoopClosureCsv, ReadsRows) {
  const fs::path p = write_temp(
      "lc.csv", std::string(kHeader) +
                    "3,40,30,400,1.000000,13.333333,sampled,57,0.8,0.1,-0.2,0.3,0,0,0.7071068,"
                    "0.7071068\n");
  const auto rows = read_loop_closures_csv(p);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].from_keyframe, 3);
  EXPECT_EQ(rows[0].to_keyframe, 40);
  EXPECT_EQ(rows[0].role, "sampled");
  EXPECT_EQ(rows[0].inliers, 57);
  EXPECT_EQ(rows[0].to_time, Timestamp::from_ns(13'333'333'000LL));
  EXPECT_NEAR(rows[0].from_to.translation().y(), -0.2, 1e-12);
  EXPECT_NEAR(Eigen::AngleAxisd(rows[0].from_to.linear()).angle(), M_PI / 2, 1e-6);
  EXPECT_EQ(rows[0].line, 2);
}

TEST(LoopClosureCsv, BadRowsNameFileLineAndColumn) {
  const fs::path p = write_temp(
      "lc_bad.csv", std::string(kHeader) + "3,40,30,400,1.0,13.3,sampled,57,0.8,nan,0,0,0,0,0,1\n");
  const std::string e = error_of([&] { read_loop_closures_csv(p); });
  EXPECT_NE(e.find("lc_bad.csv:2"), std::string::npos) << e;
  EXPECT_NE(e.find("tx"), std::string::npos) << e;
  const fs::path short_row = write_temp("lc_short.csv", std::string(kHeader) + "3,40\n");
  EXPECT_NE(error_of([&] { read_loop_closures_csv(short_row); }).find("lc_short.csv:2"),
            std::string::npos);
  const fs::path header = write_temp("lc_header.csv", "a,b\n");
  EXPECT_NE(error_of([&] { read_loop_closures_csv(header); }).find("lc_header.csv:1"),
            std::string::npos);
}

TEST(WifiClustersCsv, ReadsClustersAndSignatures) {
  const fs::path p = write_temp("clusters.csv",
                                "cluster_id,founder_keyframe,keyframes,representative_signature\n"
                                "0,0,0 1 2 5,02:1a:11:00:00:30=-61.5;02:1a:11:00:00:40=-70\n"
                                "1,3,3 4,\n");
  const auto c = read_wifi_clusters_csv(p);
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c[0].keyframes, (std::vector<std::int64_t>{0, 1, 2, 5}));
  ASSERT_EQ(c[0].representative_signature.size(), 2u);
  EXPECT_EQ(c[0].representative_signature[0].first, "02:1a:11:00:00:30");
  EXPECT_DOUBLE_EQ(c[0].representative_signature[0].second, -61.5);
  EXPECT_EQ(c[1].founder_keyframe, 3);
  EXPECT_TRUE(c[1].representative_signature.empty());
  const fs::path bad = write_temp("clusters_bad.csv",
                                  "cluster_id,founder_keyframe,keyframes,representative_signature\n"
                                  "0,0,0 x,02:1a:11:00:00:30=-61.5\n");
  const std::string e = error_of([&] { read_wifi_clusters_csv(bad); });
  EXPECT_NE(e.find("clusters_bad.csv:2"), std::string::npos) << e;
  EXPECT_NE(e.find("keyframes"), std::string::npos) << e;
}

TEST(TimingTable, WifiOverheadIsClusteringPlusManagement) {
  const fs::path p = write_temp("timing.json", R"({
    "modules": {"loop_closure_detection": {"total_s": 2.5, "calls": 10},
                "wifi_clustering": {"total_s": 0.01, "calls": 10},
                "wifi_cluster_management": {"total_s": 0.005, "calls": 10},
                "optimisation": {"total_s": 0.75, "calls": 3},
                "total": {"total_s": 9.0, "calls": 100}},
    "counters": {"candidate_comparisons": 42, "keyframes": 10},
    "keyframe_searches": [], "wall_s": 11.5})");
  const TimingTable t = read_timing_json(p);
  EXPECT_DOUBLE_EQ(t.loop_closure_detection_s, 2.5);
  EXPECT_DOUBLE_EQ(t.wifi_overhead_s, 0.015);
  EXPECT_DOUBLE_EQ(t.optimisation_s, 0.75);
  EXPECT_DOUBLE_EQ(t.total_s, 9.0);
  EXPECT_DOUBLE_EQ(t.wall_s, 11.5);
  EXPECT_EQ(t.counter("candidate_comparisons"), 42);
  EXPECT_EQ(t.counter("absent"), 0);

  const fs::path vanilla =
      write_temp("timing_vanilla.json", R"({"modules": {"total": {"total_s": 1, "calls": 1}}})");
  EXPECT_DOUBLE_EQ(read_timing_json(vanilla).wifi_overhead_s, 0.0);
  const fs::path broken = write_temp("timing_broken.json", "{\"modules\": {\n  \"x\": [}");
  const std::string e = error_of([&] { read_timing_json(broken); });
  EXPECT_NE(e.find("timing_broken.json"), std::string::npos) << e;
  EXPECT_NE(e.find("line 2"), std::string::npos) << e;
  const fs::path negative =
      write_temp("timing_neg.json", R"({"modules": {"total": {"total_s": -1}}})");
  EXPECT_NE(error_of([&] { read_timing_json(negative); }).find("modules.total.total_s"),
            std::string::npos);
}

TEST(TimingTable, ReadsPerRoleWorkAndLocatesAMissingField) {
  const fs::path p = write_temp("timing_roles.json", R"({
 "roles": {"long_term": {"comparisons": 40, "ransac_runs": 31, "verified": 3, "accepted": 2,
                         "time_s": 0.5},
           "tracking": {"comparisons": 100, "ransac_runs": 100, "verified": 97,
                        "accepted": 97, "time_s": 1.5}}})");
  const TimingTable t = read_timing_json(p);
  ASSERT_EQ(t.roles.size(), 2u);
  EXPECT_EQ(t.roles.at("long_term").comparisons, 40);
  EXPECT_EQ(t.roles.at("long_term").ransac_runs, 31);
  EXPECT_EQ(t.roles.at("long_term").verified, 3);
  EXPECT_EQ(t.roles.at("long_term").accepted, 2);
  EXPECT_DOUBLE_EQ(t.roles.at("tracking").time_s, 1.5);
  const fs::path missing =
      write_temp("timing_roles_missing.json",
                 R"({"roles": {"neighbour": {"comparisons": 1, "ransac_runs": 1, "verified": 1,
                                  "time_s": 0.1}}})");
  EXPECT_NE(error_of([&] { read_timing_json(missing); }).find("roles.neighbour.accepted"),
            std::string::npos);
}

/// A run folder with three keyframes (1, 2, 3 s) and the given edges ("from to type").
fs::path write_run(const std::string& name, const std::vector<std::string>& edges) {
  std::string graph = R"({"edges": [)";
  for (std::size_t i = 0; i < edges.size(); ++i) {
    std::istringstream in(edges[i]);
    int from = 0, to = 0;
    std::string type;
    in >> from >> to >> type;
    graph +=
        (i ? "," : "") + fmt::format(R"({{"from": {}, "to": {}, "type": "{}", "inliers": 30,)"
                                     R"( "from_to": {{"t": [0, 0, 1], "q_xyzw": [0, 0, 0, 1]}}}})",
                                     from, to, type);
  }
  graph += "]}";
  const fs::path dir = write_temp(name + "_keyframes.txt", "").parent_path() / name;
  fs::create_directories(dir);
  // Unix stamps, as generated datasets carry.
  std::ofstream(dir / "keyframes.txt") << "1700000001.0 0 0 0 0 0 0 1\n1700000002.0 0 0 1 0 0 0 1\n"
                                          "1700000003.250001 0 0 2 0 0 0 1\n";
  std::ofstream(dir / "graph.json") << graph;
  return dir;
}

TEST(RunDivergence, FindsTheFirstKeyframeWhoseEdgesDiffer) {
  const fs::path a = write_run("div_a", {"0 1 visual", "1 2 visual", "0 2 loop"});
  const fs::path same = write_run("div_same", {"0 2 loop", "0 1 visual", "1 2 visual"});
  const fs::path other = write_run("div_other", {"0 1 visual", "1 2 visual"});
  EXPECT_FALSE(first_divergence(a, same).has_value());  // edge order does not matter
  const auto d = first_divergence(a, other);
  ASSERT_TRUE(d.has_value());
  EXPECT_EQ(d->keyframe, 2);
  // Since the run's first keyframe, to the microsecond (a difference of two double seconds at
  // 1.7e9 s would be off by up to 2.4e-7 s).
  EXPECT_DOUBLE_EQ(d->time_s, 2.250001);
}

TEST(EvalOptions, SetAndValidate) {
  EvalOptions o;
  set_option(o, "revisit_min_path_m=12.5");
  set_option(o, "align=sim3");
  set_option(o, "time_offset_s=-0.25");
  set_option(o, "episode_max_gap_keyframes=4");
  EXPECT_DOUBLE_EQ(o.revisit_min_path_m, 12.5);
  EXPECT_EQ(o.align, AlignmentMode::kSim3);
  EXPECT_EQ(o.to_json()["align"], "sim3");
  EXPECT_DOUBLE_EQ(o.time_offset_s, -0.25);
  EXPECT_NE(error_of([&] { set_option(o, "align=affine"); }).find("none, se3, sim3"),
            std::string::npos);
  EXPECT_EQ(o.align, AlignmentMode::kSim3);  // unchanged by the rejected value
  EXPECT_EQ(o.episode_max_gap_keyframes, 4);
  EXPECT_EQ(o.to_json()["revisit_min_path_m"], 12.5);
  EXPECT_NE(error_of([&] {
              set_option(o, "revisit_min_pth_m=3");
            }).find("did you mean 'revisit_min_path_m'?"),
            std::string::npos);
  EXPECT_NE(error_of([&] { set_option(o, "overlap_min_fraction=2"); }).find("overlap_min_fraction"),
            std::string::npos);
  // Stamps are 64-bit nanoseconds: beyond these a difference or an offset overflowed them.
  EXPECT_NE(error_of([&] { set_option(o, "max_time_difference_s=1e10"); }).find("(0, 1e6]"),
            std::string::npos);
  EXPECT_NE(error_of([&] { set_option(o, "time_offset_s=5e9"); }).find("[-1e9, 1e9]"),
            std::string::npos);
  EXPECT_NE(error_of([&] { set_option(o, "rpe_delta_m=abc"); }).find("expected a finite number"),
            std::string::npos);
  EXPECT_NE(error_of([&] { set_option(o, "episode_max_gap_keyframes=1.5"); }).find("integer"),
            std::string::npos);
  // Every threshold appears in the JSON (and so in every output).
  EXPECT_EQ(o.to_json().size(), option_descriptions().size());
}

}  // namespace
}  // namespace wifislam::eval
