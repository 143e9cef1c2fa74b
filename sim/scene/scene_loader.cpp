#include "sim/scene/scene_loader.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <tuple>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/camera_intrinsics.hpp"
#include "core/did_you_mean.hpp"
#include "core/error.hpp"
#include "core/text_lines.hpp"
#include "core/yaml_document.hpp"
#include "sim/scene/scene_levels.hpp"
#include "sim/scene/scene_schema.hpp"

namespace wifislam::sim::scene {

namespace {

using schema::Limits;

/// Where each key path was found in the file ("file:line:column"), for errors raised after
/// reading (cross-references, connectivity) as well as during it.
struct SourceMap {
  std::string file;
  std::map<std::string, YAML::Mark> marks;

  std::string where(const YAML::Mark& mark) const {
    if (mark.line < 0) return file;
    return fmt::format("{}:{}:{}", file, mark.line + 1, mark.column + 1);
  }
  /// Position of `key_path`, or of its closest recorded parent.
  std::string where(std::string key_path) const {
    while (true) {
      auto it = marks.find(key_path);
      if (it != marks.end()) return where(it->second);
      const auto cut = key_path.find_last_of(".[");
      if (cut == std::string::npos) return file;
      key_path.resize(cut);
    }
  }
};

std::string describe(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Null:
      return "nothing";
    case YAML::NodeType::Scalar:
      return "'" + node.Scalar() + "'";
    case YAML::NodeType::Sequence:
      return "a list";
    case YAML::NodeType::Map:
      return "a mapping";
    default:
      return "an undefined value";
  }
}

std::string describe_limits(const Limits& l) {
  const bool has_lo = std::isfinite(l.lo), has_hi = std::isfinite(l.hi);
  if (has_lo && has_hi) return fmt::format("a number in [{}, {}]", l.lo, l.hi);
  if (has_lo) return fmt::format("a number {} {}", l.open_low ? ">" : ">=", l.lo);
  if (has_hi) return fmt::format("a number <= {}", l.hi);
  return "a number";
}

/// Reads one YAML mapping into a struct through schema::visit, checking types and ranges and,
/// at the end, that no key was left unread (typos must not pass silently).
class YamlReader {
 public:
  YamlReader(const YAML::Node& node, std::string path, SourceMap& sources)
      : node_(node), path_(std::move(path)), sources_(sources) {
    if (!node_.IsMap()) {
      throw ParseError(sources_.where(node_.Mark()), path_.empty() ? "(top level)" : path_,
                       "expected a mapping of keys, got " + describe(node_));
    }
    if (!path_.empty()) sources_.marks[path_] = node_.Mark();
  }

  void required() { next_required_ = true; }

