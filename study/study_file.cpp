#include "study/study_file.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <map>
#include <set>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <yaml-cpp/yaml.h>

#include "core/atomic_file.hpp"
#include "core/did_you_mean.hpp"
#include "core/error.hpp"
#include "core/option_table.hpp"
#include "core/yaml_document.hpp"
#include "eval/evaluate_run.hpp"
#include "interop/external_system.hpp"
#include "sim/scene/scene_keys.hpp"
#include "slam/frontend/front_end_registry.hpp"
#include "slam/slam_options.hpp"
#include "study/front_end_choice.hpp"

namespace wifislam::study {

namespace {

namespace fs = std::filesystem;

const std::vector<std::string> kTopLevelKeys = {"version", "name", "description", "scene", "level",
                                                "set",     "axes", "cases",       "slam"};
const std::vector<std::string> kSlamKeys = {"frontend", "fps", "max_frames", "settings"};

// The SLAM options a radio-level case reads: the Wi-Fi module's signature and pause settings
// (run_case in study_runner.cpp hands radio_resolution.hpp `SlamOptions::wifi` and nothing
// else). Any other option would leave every number of a radio case as it is.
const std::vector<std::string> kRadioLevelOptions = {"wifi_similarity", "wifi_floor_dbm",
                                                     "wifi_pause_gap_s", "wifi_pause_motion_m"};

bool radio_level_reads(const std::string& option) {
  return std::find(kRadioLevelOptions.begin(), kRadioLevelOptions.end(), option) !=
         kRadioLevelOptions.end();
}

/// `effect`: what the key would do at level radio ("would change no result").
std::string radio_level_refusal(const std::string& key, const std::string& effect) {
  return fmt::format(
      "level radio renders nothing and runs no front end: '{}' {}; a radio case reads only the "
      "SLAM options {} (use level: slam)",
      key, effect, fmt::join(kRadioLevelOptions, ", "));
}

// A SLAM case runs vanilla and with Wi-Fi; a radio case runs neither.
constexpr const char* kWifiOptionRefusal =
    "a study runs each SLAM case both vanilla and with Wi-Fi (and a radio case neither), so the "
    "'wifi' option would change nothing";

// Ids number cases in five digits, so they sort in study order only below 100 000; and the
// product is held in memory, which a few dozen two-valued axes (2^40 cases) would exhaust.
constexpr std::size_t kMaxStudyCases = 100000;

using Reader = YamlReader;

std::vector<std::string> slam_option_keys() {
  std::vector<std::string> keys;
  for (const std::string& key : options::option_keys<slam::SlamOptions>())
    keys.push_back("slam." + key);
  return keys;
}

AxisKind axis_kind(const Reader& r, const YAML::Node& key_node, const std::string& key) {
  if (key == "frontend") return AxisKind::kFrontend;
  if (key == "system") return AxisKind::kSystem;
  if (key == "slam.frontend") {  // one way to sweep front ends, checked as front ends
    r.fail(key_node, "axes." + key, "sweep front ends with the 'frontend' or 'system' axis");
  }
  if (key.rfind("slam.", 0) == 0) {
    const auto keys = slam_option_keys();
    if (std::find(keys.begin(), keys.end(), key) == keys.end()) {
      r.fail(key_node, "axes." + key, "unknown SLAM option" + did_you_mean(key, keys));
    }
    if (key == "slam.wifi") r.fail(key_node, "axes." + key, kWifiOptionRefusal);
    return AxisKind::kSlamOption;
  }
  if (!sim::scene::is_scene_key_path(key)) {
    std::vector<std::string> known = sim::scene::scene_key_paths();
    for (const std::string& k : slam_option_keys()) known.push_back(k);
    known.push_back("frontend");
    known.push_back("system");
    r.fail(key_node, "axes." + key,
           "not a scene key, a SLAM option (slam.<option>), 'frontend' or 'system'" +
               did_you_mean(sim::scene::generic_key_path(key), known));
  }
  return AxisKind::kSceneKey;
}

std::string case_label(const std::vector<StudyAxis>& axes, const std::vector<std::string>& values) {
  std::string label;
  for (std::size_t a = 0; a < axes.size(); ++a) {
    label += (a ? ";" : "") + axes[a].key + "=" + values[a];
  }
  return label;
}

StudyCase make_case(const std::vector<StudyAxis>& axes, std::vector<std::string> values,
                    std::size_t index) {
  StudyCase c;
  c.id = fmt::format("{:05d}-{}", index, sha256_hex(case_label(axes, values)).substr(0, 12));
  c.values = std::move(values);
  c.index = index;
  return c;
}

}  // namespace

const char* to_string(StudyLevel level) { return level == StudyLevel::kRadio ? "radio" : "slam"; }

std::string column_name(const std::string& axis_key) {
  std::string out;
  for (char c : axis_key) {
    out += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  }
  while (!out.empty() && out.back() == '_') out.pop_back();
  return out;
}

StudyFile load_study_file(const fs::path& path) {
  // Bounded, and never blocking on a FIFO: a plain ifstream hung on one and read /dev/zero
  // until memory ran out.
  return load_study_yaml(read_yaml_text(path.string()), path);
}

namespace {

/// version, name, description, scene (relative to the study file) and level.
void read_header(const Reader& r, const YAML::Node& root, const fs::path& path, StudyFile& study) {
  for (const char* key : {"version", "name", "scene", "axes"}) {
    if (!root[key]) throw ParseError(path.string(), key, fmt::format("missing key '{}'", key));
  }
  if (r.scalar(root["version"], "version") != "1") {
    r.fail(root["version"], "version", "unsupported study version; this build reads version 1");
  }
  study.name = r.scalar(root["name"], "name");
  if (study.name.empty() || study.name.find_first_of("\n\r") != std::string::npos) {
    r.fail(root["name"], "name", "expected a one-line name");
  }
  if (root["description"]) study.description = r.scalar(root["description"], "description");
  const std::string scene = r.scalar(root["scene"], "scene");
  study.scene_path = fs::path(scene).is_absolute() ? fs::path(scene) : path.parent_path() / scene;
  if (root["level"]) {
    const std::string level = r.scalar(root["level"], "level");
    if (level == "radio") {
      study.level = StudyLevel::kRadio;
    } else if (level == "slam") {
      study.level = StudyLevel::kSlam;
    } else {
      r.fail(root["level"], "level", "expected 'radio' or 'slam', got '" + level + "'");
    }
  }
}

/// `set`: scene keys for every case, kept as flow YAML to set on each case's scene.
void read_scene_set(const Reader& r, const YAML::Node& set, StudyFile& study) {
  if (!set.IsMap()) r.fail(set, "set", "expected a mapping of scene keys to values");
  for (const auto& kv : set) {
    const std::string key = kv.first.Scalar();
    if (!sim::scene::is_scene_key_path(key)) {
      r.fail(kv.first, "set." + key,
             "not a scene key" +
                 did_you_mean(sim::scene::generic_key_path(key), sim::scene::scene_key_paths()));
    }
    if (!kv.second.IsScalar() && !kv.second.IsSequence()) {
      r.fail(kv.second, "set." + key, "expected a value or a list (e.g. a point [x, y])");
    }
    YAML::Emitter out;
    out << YAML::Flow << kv.second;
    study.scene_set.emplace_back(key, out.c_str());
  }
}

/// What an axis value means, for finding the same value written twice, as its reader takes it:
/// the scene's seed is decoded by YAML (1, 0x1 and 0o1 are one seed; a leading 0 is octal
/// there), every other number decimally (the scene's numbers and the SLAM options: 010 is ten,
/// +1 and 1.0 are one); anything else is its text.
std::string axis_value_meaning(const std::string& key, const std::string& value) {
  if (key == "seed") {
    std::uint64_t seed = 0;
    if (YAML::convert<std::uint64_t>::decode(YAML::Node(value), seed))
      return fmt::format("n:{}", seed);
    return "t:" + value;
  }
  const std::string_view digits =
      !value.empty() && value[0] == '+' ? std::string_view(value).substr(1) : value;
  double number = 0.0;
  const char* end = digits.data() + digits.size();
  const auto [ptr, ec] = std::from_chars(digits.data(), end, number);
  if (!digits.empty() && ec == std::errc() && ptr == end && std::isfinite(number)) {
    return fmt::format("r:{}", number);  // shortest text that reads back as the same double
  }
  return "t:" + value;
}

/// "external:X" with X a relative system file path made relative to `dir`; anything else as is.
std::string front_end_from(const fs::path& dir, const std::string& frontend) {
  if (!interop::is_external_frontend(frontend)) return frontend;
  const std::string x = frontend.substr(std::string(interop::kExternalPrefix).size());
  const fs::path file(x);
  const bool is_path = x.find('/') != std::string::npos || file.extension() == ".yaml";
  if (!is_path || file.is_absolute()) return frontend;
  return std::string(interop::kExternalPrefix) + (dir / file).lexically_normal().string();
}

StudyAxis read_axis(const Reader& r, const YAML::Node& key_node, const YAML::Node& values,
                    const fs::path& study_dir) {
  StudyAxis axis;
  axis.key = key_node.Scalar();
  axis.where = r.where(key_node);
  axis.kind = axis_kind(r, key_node, axis.key);
  const std::string key_path = "axes." + axis.key;
  if (values.IsScalar()) {
    axis.values.push_back(values.Scalar());
  } else if (values.IsSequence() && values.size() > 0) {
    for (const YAML::Node& v : values) axis.values.push_back(r.scalar(v, key_path));
  } else {
    r.fail(values, key_path, "expected a value or a non-empty list of values");
  }
  // Values are compared as what they mean: 1, 01, +1 and 0x1 are one seed (the scene reader
  // takes them alike), so listing two of them would run the same case twice.
  std::map<std::string, std::string> seen;
  for (const std::string& v : axis.values) {
    const auto [it, added] = seen.emplace(axis_value_meaning(axis.key, v), v);
    if (!added) {
      r.fail(values, key_path,
             it->second == v ? "value '" + v + "' is listed twice"
                             : "values '" + it->second + "' and '" + v + "' are the same");
    }
  }
  if (axis.kind == AxisKind::kFrontend || axis.kind == AxisKind::kSystem) {
    for (const std::string& v : axis.values) {
      const std::string frontend =
          front_end_from(study_dir, axis.kind == AxisKind::kSystem ? system_front_end(v) : v);
      if (const std::optional<std::string> problem = front_end_problem(frontend)) {
        r.fail(values, key_path, *problem);
      }
    }
  }
  return axis;
}

/// `axes`, in file order; each axis is one column, so two must not share a column name, and
/// their product must stay within the case ids' five digits.
void read_axes(const Reader& r, const YAML::Node& axes, StudyFile& study) {
  if (!axes.IsMap() || axes.size() == 0) {
    r.fail(axes, "axes", "expected a mapping of axis keys to lists of values");
  }
  for (const auto& kv : axes) {
    study.axes.push_back(read_axis(r, kv.first, kv.second, study.path.parent_path()));
  }
  // One way to choose the front end, and only where one runs.
  const auto has = [&](AxisKind kind) {
    return std::any_of(study.axes.begin(), study.axes.end(),
                       [kind](const StudyAxis& a) { return a.kind == kind; });
  };
  if (has(AxisKind::kFrontend) && has(AxisKind::kSystem)) {
    r.fail(axes, "axes", "give the front end by 'frontend' or by 'system', not both");
  }
  if (study.level == StudyLevel::kRadio && (has(AxisKind::kFrontend) || has(AxisKind::kSystem))) {
    r.fail(axes, "axes",
           "level radio runs no front end: a 'frontend' or 'system' axis would only repeat "
           "identical cases (use level: slam)");
  }
  if (study.level == StudyLevel::kRadio) {
    for (const StudyAxis& a : study.axes) {
      if (a.kind == AxisKind::kSlamOption && !radio_level_reads(a.key.substr(5))) {
        throw ParseError(a.where, "axes." + a.key,
                         radio_level_refusal(a.key, "would only repeat identical cases"));
      }
    }
  }
  // Distinct column names: "a.b" and "a_b" would share one.
  std::set<std::string> columns;
  for (const StudyAxis& a : study.axes) {
    if (!columns.insert(column_name(a.key)).second) {
      throw ParseError(a.where, "axes." + a.key, "two axes share the column " + column_name(a.key));
    }
  }
  std::size_t product_size = 1;
  for (const StudyAxis& axis : study.axes) {
    product_size *= axis.values.size();  // at most kMaxStudyCases times a list's length
    if (product_size > kMaxStudyCases) {
      r.fail(axes, "axes",
             fmt::format("the axes up to '{}' make more than {} cases (case ids number them "
                         "in five digits); split the study",
                         axis.key, kMaxStudyCases));
    }
  }
}

/// The full product of the axes' values, in axis order (the last axis varies fastest).
std::vector<std::vector<std::string>> axis_product(const std::vector<StudyAxis>& axes) {
  std::vector<std::vector<std::string>> product = {{}};
  for (const StudyAxis& axis : axes) {
    std::vector<std::vector<std::string>> next;
    for (const auto& partial : product) {
      for (const std::string& v : axis.values) {
        auto extended = partial;
        extended.push_back(v);
        next.push_back(std::move(extended));
      }
    }
    product = std::move(next);
  }
  return product;
}

/// The index in the product of each listed case (`cases`), in increasing order.
std::set<std::size_t> listed_case_indexes(const Reader& r, const YAML::Node& listed,
                                          const std::vector<StudyAxis>& axes) {
  if (!listed.IsSequence() || listed.size() == 0) {
    r.fail(listed, "cases", "expected a list of cases, each a mapping of every axis to a value");
  }
  std::vector<std::string> axis_keys;
  for (const StudyAxis& axis : axes) axis_keys.push_back(axis.key);
  std::set<std::size_t> chosen;
  for (std::size_t i = 0; i < listed.size(); ++i) {
    const YAML::Node c = listed[i];
    const std::string key_path = fmt::format("cases[{}]", i);
    if (!c.IsMap()) r.fail(c, key_path, "expected a mapping of every axis to a value");
    r.only_keys(c, axis_keys, key_path + ".");
    // The case's index in the product, from its values' places (searching the product for
    // each listed case took listed x product comparisons).
    std::size_t index = 0;
    for (const StudyAxis& axis : axes) {
      if (!c[axis.key]) r.fail(c, key_path, "missing axis '" + axis.key + "'");
      const std::string v = r.scalar(c[axis.key], key_path + "." + axis.key);
      const auto at = std::find(axis.values.begin(), axis.values.end(), v);
      if (at == axis.values.end()) {
        r.fail(c[axis.key], key_path + "." + axis.key,
               fmt::format("'{}' is not one of the axis's values", v));
      }
      index = index * axis.values.size() + static_cast<std::size_t>(at - axis.values.begin());
    }
    if (!chosen.insert(index).second) r.fail(c, key_path, "this case is listed twice");
  }
  return chosen;
}

/// The cases: those listed under `cases`, else the whole product.
void make_cases(const Reader& r, const YAML::Node& listed, StudyFile& study) {
  const std::vector<std::vector<std::string>> product = axis_product(study.axes);
  if (listed) {
    for (std::size_t index : listed_case_indexes(r, listed, study.axes))
      study.cases.push_back(make_case(study.axes, product[index], index));
  } else {
    for (std::size_t i = 0; i < product.size(); ++i)
      study.cases.push_back(make_case(study.axes, product[i], i));
  }
}

/// `slam`: front end, frame rate, length, and SLAM options (checked now, applied per case). The
/// numbers read by the options' text rules (core/option_table.hpp).
void read_slam(const Reader& r, const YAML::Node& s, StudyFile& study) {
  if (!s.IsMap()) r.fail(s, "slam", "expected a mapping (frontend, fps, max_frames, settings)");
  r.only_keys(s, kSlamKeys, "slam.");
  if (study.level == StudyLevel::kRadio) {
    for (const char* key : {"frontend", "fps", "max_frames"}) {
      if (s[key])
        r.fail(s[key], std::string("slam.") + key,
               radio_level_refusal(std::string("slam.") + key, "would change no result"));
    }
  }
  if (s["frontend"]) {
    study.slam.frontend = r.scalar(s["frontend"], "slam.frontend");
    if (const std::optional<std::string> problem = front_end_problem(study.slam.frontend)) {
      r.fail(s["frontend"], "slam.frontend", *problem);
    }
  }
  if (s["fps"]) {
    double fps = 0;
    if (!options::parse_number(r.scalar(s["fps"], "slam.fps"), fps, options::Infinity::kRefused) ||
        !(fps > 0 && fps <= 120)) {
      r.fail(s["fps"], "slam.fps", "expected frames per second in (0, 120]");
    }
    study.slam.fps = fps;
  }
  if (s["max_frames"]) {
    std::int64_t frames = 0;
    // Each case's runs are scored against ground truth, which aligns at least 3 poses: fewer
    // frames would fail every case after its rendering.
    const auto fewest = static_cast<std::int64_t>(eval::kMinAssociatedPoses);
    if (!options::parse_int64(r.scalar(s["max_frames"], "slam.max_frames"), frames) ||
        frames < -1 || (frames >= 0 && frames < fewest)) {
      r.fail(s["max_frames"], "slam.max_frames",
             fmt::format("expected -1 (every frame) or a whole number of {} or more (the "
                         "evaluation aligns at least {} poses)",
                         fewest, fewest));
    }
    study.slam.max_frames = frames;
  }
  if (const YAML::Node settings = s["settings"]) {
    if (!settings.IsMap()) r.fail(settings, "slam.settings", "expected a mapping of options");
    for (const auto& kv : settings) {
      const std::string key = kv.first.Scalar();
      const std::string value = r.scalar(kv.second, "slam.settings." + key);
      if (key == "wifi") r.fail(kv.first, "slam.settings." + key, kWifiOptionRefusal);
      slam::SlamOptions probe;
      try {
        slam::set_option(probe, key, value);
      } catch (const Error& e) {
        r.fail(kv.first, "slam.settings." + key, e.what());
      }
      if (study.level == StudyLevel::kRadio && !radio_level_reads(key)) {
        r.fail(kv.first, "slam.settings." + key,
               radio_level_refusal(key, "would change no result"));
      }
      study.slam.settings.push_back(key + "=" + value);
    }
  }
}

}  // namespace

StudyFile load_study_yaml(const std::string& text, const fs::path& path) {
  const std::string file = path.string();
  const YAML::Node root = parse_yaml_document(text, file);
  const Reader r(file);
  if (root.IsNull()) {
    // An empty file, or a FIFO no program writes (read as empty rather than waited on).
    throw ParseError(file, "", "the study file is empty");
  }
  if (!root.IsMap()) throw ParseError(file, "", "a study file is a mapping of keys (see studies/)");
  r.only_keys(root, kTopLevelKeys, "");
  StudyFile study;
  study.path = path;
  study.file_hash = sha256_hex(text);
  read_header(r, root, path, study);
  if (const YAML::Node set = root["set"]) read_scene_set(r, set, study);
  read_axes(r, root["axes"], study);
  make_cases(r, root["cases"], study);
  if (const YAML::Node s = root["slam"]) read_slam(r, s, study);
  return study;
}

std::string axis_front_end(const StudyFile& study, AxisKind kind, const std::string& value) {
  return front_end_from(study.path.parent_path(),
                        kind == AxisKind::kSystem ? system_front_end(value) : value);
}

std::vector<fs::path> input_files(const StudyFile& study) {
  std::vector<fs::path> out = {study.path, study.scene_path};
  const auto add_vocabulary = [&](const std::string& setting) {
    const std::string prefix = "vocabulary=";
    if (setting.rfind(prefix, 0) == 0 && setting.size() > prefix.size())
      out.emplace_back(setting.substr(prefix.size()));
  };
  for (const std::string& setting : study.slam.settings) add_vocabulary(setting);
  const auto add_system_file = [&](const std::string& frontend) {
    if (fs::path file = interop::user_system_file(frontend); !file.empty())
      out.push_back(std::move(file));
  };
  add_system_file(front_end_from(study.path.parent_path(), study.slam.frontend));
  for (const StudyAxis& axis : study.axes) {
    for (const std::string& value : axis.values) {
      if (axis.kind == AxisKind::kSlamOption) {
        add_vocabulary(axis.key.substr(axis.key.find('.') + 1) + "=" + value);
      } else if (axis.kind == AxisKind::kFrontend || axis.kind == AxisKind::kSystem) {
        add_system_file(axis_front_end(study, axis.kind, value));
      }
    }
  }
  return out;
}

std::vector<StudyCase> shard_cases(const StudyFile& study, int index, int count) {
  std::vector<StudyCase> out;
  for (const StudyCase& c : study.cases) {
    if (static_cast<int>(c.index % static_cast<std::size_t>(count)) == index) out.push_back(c);
  }
  return out;
}

}  // namespace wifislam::study
