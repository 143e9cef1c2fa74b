#include "sim/scene/scene_keys.hpp"

#include <algorithm>
#include <charconv>
#include <limits>
#include <regex>

#include <fmt/format.h>

#include "core/error.hpp"
#include "sim/scene/scene_schema.hpp"

namespace wifislam::sim::scene {

namespace {

using schema::Limits;

/// Walks the schema with default values and records every key's path.
class KeyCollector {
 public:
  explicit KeyCollector(std::vector<std::string>& out, std::string prefix = "")
      : out_(out), prefix_(std::move(prefix)) {}
  void required() {}
  void number(const char* key, double&, Limits) { add(key); }
  void integer(const char* key, int&, Limits) { add(key); }
  template <class T>
  void uint64(const char* key, T&, std::uint64_t = 0) {
    add(key);
  }
  void optional_uint64(const char* key, std::optional<std::uint64_t>&) { add(key); }
  void optional_number(const char* key, std::optional<double>&, Limits) { add(key); }
  void boolean(const char* key, bool&) { add(key); }
  void text(const char* key, std::string&) { add(key); }
  template <class E>
  void choice(const char* key, E&, const schema::Names<E>&) {
    add(key);
  }
  void vec2(const char* key, Eigen::Vector2d&, Limits) { add(key); }
  void vec3(const char* key, Eigen::Vector3d&, Limits, Limits) { add(key); }
  void optional_vec3(const char* key, std::optional<Eigen::Vector3d>&, Limits, Limits) { add(key); }
  void polygon(const char* key, std::vector<Eigen::Vector2d>&, Limits) { add(key); }
  void points_if_any(const char* key, std::vector<Eigen::Vector2d>&, Limits) { add(key); }
  void text_list(const char* key, std::vector<std::string>&) { add(key); }
  void interval(const char* key, double&, double&, Limits) { add(key); }
  template <class T>
  void object(const char* key, T& value) {
    KeyCollector inner(out_, path(key) + ".");
    schema::visit(inner, value);
  }
  /// The device itself (a shipped name) and each key of an inline one.
  void device(const char* key, std::optional<radio_model::ReceiverDevice>&) {
    add(key);
    radio_model::ReceiverDevice inline_device;
    object(key, inline_device);
  }
  template <class T>
  void list(const char* key, std::vector<T>&) {
    add(key);
    T element{};
    KeyCollector inner(out_, path(key) + "[*].");
    schema::visit(inner, element);
  }
  template <class T>
  void list_if_any(const char* key, std::vector<T>& items) {
    list(key, items);
  }

 private:
  std::string path(const char* key) const { return prefix_ + key; }
  void add(const char* key) { out_.push_back(path(key)); }
  std::vector<std::string>& out_;
  std::string prefix_;
};

// One step of a path: a key, optionally followed by an index ("[3]" or "[*]").
struct Step {
  std::string key;
  bool indexed = false;
  bool every = false;
  std::size_t index = 0;
};

std::vector<Step> steps_of(const std::string& path) {
  std::vector<Step> steps;
  std::size_t start = 0;
  while (start <= path.size()) {
    const std::size_t dot = path.find('.', start);
    std::string part =
        path.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    Step step;
    if (const std::size_t open = part.find('['); open != std::string::npos && part.back() == ']') {
      const std::string inside = part.substr(open + 1, part.size() - open - 2);
      step.indexed = true;
      step.every = inside == "*";
      // An index too large for size_t is past the end of any list: set_at says how long the
      // list is (std::stoull threw std::out_of_range, which no caller expects).
      if (!step.every) {
        const auto [end, error] =
            std::from_chars(inside.data(), inside.data() + inside.size(), step.index);
        if (error != std::errc() || end != inside.data() + inside.size()) {
          step.index = std::numeric_limits<std::size_t>::max();
        }
      }
      part = part.substr(0, open);
    }
    step.key = part;
    steps.push_back(step);
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  return steps;
}

void set_at(YAML::Node node, const std::vector<Step>& steps, std::size_t k, const YAML::Node& value,
            const std::string& path) {
  const Step& step = steps[k];
  const bool last = k + 1 == steps.size();
  if (!step.indexed) {
    if (last) {
      node[step.key] = value;
      return;
    }
    YAML::Node child = node[step.key];
    if (!child.IsDefined() || child.IsNull()) {
      node[step.key] = YAML::Node(YAML::NodeType::Map);
      child = node[step.key];
    }
    set_at(child, steps, k + 1, value, path);
    return;
  }
  YAML::Node list = node[step.key];
  if (!list.IsSequence()) {
    throw InvalidInputError(fmt::format("{}: the scene has no list '{}' to set", path, step.key));
  }
  if (!step.every && step.index >= list.size()) {
    throw InvalidInputError(
        fmt::format("{}: the scene's '{}' has {} elements", path, step.key, list.size()));
  }
  for (std::size_t i = 0; i < list.size(); ++i) {
    if (!step.every && i != step.index) continue;
    YAML::Node element = list[i];
    if (last) {
      list[i] = value;
    } else {
      set_at(element, steps, k + 1, value, path);
    }
  }
}

}  // namespace

const std::vector<std::string>& scene_key_paths() {
  static const std::vector<std::string> paths = [] {
    std::vector<std::string> out;
    Scene scene;
    KeyCollector collector(out);
    schema::visit(collector, scene);
    return out;
  }();
  return paths;
}

std::string generic_key_path(const std::string& path) {
  static const std::regex index(R"(\[[0-9]+\])");
  return std::regex_replace(path, index, "[*]");
}

bool is_scene_key_path(const std::string& path) {
  const std::string generic = generic_key_path(path);
  const auto& paths = scene_key_paths();
  return std::find(paths.begin(), paths.end(), generic) != paths.end();
}

void set_scene_key(YAML::Node root, const std::string& path, const YAML::Node& value) {
  set_at(root, steps_of(path), 0, value, path);
}

}  // namespace wifislam::sim::scene