  void number(const char* key, double& out, Limits limits) {
    if (auto n = fetch(key)) out = to_number(*n, key, limits);
  }
  void integer(const char* key, int& out, Limits limits) {
    if (auto n = fetch(key)) {
      const double value = to_number(*n, key, limits);
      if (value != std::floor(value)) fail(*n, key, "expected a whole number, got " + describe(*n));
      out = static_cast<int>(value);
    }
  }
  void uint64(const char* key, std::uint64_t& out,
              std::uint64_t max = std::numeric_limits<std::uint64_t>::max()) {
    if (auto n = fetch(key)) {
      out = to_uint64(*n, key);
      if (out > max) {
        fail(*n, key, fmt::format("expected a whole number from 0 to {}, got {}", max, out));
      }
    }
  }
  void optional_uint64(const char* key, std::optional<std::uint64_t>& out) {
    if (auto n = fetch(key)) out = to_uint64(*n, key);
  }
  void optional_number(const char* key, std::optional<double>& out, Limits limits) {
    if (auto n = fetch(key)) out = to_number(*n, key, limits);
  }
  void boolean(const char* key, bool& out) {
    if (auto n = fetch(key)) {
      bool value = false;
      if (!n->IsScalar() || !YAML::convert<bool>::decode(*n, value)) {
        fail(*n, key, "expected true or false, got " + describe(*n));
      }
      out = value;
    }
  }
  void text(const char* key, std::string& out) {
    if (auto n = fetch(key)) {
      if (!n->IsScalar()) fail(*n, key, "expected text, got " + describe(*n));
      out = n->Scalar();
      if (out.empty()) fail(*n, key, "must not be empty");
      // Names and descriptions go into one-line headers of the dataset's text files.
      for (std::size_t i = 0; i < out.size(); ++i) {
        const unsigned char c = static_cast<unsigned char>(out[i]);
        if (c < 0x20 || c == 0x7f) {
          fail(*n, key,
               fmt::format("must be one line of printable text; character {} is a control "
                           "character ({})",
                           i + 1, c == '\n' ? "a line break" : fmt::format("code {}", c)));
        }
      }
    }
  }
  template <class E>
  void choice(const char* key, E& out, const schema::Names<E>& names) {
    if (auto n = fetch(key)) {
      std::string options;
      for (const auto& [value, name] : names) {
        if (n->IsScalar() && n->Scalar() == name) {
          out = value;
          return;
        }
        options += (options.empty() ? "" : ", ") + std::string(name);
      }
      fail(*n, key, "expected one of " + options + "; got " + describe(*n));
    }
  }
  void vec2(const char* key, Eigen::Vector2d& out, Limits limits) {
    if (auto n = fetch(key)) out = to_vector<2>(*n, key, {limits, limits});
  }
  void vec3(const char* key, Eigen::Vector3d& out, Limits xy, Limits z) {
    if (auto n = fetch(key)) out = to_vector<3>(*n, key, {xy, xy, z});
  }
  void optional_vec3(const char* key, std::optional<Eigen::Vector3d>& out, Limits xy, Limits z) {
    if (auto n = fetch(key)) out = to_vector<3>(*n, key, {xy, xy, z});
  }
  void polygon(const char* key, std::vector<Eigen::Vector2d>& out, Limits limits) {
    if (auto n = fetch(key)) {
      if (!n->IsSequence() || n->size() < 3) {
        fail(*n, key, "expected a list of at least 3 [x, y] points, got " + describe(*n));
      }
      out.clear();
      for (std::size_t i = 0; i < n->size(); ++i) {
        out.push_back(to_vector<2>((*n)[i], fmt::format("{}[{}]", key, i), {limits, limits}));
      }
    }
  }
  void points_if_any(const char* key, std::vector<Eigen::Vector2d>& out, Limits limits) {
    if (auto n = fetch(key)) {
      if (!n->IsSequence() || n->size() < 2) {
        fail(*n, key, "expected a list of at least 2 [x, y] points, got " + describe(*n));
      }
      out.clear();
      for (std::size_t i = 0; i < n->size(); ++i) {
        out.push_back(to_vector<2>((*n)[i], fmt::format("{}[{}]", key, i), {limits, limits}));
      }
    }
  }
  void text_list(const char* key, std::vector<std::string>& out) {
    if (auto n = fetch(key)) {
      if (!n->IsSequence()) fail(*n, key, "expected a list of names, got " + describe(*n));
      out.clear();
      for (std::size_t i = 0; i < n->size(); ++i) {
        const YAML::Node item = (*n)[i];
        if (!item.IsScalar()) {
          fail(item, fmt::format("{}[{}]", key, i), "expected a name, got " + describe(item));
        }
        out.push_back(item.Scalar());
      }
    }
  }
  void interval(const char* key, double& lo, double& hi, Limits limits) {
    if (auto n = fetch(key)) {
      if (n->IsScalar()) {
        lo = hi = to_number(*n, key, limits);
        return;
      }
      if (!n->IsSequence() || n->size() != 2) {
        fail(*n, key, "expected [min, max] or a single number, got " + describe(*n));
      }
      lo = to_number((*n)[0], std::string(key) + "[0]", limits);
      hi = to_number((*n)[1], std::string(key) + "[1]", limits);
      if (hi < lo) fail(*n, key, fmt::format("max {} is smaller than min {}", hi, lo));
    }
  }
  template <class T>
  void object(const char* key, T& out) {
    if (auto n = fetch(key)) {
      YamlReader child(*n, child_path(key), sources_);
      schema::visit(child, out);
      child.finish();
    }
  }
  /// A device: a shipped name or a device file (relative to the scene's folder), or a mapping.
  void device(const char* key, std::optional<radio_model::ReceiverDevice>& out) {
    if (auto n = fetch(key)) {
      if (n->IsMap()) {
        radio_model::ReceiverDevice inline_device;
        object(key, inline_device);
        out = inline_device;
        return;
      }
      if (!n->IsScalar() || n->Scalar().empty()) {
        fail(*n, key,
             "expected a shipped device's name, a device file or a mapping, got " + describe(*n));
      }
      const std::string folder = std::filesystem::path(sources_.file).parent_path().string();
      try {
        out = load_receiver_device(n->Scalar(), folder);
      } catch (const InvalidInputError& e) {
        fail(*n, key, e.what());
      }
    }
  }
  /// The wifi block: the receiver keys belong to the device when the block names one.
  void object(const char* key, WifiScannerSpec& out) {
    if (auto n = fetch(key)) {
      YamlReader child(*n, child_path(key), sources_);
      schema::visit(child, out);
      child.finish();
      if (!out.device) return;
      for (const char* receiver_key : {"sensitivity_dbm", "dwell_per_channel_s"}) {
        const YAML::Node set = (*n)[receiver_key];
        if (set.IsDefined()) {
          throw ParseError(sources_.where(set.Mark()), child_path(key) + "." + receiver_key,
                           fmt::format("the device '{}' sets the receiver: set {} in the "
                                       "device, or drop `device`",
                                       out.device->name, receiver_key));
        }
      }
    }
  }
  template <class T>
  void list(const char* key, std::vector<T>& out) {
    if (auto n = fetch(key)) {
      if (!n->IsSequence()) fail(*n, key, "expected a list, got " + describe(*n));
      out.clear();
      for (std::size_t i = 0; i < n->size(); ++i) {
        T item{};
        YamlReader child((*n)[i], fmt::format("{}[{}]", child_path(key), i), sources_);
        schema::visit(child, item);
        child.finish();
        out.push_back(std::move(item));
      }
    }
  }
  template <class T>
  void list_if_any(const char* key, std::vector<T>& out) {
    list(key, out);
  }

  /// Every key present must have been read by the schema.
  void finish() const {
    for (const auto& kv : node_) {
      const std::string key = kv.first.Scalar();
      if (!read_keys_.count(key)) {
        throw ParseError(sources_.where(kv.first.Mark()), child_path(key),
                         "unknown key (see scenes/README.md for the schema)" + suggestion(key));
      }
    }
  }

