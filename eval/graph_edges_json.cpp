#include "eval/graph_edges_json.hpp"

#include <cmath>
#include <fstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/run_format.hpp"

namespace wifislam::eval {

namespace {

namespace key = run_folder::graph_key;

/// Reads one edge, naming "edges[i].key" in every error.
class EdgeReader {
 public:
  EdgeReader(const std::string& file, std::size_t index, const nlohmann::json& edge)
      : file_(file), prefix_(fmt::format("{}[{}]", key::kEdges, index)), edge_(edge) {
    if (!edge_.is_object()) fail("", "expected a JSON object");
  }

  [[noreturn]] void fail(const std::string& k, const std::string& message) const {
    throw ParseError(file_, k.empty() ? prefix_ : prefix_ + "." + k, message);
  }

  const nlohmann::json& required(const char* k) const {
    if (!edge_.contains(k)) fail(k, "missing");
    return edge_[k];
  }

  std::int64_t keyframe(const char* k) const {
    const nlohmann::json& v = required(k);
    if (!v.is_number_integer() || v.get<std::int64_t>() < 0) {
      fail(k, "expected a keyframe id (integer >= 0), got " + v.dump());
    }
    return v.get<std::int64_t>();
  }

  double number(const nlohmann::json& v, const std::string& k) const {
    if (!v.is_number() || !std::isfinite(v.get<double>())) {
      fail(k, "expected a finite number, got " + v.dump());
    }
    return v.get<double>();
  }

  /// A fixed-length array of finite numbers under from_to.
  std::vector<double> numbers(const nlohmann::json& parent, const char* k, std::size_t n) const {
    const std::string path = std::string(key::kFromTo) + "." + k;
    if (!parent.contains(k)) fail(path, "missing");
    const nlohmann::json& v = parent[k];
    if (!v.is_array() || v.size() != n) {
      fail(path, fmt::format("expected an array of {} numbers, got {}", n, v.dump()));
    }
    std::vector<double> out;
    for (std::size_t i = 0; i < n; ++i) out.push_back(number(v[i], fmt::format("{}[{}]", path, i)));
    return out;
  }

  GraphEdgeRecord read(std::size_t index) const {
    GraphEdgeRecord e;
    e.index = index;
    e.from_keyframe = keyframe(key::kFrom);
    e.to_keyframe = keyframe(key::kTo);
    const nlohmann::json& type = required(key::kType);
    if (!type.is_string()) fail(key::kType, "expected a string, got " + type.dump());
    e.type = type.get<std::string>();
    if (edge_.contains(key::kInliers)) {
      const nlohmann::json& v = edge_[key::kInliers];
      if (!v.is_number_integer()) fail(key::kInliers, "expected an integer, got " + v.dump());
      e.inliers = v.get<std::int64_t>();
    }
    const nlohmann::json& from_to = required(key::kFromTo);
    if (!from_to.is_object()) fail(key::kFromTo, "expected a JSON object");
    const std::vector<double> t = numbers(from_to, key::kTranslation, 3);
    const std::vector<double> q = numbers(from_to, key::kRotationXyzw, 4);
    const Eigen::Quaterniond rotation(q[3], q[0], q[1], q[2]);
    if (rotation.norm() < 1e-9) {
      fail(std::string(key::kFromTo) + "." + key::kRotationXyzw, "zero quaternion");
    }
    e.from_to = pose_from_translation_quaternion(Eigen::Vector3d(t[0], t[1], t[2]), rotation);
    if (edge_.contains(key::kPruned)) {
      const nlohmann::json& v = edge_[key::kPruned];
      if (!v.is_boolean()) fail(key::kPruned, "expected true or false, got " + v.dump());
      e.pruned = v.get<bool>();
    }
    if (edge_.contains(key::kWeight)) {
      e.weight = number(edge_[key::kWeight], key::kWeight);
      if (e.weight < 0) fail(key::kWeight, "must be >= 0");
    }
    return e;
  }

 private:
  const std::string& file_;
  std::string prefix_;
  const nlohmann::json& edge_;
};

}  // namespace

std::vector<GraphEdgeRecord> read_graph_edges_json(const std::filesystem::path& path) {
  const std::string file = path.string();
  std::ifstream in(path);
  if (!in) throw IoError(file + ": cannot read");
  nlohmann::json j;
  try {
    in >> j;
  } catch (const nlohmann::json::exception& e) {
    throw ParseError(file, "", std::string("not valid JSON: ") + e.what());
  }
  if (!j.is_object()) throw ParseError(file, "", "expected a JSON object");
  if (!j.contains(key::kEdges)) throw ParseError(file, key::kEdges, "missing");
  const nlohmann::json& edges = j[key::kEdges];
  if (!edges.is_array()) throw ParseError(file, key::kEdges, "expected an array");
  std::vector<GraphEdgeRecord> out;
  out.reserve(edges.size());
  for (std::size_t i = 0; i < edges.size(); ++i)
    out.push_back(EdgeReader(file, i, edges[i]).read(i));
  return out;
}

}  // namespace wifislam::eval