 private:
  std::optional<YAML::Node> fetch(const char* key) {
    const bool required = next_required_;
    next_required_ = false;
    read_keys_.insert(key);
    known_keys_.push_back(key);
    const YAML::Node n = node_[key];
    if (!n.IsDefined() || n.IsNull()) {
      if (required) {
        throw ParseError(sources_.where(node_.Mark()), child_path(key), "required key is missing");
      }
      return std::nullopt;
    }
    sources_.marks[child_path(key)] = n.Mark();
    return n;
  }

  std::string child_path(const std::string& key) const {
    return path_.empty() ? key : path_ + "." + key;
  }

  [[noreturn]] void fail(const YAML::Node& n, const std::string& key,
                         const std::string& message) const {
    throw ParseError(sources_.where(n.Mark()), child_path(key), message);
  }

  double to_number(const YAML::Node& n, const std::string& key, Limits limits) const {
    double value = 0;
    if (!n.IsScalar() || !YAML::convert<double>::decode(n, value) || !std::isfinite(value)) {
      fail(n, key, "expected " + describe_limits(limits) + ", got " + describe(n));
    }
    const bool low_ok = limits.open_low ? value > limits.lo : value >= limits.lo;
    if (!low_ok || value > limits.hi) {
      fail(n, key, "expected " + describe_limits(limits) + ", got " + n.Scalar());
    }
    return value;
  }

  std::uint64_t to_uint64(const YAML::Node& n, const std::string& key) const {
    std::uint64_t value = 0;
    const bool ok = n.IsScalar() && !n.Scalar().empty() && n.Scalar()[0] != '-' &&
                    YAML::convert<std::uint64_t>::decode(n, value);
    if (!ok) fail(n, key, "expected a non-negative whole number, got " + describe(n));
    return value;
  }

  template <int N>
  Eigen::Matrix<double, N, 1> to_vector(const YAML::Node& n, const std::string& key,
                                        const std::array<Limits, N>& limits) const {
    if (!n.IsSequence() || static_cast<int>(n.size()) != N) {
      fail(n, key, fmt::format("expected a list of {} numbers, got {}", N, describe(n)));
    }
    Eigen::Matrix<double, N, 1> v;
    for (int i = 0; i < N; ++i) v[i] = to_number(n[i], fmt::format("{}[{}]", key, i), limits[i]);
    return v;
  }

  std::string suggestion(const std::string& key) const { return did_you_mean(key, known_keys_); }

  YAML::Node node_;
  std::string path_;
  SourceMap& sources_;
  std::set<std::string> read_keys_;
  std::vector<std::string> known_keys_;
  bool next_required_ = false;
};

/// Writes a struct back as YAML through the same schema (resolved scenes).
/// Whether plain YAML would read `text` as something other than a string (null, a boolean or a
/// number: "007", "1e5", "0x1F", ".5", "nan", "yes"), so a reader that types plain scalars, as
/// Python's to_dict does, would change it.
bool reads_as_other_than_text(const std::string& text) {
  std::string lower;
  for (char c : text) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const char* word : {"", "~", "null", "true", "false", "yes", "no", "on", "off", "y", "n"})
    if (lower == word) return true;
  char* end = nullptr;
  std::strtod(text.c_str(), &end);
  return end != text.c_str() && *end == '\0';
}

class YamlWriter {
 public:
  YamlWriter(YAML::Emitter& out, TextQuoting quoting) : out_(out), quoting_(quoting) {}
  void required() {}
  void number(const char* key, double value, Limits) {
    out_ << YAML::Key << key << YAML::Value << exact(value);
  }
  void integer(const char* key, int value, Limits) {
    out_ << YAML::Key << key << YAML::Value << value;
  }
  void uint64(const char* key, std::uint64_t value, std::uint64_t = 0) {
    out_ << YAML::Key << key << YAML::Value << value;
  }
  void optional_uint64(const char* key, const std::optional<std::uint64_t>& value) {
    if (value) uint64(key, *value);
  }
  void optional_number(const char* key, const std::optional<double>& value, Limits l) {
    if (value) number(key, *value, l);
  }
  void boolean(const char* key, bool value) { out_ << YAML::Key << key << YAML::Value << value; }
  void text(const char* key, const std::string& value) {
    if (value.empty()) return;
    out_ << YAML::Key << key << YAML::Value;
    if (quoting_ == TextQuoting::kWhereAmbiguous && reads_as_other_than_text(value))
      out_ << YAML::DoubleQuoted;
    out_ << value;
  }
  template <class E>
  void choice(const char* key, E value, const schema::Names<E>& names) {
    for (const auto& [v, name] : names) {
      if (v == value) out_ << YAML::Key << key << YAML::Value << std::string(name);
    }
  }
  template <class Vec>
  void write_vector(const Vec& v) {
    out_ << YAML::Flow << YAML::BeginSeq;
    for (int i = 0; i < v.size(); ++i) out_ << exact(v[i]);
    out_ << YAML::EndSeq;
  }
  void vec2(const char* key, const Eigen::Vector2d& v, Limits) {
    out_ << YAML::Key << key << YAML::Value;
    write_vector(v);
  }
  void vec3(const char* key, const Eigen::Vector3d& v, Limits, Limits) {
    out_ << YAML::Key << key << YAML::Value;
    write_vector(v);
  }
  void optional_vec3(const char* key, const std::optional<Eigen::Vector3d>& v, Limits xy,
                     Limits z) {
    if (v) vec3(key, *v, xy, z);
  }
  void polygon(const char* key, const std::vector<Eigen::Vector2d>& points, Limits) {
    out_ << YAML::Key << key << YAML::Value << YAML::Flow << YAML::BeginSeq;
    for (const auto& p : points) write_vector(p);
    out_ << YAML::EndSeq;
  }
  void points_if_any(const char* key, const std::vector<Eigen::Vector2d>& points, Limits l) {
    if (!points.empty()) polygon(key, points, l);
  }
  void text_list(const char* key, const std::vector<std::string>& items) {
    if (quoting_ != TextQuoting::kWhereAmbiguous) {
      out_ << YAML::Key << key << YAML::Value << YAML::Flow << items;
      return;
    }
    // As text() quotes: route nodes named "01" or "1e2" must come back as those names.
    out_ << YAML::Key << key << YAML::Value << YAML::Flow << YAML::BeginSeq;
    for (const std::string& item : items) {
      if (reads_as_other_than_text(item)) out_ << YAML::DoubleQuoted;
      out_ << item;
    }
    out_ << YAML::EndSeq;
  }
  void interval(const char* key, double lo, double hi, Limits) {
    out_ << YAML::Key << key << YAML::Value << YAML::Flow << YAML::BeginSeq << exact(lo)
         << exact(hi) << YAML::EndSeq;
  }
  template <class T>
  void object(const char* key, T& value) {
    out_ << YAML::Key << key << YAML::Value << YAML::BeginMap;
    schema::visit(*this, value);
    out_ << YAML::EndMap;
  }
  template <class T>
  void list(const char* key, std::vector<T>& items) {
    out_ << YAML::Key << key << YAML::Value << YAML::BeginSeq;
    for (auto& item : items) {
      out_ << YAML::BeginMap;
      schema::visit(*this, item);
      out_ << YAML::EndMap;
    }
    out_ << YAML::EndSeq;
  }
  template <class T>
  void list_if_any(const char* key, std::vector<T>& items) {
    if (!items.empty()) list(key, items);
  }
  void device(const char* key, std::optional<radio_model::ReceiverDevice>& value) {
    if (value) object(key, *value);
  }
  /// The wifi block without the reference receiver's keys when a device sets the receiver.
  void object(const char* key, WifiScannerSpec& value) {
    out_ << YAML::Key << key << YAML::Value << YAML::BeginMap;
    if (value.device) {
      device("device", value.device);
      number("scan_interval_s", value.scan_interval_s, {});
    } else {
      schema::visit(*this, value);
    }
    out_ << YAML::EndMap;
  }
  /// radio.wall_loss_db only when it sets a loss: resolved scenes without one stay as they were.
  void object(const char* key, WallLossOverrides& value) {
    for (const auto& loss : value.by_material_db)
      if (loss) {
        out_ << YAML::Key << key << YAML::Value << YAML::BeginMap;
        schema::visit(*this, value);
        out_ << YAML::EndMap;
        return;
      }
  }

 private:
  // Shortest text that reads back to the same double ("2.8", not "2.7999999999999998").
  static std::string exact(double value) { return format_double_exact(value); }
  YAML::Emitter& out_;
  TextQuoting quoting_;
};

using Locator = std::function<std::string(const std::string& key_path)>;

[[noreturn]] void invalid(const Locator& locate, const std::string& key_path,
                          const std::string& message) {
  if (locate) throw ParseError(locate(key_path), key_path, message);
  throw InvalidInputError("scene: key '" + key_path + "': " + message);
}

/// Node ids are unique and no two nodes share a spot; returns the ids.
std::set<std::string> check_nodes(const Scene& scene, const Locator& locate) {
  std::set<std::string> node_ids;
  for (std::size_t i = 0; i < scene.nodes.size(); ++i) {
    if (!node_ids.insert(scene.nodes[i].id).second) {
      invalid(locate, fmt::format("nodes[{}].id", i),
              "duplicate node id '" + scene.nodes[i].id + "'");
    }
  }
  // Two nodes at one spot make two corridor ends that the graph does not join, and a route through
  // both turns back where it seems to go on.
  // Nodes of different levels may stand one above the other.
  std::map<std::tuple<std::string, double, double>, std::size_t> node_at;
  for (std::size_t i = 0; i < scene.nodes.size(); ++i) {
    const Eigen::Vector2d& p = scene.nodes[i].position_m;
    const auto [other, fresh] =
        node_at.emplace(std::tuple{level_or_first(scene, scene.nodes[i].level), p.x(), p.y()}, i);
    if (!fresh) {
      invalid(locate, fmt::format("nodes[{}].position_m", i),
              fmt::format("node '{}' is at the same spot as node '{}' (nodes[{}]); use one node "
                          "and name it in every corridor and route step that meets there",
                          scene.nodes[i].id, scene.nodes[other->second].id, other->second));
    }
  }
  return node_ids;
}

/// The room rows of a corridor `length_m` long (at key path `path`) fit along it.
void check_room_rows(const Corridor& c, const std::string& path, double length_m,
                     const Locator& locate) {
  for (std::size_t r = 0; r < c.rooms.size(); ++r) {
    const RoomRow& row = c.rooms[r];
    const std::string rp = fmt::format("{}.rooms[{}]", path, r);
    const double to_m = row.to_m.value_or(length_m);
    if (to_m > length_m + 1e-9) {
      invalid(locate, rp + ".to_m",
              fmt::format("{} m is beyond the corridor's length {:.3f} m", to_m, length_m));
    }
    if (row.from_m >= to_m) {
      invalid(locate, rp + ".from_m",
              fmt::format("from_m {} must be smaller than to_m {}", row.from_m, to_m));
    }
    if (row.door_offset_m + row.door_width_m > row.room_length_m) {
      invalid(locate, rp + ".door_offset_m",
              fmt::format("door ({} m + {} m wide) does not fit in a {} m room", row.door_offset_m,
                          row.door_width_m, row.room_length_m));
    }
  }
}

/// Corridor `i`: a fresh id, two distinct known end nodes, a usable length, room rows that fit.
void check_corridor(const Scene& scene, std::size_t i, const std::set<std::string>& node_ids,
                    std::set<std::string>& corridor_ids, const Locator& locate) {
  const Corridor& c = scene.corridors[i];
  const std::string path = fmt::format("corridors[{}]", i);
  if (!corridor_ids.insert(c.id).second) {
    invalid(locate, path + ".id", "duplicate corridor id '" + c.id + "'");
  }
  for (const auto& [key, end] : {std::pair{"from", c.from}, std::pair{"to", c.to}}) {
    if (!node_ids.count(end)) {
      invalid(locate, path + "." + key, "no node with id '" + end + "' (corridor '" + c.id + "')");
    }
  }
  if (c.from == c.to)
    invalid(locate, path + ".to", "corridor joins node '" + c.from + "' to itself");
  const std::string from_level = level_or_first(scene, scene.find_node(c.from)->level);
  const std::string to_level = level_or_first(scene, scene.find_node(c.to)->level);
  if (from_level != to_level) {
    invalid(locate, path + ".to",
            fmt::format("corridor '{}' joins node '{}' on level '{}' to node '{}' on level '{}'; a "
                        "corridor stays on one level",
                        c.id, c.from, from_level, c.to, to_level));
  }
  const double length_m =
      (scene.find_node(c.to)->position_m - scene.find_node(c.from)->position_m).norm();
  if (length_m < 0.5)
    invalid(locate, path, fmt::format("corridor is only {:.3f} m long", length_m));
  check_room_rows(c, path, length_m, locate);
}

using Adjacency = std::map<std::string, std::vector<std::string>>;

/// Checks every corridor; returns the corridor graph (node id to the node ids it is joined to).
Adjacency check_corridors(const Scene& scene, const std::set<std::string>& node_ids,
                          const Locator& locate) {
  if (scene.corridors.empty() && scene.spaces.empty())
    invalid(locate, "corridors", "a scene needs at least one corridor (or spaces)");
  std::set<std::string> corridor_ids;
  Adjacency adjacency;
  for (std::size_t i = 0; i < scene.corridors.size(); ++i) {
    check_corridor(scene, i, node_ids, corridor_ids, locate);
    const Corridor& c = scene.corridors[i];
    adjacency[c.from].push_back(c.to);
    adjacency[c.to].push_back(c.from);
  }
  return adjacency;
}

/// Every node is on a corridor, and each level's corridor graph is connected: the robot and the
/// radio see one building. (Corridors stay on one level, so a level's nodes reach only its own.)
void check_graph_connected(const Scene& scene, const Adjacency& adjacency, const Locator& locate) {
  if (scene.nodes.empty()) return;  // a scene of spaces only
  for (std::size_t i = 0; i < scene.nodes.size(); ++i) {
    if (!adjacency.count(scene.nodes[i].id)) {
      invalid(locate, fmt::format("nodes[{}]", i),
              "node '" + scene.nodes[i].id + "' is not joined to any corridor");
    }
  }
  std::map<std::string, std::string> first_node_of_level;
  std::set<std::string> reached;
  for (const SceneNode& start : scene.nodes) {
    if (!first_node_of_level.emplace(level_or_first(scene, start.level), start.id).second) continue;
    reached.insert(start.id);
    std::vector<std::string> frontier{start.id};
    while (!frontier.empty()) {
      const std::string n = frontier.back();
      frontier.pop_back();
      // Every node is a key (checked above), so at() finds each one.
      for (const auto& m : adjacency.at(n))
        if (reached.insert(m).second) frontier.push_back(m);
    }
  }
  for (std::size_t i = 0; i < scene.nodes.size(); ++i) {
    if (!reached.count(scene.nodes[i].id)) {
      invalid(locate, fmt::format("nodes[{}]", i),
              "the corridor graph is disconnected: node '" + scene.nodes[i].id +
                  "' cannot be reached from node '" +
                  first_node_of_level.at(level_or_first(scene, scene.nodes[i].level)) + "'");
    }
  }
}

void check_open_area_ids(const Scene& scene, const Locator& locate) {
  std::set<std::string> area_ids;
  for (std::size_t i = 0; i < scene.open_areas.size(); ++i) {
    if (!area_ids.insert(scene.open_areas[i].id).second) {
      invalid(locate, fmt::format("open_areas[{}].id", i), "duplicate open area id");
    }
  }
}

/// Spaces have unique ids, doors have a width.
void check_spaces(const Scene& scene, const Locator& locate) {
  std::set<std::string> ids;
  for (std::size_t i = 0; i < scene.spaces.size(); ++i) {
    if (!ids.insert(scene.spaces[i].id).second)
      invalid(locate, fmt::format("spaces[{}].id", i), "duplicate space id");
  }
  for (std::size_t i = 0; i < scene.doors.size(); ++i) {
    const double width_m = (scene.doors[i].to_m - scene.doors[i].from_m).norm();
    if (!(width_m >= 0.3 && width_m <= 10.0))
      invalid(locate, fmt::format("doors[{}].to_m", i),
              fmt::format("a door is 0.3 to 10 m wide, this one {:.3f} m", width_m));
  }
}

/// Route: nodes or waypoints (not both); known nodes, consecutive nodes joined by a corridor.
void check_route(const Scene& scene, const std::set<std::string>& node_ids, const Locator& locate) {
  const auto& route = scene.route.nodes;
  if (!scene.route.waypoints_m.empty()) {
    if (!route.empty())
      invalid(locate, "route.waypoints_m", "give route.nodes or route.waypoints_m, not both");
    return;  // the route builder checks that every leg stays in walkable space
  }
  if (route.size() < 2)
    invalid(locate, "route.nodes",
            "a route needs at least two nodes (or at least two route.waypoints_m)");
  for (std::size_t i = 0; i < route.size(); ++i) {
    if (!node_ids.count(route[i])) {
      invalid(locate, fmt::format("route.nodes[{}]", i), "no node with id '" + route[i] + "'");
    }
    const std::string node_level = level_or_first(scene, scene.find_node(route[i])->level);
    if (node_level != route_level(scene)) {
      invalid(locate, fmt::format("route.nodes[{}]", i),
              fmt::format("node '{}' is on level '{}', the route on level '{}'; a route runs on "
                          "one level (route.level)",
                          route[i], node_level, route_level(scene)));
    }
    if (i > 0 && !scene.corridor_between(route[i - 1], route[i])) {
      invalid(locate, fmt::format("route.nodes[{}]", i),
              "no corridor joins '" + route[i - 1] + "' and '" + route[i] + "'");
    }
  }
}

void check_depth_sensor(const Scene& scene, const Locator& locate) {
  const auto& depth = scene.sensors.depth;
  if (depth.max_range_m <= depth.min_range_m) {
    invalid(locate, "sensors.depth.max_range_m", "must be larger than min_range_m");
  }
  // The reader bounds these already; a scene built in code is checked here.
  if (depth.lateral_noise &&
      !(depth.lateral_noise_base_px >= 0.0 && depth.lateral_noise_angle_coeff_px >= 0.0)) {
    invalid(locate, "sensors.depth.lateral_noise_base_px",
            "lateral noise needs lateral_noise_base_px and lateral_noise_angle_coeff_px >= 0");
  }
  if (depth.lateral_noise && !(depth.grazing_dropout_deg < 90.0)) {
    invalid(locate, "sensors.depth.grazing_dropout_deg",
            "lateral noise caps the incidence angle here, so it must be below 90");
  }
}

void check_name(const Scene& scene, const Locator& locate) {
  if (const std::optional<std::string> problem = scene_name_problem(scene.name))
    invalid(locate, "name", *problem);
}

void check_camera(const Scene& scene, const Locator& locate) {
  const CameraSpec& camera = scene.sensors.camera;
  if (const std::optional<IntrinsicsProblem> problem = intrinsics_problem(camera.intrinsics))
    invalid(locate, "sensors.camera." + problem->key, problem->why);
  // The loader bounds it already; a scene built in code (or given another fps) is checked here.
  if (!(camera.fps >= kMinCameraFps && camera.fps <= kMaxCameraFps)) {
    invalid(locate, "sensors.camera.fps",
            fmt::format("expected a frame rate from {} to {}, got {}", kMinCameraFps, kMaxCameraFps,
                        camera.fps));
  }
}

void check_color_sensor(const Scene& scene, const Locator& locate) {
  const auto& color = scene.sensors.color;
  if (color.auto_exposure &&
      !(color.exposure_min_gain > 0.0 && color.exposure_min_gain <= color.exposure_max_gain)) {
    invalid(locate, "sensors.color.exposure_gain_range",
            fmt::format("must be [min, max] with 0 < min <= max, got [{}, {}]",
                        color.exposure_min_gain, color.exposure_max_gain));
  }
  if (color.auto_exposure && !(color.exposure_time_constant_s > 0.0)) {
    invalid(locate, "sensors.color.exposure_time_constant_s", "must be > 0");
  }
  if (color.auto_exposure &&
      !(color.exposure_target_dn > 0.0 && color.exposure_target_dn < 255.0)) {
    invalid(locate, "sensors.color.exposure_target_dn", "must be within (0, 255)");
  }
  if (color.noise && !(color.conversion_gain_dn_per_e >= 0.0 && color.read_noise_dn >= 0.0)) {
    invalid(locate, "sensors.color.conversion_gain_dn_per_e",
            "noise needs conversion_gain_dn_per_e and read_noise_dn >= 0");
  }
}

void check_access_points(const Scene& scene, const Locator& locate) {
  const auto& ap = scene.access_points;
  // Heights within the building: from the floor to the ceiling.
  const double ceiling_m = scene.building.wall_height_m;
  if (ap.height_m > ceiling_m) {
    invalid(locate, "access_points.height_m",
            fmt::format("{} m is above the ceiling (building.wall_height_m {} m)", ap.height_m,
                        ceiling_m));
  }
  for (std::size_t i = 0; i < ap.explicit_list.size(); ++i) {
    const double z_m = ap.explicit_list[i].position_m.z();
    if (!(z_m >= 0.0 && z_m <= ceiling_m)) {
      invalid(locate, fmt::format("access_points.list[{}].position_m[2]", i),
              fmt::format("height {} m is not within the building (0 to {} m, "
                          "building.wall_height_m)",
                          z_m, ceiling_m));
    }
  }
  if (ap.placement == ApPlacement::kExplicit && ap.explicit_list.empty() && ap.count > 0) {
    invalid(locate, "access_points.list", "placement 'explicit' needs a list of access points");
  }
  if (ap.placement == ApPlacement::kColinear && ap.count > 0 &&
      (ap.line_to_m - ap.line_from_m).norm() < 1e-6) {
    invalid(locate, "access_points.line_to_m",
            "placement 'colinear' needs line_from_m != line_to_m");
  }
}

void check_radio(const Scene& scene, const Locator& locate) {
  const RadioSpec& radio = scene.radio;
  if (radio.model == PathLossModel::kItuSiteGeneralFit &&
      radio.environment != RadioEnvironment::kOffice) {
    invalid(locate, "radio.environment",
            fmt::format("model 'itu_site_general_fit' has rows for 'office' only (ITU-R P.1238-11 "
                        "Table 2 fits offices, corridors and factories); this scene says '{}'",
                        to_string(radio.environment)));
  }
  if (radio.model != PathLossModel::kItuWalls && radio.distance_coefficient) {
    invalid(locate, "radio.distance_coefficient",
            fmt::format("model '{}' takes N from ITU-R P.1238's tables; distance_coefficient is "
                        "for model 'itu_walls'",
                        to_string(radio.model)));
  }
}

/// Level ids are unique, levels do not overlap, and every piece names a level the scene has.
void check_levels(const Scene& scene, const Locator& locate) {
  const auto missing = [&](const std::string& key, const std::string& level) {
    if (level.empty()) return;
    if (scene.levels.empty()) {
      invalid(locate, key,
              "names level '" + level + "', but the scene has no `levels:` (one level, unnamed)");
    }
    if (level_index(scene, level) < 0) {
      std::string ids;
      for (const Level& l : scene.levels) ids += (ids.empty() ? "'" : ", '") + l.id + "'";
      invalid(locate, key, "no level '" + level + "' (levels: " + ids + ")");
    }
  };
  std::set<std::string> ids;
  for (std::size_t i = 0; i < scene.levels.size(); ++i) {
    if (!ids.insert(scene.levels[i].id).second)
      invalid(locate, fmt::format("levels[{}].id", i), "duplicate level id");
  }
  const std::vector<ResolvedLevel> levels = resolved_levels(scene);
  const double walls_m = scene.building.wall_height_m;
  for (std::size_t i = 0; i < scene.levels.size(); ++i) {
    if (levels[i].storey_height_m < walls_m) {
      invalid(locate, fmt::format("levels[{}].storey_height_m", i),
              fmt::format("{} m is lower than the walls (building.wall_height_m {} m)",
                          levels[i].storey_height_m, walls_m));
    }
    // Level i takes its slab and its walls: from elevation - slab to elevation + wall height.
    for (std::size_t j = 0; j < i; ++j) {
      const ResolvedLevel &a = levels[i], &b = levels[j];
      const bool apart = a.elevation_m + walls_m <= b.elevation_m - b.slab_thickness_m + 1e-9 ||
                         b.elevation_m + walls_m <= a.elevation_m - a.slab_thickness_m + 1e-9;
      if (!apart) {
        invalid(locate, fmt::format("levels[{}].elevation_m", i),
                fmt::format("level '{}' (slab from {} m, walls up to {} m) overlaps level '{}' "
                            "(levels[{}]: slab from {} m, walls up to {} m)",
                            a.id, a.elevation_m - a.slab_thickness_m, a.elevation_m + walls_m, b.id,
                            j, b.elevation_m - b.slab_thickness_m, b.elevation_m + walls_m));
      }
    }
  }
  for (std::size_t i = 0; i < scene.nodes.size(); ++i)
    missing(fmt::format("nodes[{}].level", i), scene.nodes[i].level);
  for (std::size_t i = 0; i < scene.open_areas.size(); ++i)
    missing(fmt::format("open_areas[{}].level", i), scene.open_areas[i].level);
  for (std::size_t i = 0; i < scene.spaces.size(); ++i)
    missing(fmt::format("spaces[{}].level", i), scene.spaces[i].level);
  for (std::size_t i = 0; i < scene.doors.size(); ++i)
    missing(fmt::format("doors[{}].level", i), scene.doors[i].level);
  for (std::size_t i = 0; i < scene.obstacles.size(); ++i)
    missing(fmt::format("obstacles[{}].level", i), scene.obstacles[i].level);
  for (std::size_t i = 0; i < scene.access_points.explicit_list.size(); ++i)
    missing(fmt::format("access_points.list[{}].level", i),
            scene.access_points.explicit_list[i].level);
  missing("route.level", scene.route.level);
  // Every level has a plan: the world builds each one.
  for (std::size_t i = 0; i < scene.levels.size(); ++i) {
    const std::string& id = scene.levels[i].id;
    bool has_plan = false;
    for (const SceneNode& n : scene.nodes) has_plan |= level_or_first(scene, n.level) == id;
    for (const Space& sp : scene.spaces) has_plan |= level_or_first(scene, sp.level) == id;
    if (!has_plan) {
      invalid(locate, fmt::format("levels[{}]", i),
              "level '" + id + "' has no corridors' nodes and no spaces");
    }
  }
}

/// Checks what the schema's per-key limits cannot: cross-references, the graph, and relations
/// between keys. The checks run in this order, so the first problem in it is the one reported.
void validate_scene_impl(const Scene& scene, const Locator& locate) {
  // The loader bounds it already; a scene built in code is checked here.
  if (scene.sensors.time_origin_s > dataset::kMaxTimeOriginS) {
    invalid(locate, "sensors.time_origin_s",
            fmt::format("expected a whole number from 0 to {}, got {}", dataset::kMaxTimeOriginS,
                        scene.sensors.time_origin_s));
  }
  check_name(scene, locate);
  check_levels(scene, locate);
  const std::set<std::string> node_ids = check_nodes(scene, locate);
  const Adjacency adjacency = check_corridors(scene, node_ids, locate);
  check_graph_connected(scene, adjacency, locate);
  check_open_area_ids(scene, locate);
  check_spaces(scene, locate);
  check_route(scene, node_ids, locate);
  check_camera(scene, locate);
  check_depth_sensor(scene, locate);
  check_color_sensor(scene, locate);
  check_access_points(scene, locate);
  check_radio(scene, locate);
}

Scene load_scene_node(const YAML::Node& root, const std::string& source_name) {
  if (!root.IsDefined() || root.IsNull())
    throw ParseError(source_name, "", "the scene file is empty");
  SourceMap sources{source_name, {}};
  Scene scene;
  YamlReader reader(root, "", sources);
  // Check the version first so a future file fails with a clear message, not a wrong key.
  if (root.IsMap() && root["version"].IsDefined()) {
    const YAML::Node v = root["version"];
    if (!v.IsScalar() || v.Scalar() != "1") {
      throw ParseError(sources.where(v.Mark()), "version",
                       "unsupported scene version " + describe(v) + "; this build reads version 1");
    }
  }
  schema::visit(reader, scene);
  reader.finish();
  scene.source_path = sources.file;
  for (const auto& [key_path, mark] : sources.marks)
    scene.key_locations[key_path] = sources.where(mark);
  validate_scene_impl(scene, [&](const std::string& key) { return sources.where(key); });
  // Level defaults written out, so the resolved scene says where every level stands.
  const std::vector<ResolvedLevel> levels = resolved_levels(scene);
  for (std::size_t i = 0; i < scene.levels.size(); ++i) {
    scene.levels[i].elevation_m = levels[i].elevation_m;
    scene.levels[i].storey_height_m = levels[i].storey_height_m;
  }
  if (scene.access_points.placement == ApPlacement::kExplicit && scene.access_points.count == 0) {
    scene.access_points.count = static_cast<int>(scene.access_points.explicit_list.size());
  }
  return scene;
}

}  // namespace

Scene load_scene_yaml(const std::string& yaml_text, const std::string& source_name) {
  return load_scene_node(parse_yaml_document(yaml_text, source_name), source_name);
}

Scene load_scene_file(const std::string& path) {
  return load_scene_node(load_yaml_file(path), path);
}

radio_model::ReceiverDevice load_receiver_device(const std::string& name_or_file,
                                                 const std::string& folder) {
  const auto ends_with = [&](std::string_view tail) {
    return name_or_file.size() >= tail.size() &&
           name_or_file.compare(name_or_file.size() - tail.size(), tail.size(), tail) == 0;
  };
  const bool is_file =
      ends_with(".yaml") || ends_with(".yml") || name_or_file.find('/') != std::string::npos;
  if (!is_file) {
    if (auto device = radio_model::shipped_device(name_or_file)) return *device;
    std::vector<std::string> names;
    for (const radio_model::ReceiverDevice& d : radio_model::shipped_devices())
      names.push_back(d.name);
    throw InvalidInputError(
        fmt::format("no shipped device '{}'{} (shipped: {}; a device file's name ends in .yaml)",
                    name_or_file, did_you_mean(name_or_file, names), fmt::join(names, ", ")));
  }
  std::filesystem::path path(name_or_file);
  if (path.is_relative() && !folder.empty()) path = std::filesystem::path(folder) / path;
  if (!std::filesystem::is_regular_file(path))
    throw InvalidInputError(fmt::format("no device file {}", path.string()));
  SourceMap sources{path.string(), {}};
  const YAML::Node root = load_yaml_file(path.string());
  YamlReader reader(root, "", sources);
  radio_model::ReceiverDevice device;
  schema::visit(reader, device);
  reader.finish();
  return device;
}

void validate_scene(const Scene& scene) { validate_scene_impl(scene, nullptr); }

std::optional<std::string> scene_name_problem(const std::string& name) {
  constexpr std::size_t kMaxNameLength = 100;
  const auto alnum = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0; };
  const bool allowed = std::all_of(name.begin(), name.end(), [&](char c) {
    return alnum(c) || c == '_' || c == '-' || c == '.';
  });
  if (name.empty() || (name.size() <= kMaxNameLength && allowed && alnum(name.front())))
    return std::nullopt;
  return fmt::format(
      "'{}' is not a scene name: expected up to {} letters, digits, '_', '-' and '.', starting "
      "with a letter or digit (it names folders, as datasets/<name>-seed<seed>)",
      name, kMaxNameLength);
}

std::string resolved_scene_yaml(const Scene& scene, TextQuoting quoting) {
  YAML::Emitter out;
  out << YAML::BeginMap;
  YamlWriter writer(out, quoting);
  Scene copy = scene;
  schema::visit(writer, copy);
  out << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

}  // namespace wifislam::sim::scene
