#include "interop/external_system.hpp"

#include <algorithm>
#include <set>

#include <fmt/format.h>

#include "core/did_you_mean.hpp"
#include "core/error.hpp"
#include "core/option_table.hpp"
#include "core/yaml_document.hpp"

namespace wifislam::interop {

namespace fs = std::filesystem;

namespace {

const std::vector<std::string> kTopLevelKeys = {"version",   "name", "description", "command",
                                                "timeout_s", "wifi", "export",      "outputs"};
const std::vector<std::string> kOutputKeys = {"trajectory", "keyframes", "loop_closures",
                                              "graph",      "time_log",  "wifi_clusters"};
const std::vector<std::string> kPlaceholders = {"dataset", "rgbd_export", "out",     "seed",
                                                "wifi",    "system_dir",  "wifislam"};

/// Splits a command line at spaces; '...' and "..." keep spaces (no escapes, no expansion).
std::vector<std::string> split_command(const std::string& text, const YamlReader& r,
                                       const YAML::Node& node) {
  std::vector<std::string> out;
  std::string current;
  bool in_word = false;
  char quote = 0;
  for (char c : text) {
    if (quote) {
      if (c == quote) {
        quote = 0;
      } else {
        current += c;
      }
    } else if (c == '\'' || c == '"') {
      quote = c;
      in_word = true;
    } else if (c == ' ' || c == '\t') {
      if (in_word) out.push_back(std::move(current));
      current.clear();
      in_word = false;
    } else {
      current += c;
      in_word = true;
    }
  }
  if (quote) r.fail(node, "command", "an unclosed quote");
  if (in_word) out.push_back(std::move(current));
  return out;
}

/// Calls `visit(name)` for every placeholder of `text`; `{{` and `}}` are literal braces.
template <class Visit>
void for_each_placeholder(const std::string& text, const Visit& visit) {
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text.compare(i, 2, "{{") == 0 || text.compare(i, 2, "}}") == 0) {
      ++i;
      continue;
    }
    if (text[i] != '{') continue;
    const std::size_t end = text.find('}', i);
    visit(end == std::string::npos ? std::string() : text.substr(i + 1, end - i - 1));
    if (end == std::string::npos) return;
    i = end;
  }
}

void check_placeholders(const ExternalSystem& system, const YamlReader& r, const YAML::Node& node) {
  for (const std::string& arg : system.command) {
    for_each_placeholder(arg, [&](const std::string& name) {
      if (std::find(kPlaceholders.begin(), kPlaceholders.end(), name) == kPlaceholders.end()) {
        r.fail(node, "command",
               fmt::format("unknown placeholder {{{}}}{} (known: dataset, rgbd_export, out, "
                           "seed, wifi, system_dir, wifislam; a literal brace is {{{{ or }}}})",
                           name, did_you_mean(name, kPlaceholders)));
      }
      if (name == "rgbd_export" && !system.export_for) {
        r.fail(node, "command", "{rgbd_export} needs `export: rtabmap` or `export: orbslam2`");
      }
    });
  }
}

/// An output path: a file inside {out} (relative, no "..", not absolute, not {out} itself).
std::string output_path(const YamlReader& r, const YAML::Node& node, const std::string& key) {
  const std::string text = r.scalar(node, key);
  const fs::path p(text);
  const fs::path normal = p.lexically_normal();
  if (text.empty() || p.is_absolute() || !p.has_filename() || normal == "." ||
      normal.filename() == "." ||
      std::any_of(p.begin(), p.end(), [](const fs::path& part) { return part == ".."; })) {
    r.fail(node, key,
           "expected a file name inside {out} (relative, without ..), got '" + text + "'");
  }
  return p.lexically_normal().string();
}

void read_outputs(const YamlReader& r, const YAML::Node& outputs, ExternalSystem& system) {
  if (!outputs.IsMap()) r.fail(outputs, "outputs", "expected a mapping (trajectory, ...)");
  r.only_keys(outputs, kOutputKeys, "outputs.");
  if (!outputs["trajectory"]) {
    r.fail(outputs, "outputs.trajectory", "missing: the TUM trajectory the system writes");
  }
  system.trajectory = output_path(r, outputs["trajectory"], "outputs.trajectory");
  for (auto [key, field] :
       {std::pair{"keyframes", &system.keyframes},
        std::pair{"loop_closures", &system.loop_closures}, std::pair{"graph", &system.graph},
        std::pair{"time_log", &system.time_log},
        std::pair{"wifi_clusters", &system.wifi_clusters}}) {
    if (outputs[key]) *field = output_path(r, outputs[key], std::string("outputs.") + key);
  }
  if (!system.graph.empty() && system.keyframes.empty()) {
    r.fail(outputs["graph"], "outputs.graph",
           "needs outputs.keyframes too: graph.json numbers the keyframes of keyframes.txt");
  }
}

void read_command(const YamlReader& r, const YAML::Node& command, ExternalSystem& system) {
  if (command.IsScalar()) {
    system.command = split_command(command.Scalar(), r, command);
  } else if (command.IsSequence()) {
    for (const YAML::Node& arg : command) system.command.push_back(r.scalar(arg, "command"));
  } else {
    r.fail(command, "command", "expected a list of arguments, or one line");
  }
  if (system.command.empty() || system.command.front().empty()) {
    r.fail(command, "command", "the command is empty");
  }
}

void read_settings(const YamlReader& r, const YAML::Node& root, ExternalSystem& system) {
  if (const YAML::Node t = root["timeout_s"]) {
    if (!options::parse_number(r.scalar(t, "timeout_s"), system.timeout_s,
                               options::Infinity::kRefused) ||
        !(system.timeout_s > 0 && system.timeout_s <= 7 * 24 * 3600.0)) {
      r.fail(t, "timeout_s", "expected seconds, more than 0 and at most a week");
    }
  }
  if (const YAML::Node w = root["wifi"]) {
    if (!options::parse_boolean(r.scalar(w, "wifi"), system.wifi)) {
      r.fail(w, "wifi", "expected true or false");
    }
  }
  if (const YAML::Node e = root["export"]) {
    system.export_for = peer_from_string(r.scalar(e, "export"));
    if (!system.export_for) r.fail(e, "export", "expected rtabmap or orbslam2");
  }
}

}  // namespace

ExternalSystem load_external_system(const fs::path& file) {
  const std::string path = file.string();
  const YAML::Node root = load_yaml_file(path);
  const YamlReader r(path);
  if (!root.IsMap())
    throw ParseError(path, "", "a system file is a mapping of keys (see systems/)");
  r.only_keys(root, kTopLevelKeys, "");
  for (const char* key : {"version", "name", "command", "outputs"}) {
    if (!root[key]) throw ParseError(path, key, fmt::format("missing key '{}'", key));
  }
  if (r.scalar(root["version"], "version") != "1") {
    r.fail(root["version"], "version", "unsupported system file version; this build reads 1");
  }
  ExternalSystem system;
  system.file = fs::absolute(file).lexically_normal();
  system.name = r.scalar(root["name"], "name");
  if (system.name.empty() || system.name.find_first_not_of(
                                 "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-"
                                 ".") != std::string::npos) {
    r.fail(root["name"], "name", "expected a name of letters, digits, '_', '-' and '.'");
  }
  if (root["description"]) system.description = r.scalar(root["description"], "description");
  read_settings(r, root, system);
  read_command(r, root["command"], system);
  check_placeholders(system, r, root["command"]);
  read_outputs(r, root["outputs"], system);
  return system;
}

bool is_external_frontend(const std::string& frontend) {
  return frontend.starts_with(kExternalPrefix);
}

std::vector<std::string> shipped_system_names() {
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(WIFISLAM_SYSTEMS_DIR, ec)) {
    if (entry.path().extension() == ".yaml") names.push_back(entry.path().stem().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

ExternalSystem resolve_external_system(const std::string& frontend) {
  const std::string name = frontend.substr(std::string(kExternalPrefix).size());
  if (name.empty()) {
    throw InvalidInputError(
        fmt::format("front end '{}': name a system file or a shipped system "
                    "after '{}'",
                    frontend, kExternalPrefix));
  }
  if (const fs::path file = user_system_file(frontend); !file.empty()) {
    return load_external_system(file);
  }
  const fs::path shipped = fs::path(WIFISLAM_SYSTEMS_DIR) / (name + ".yaml");
  if (!fs::is_regular_file(shipped)) {
    const std::vector<std::string> known = shipped_system_names();
    std::string list;
    for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
    throw InvalidInputError(fmt::format(
        "front end '{}': no shipped system '{}'{} (shipped: {}; or give a system file path)",
        frontend, name, did_you_mean(name, known), list));
  }
  return load_external_system(shipped);
}

fs::path user_system_file(const std::string& frontend) {
  if (!is_external_frontend(frontend)) return {};
  const std::string name = frontend.substr(std::string(kExternalPrefix).size());
  if (name.find('/') != std::string::npos || name.ends_with(".yaml")) return name;
  return {};
}

std::vector<std::string> expand_command(const ExternalSystem& system,
                                        const ExternalRunValues& values) {
  const auto value_of = [&](const std::string& name) -> std::string {
    if (name == "dataset") return values.dataset.string();
    if (name == "rgbd_export") return values.rgbd_export.string();
    if (name == "out") return values.out.string();
    if (name == "seed") return std::to_string(values.seed);
    if (name == "wifi") return values.wifi ? "true" : "false";
    if (name == "system_dir") return system.file.parent_path().string();
    return values.wifislam_binary.string();  // "wifislam": the only other one load allows
  };
  std::vector<std::string> out;
  for (const std::string& arg : system.command) {
    std::string expanded;
    for (std::size_t i = 0; i < arg.size(); ++i) {
      if (arg.compare(i, 2, "{{") == 0 || arg.compare(i, 2, "}}") == 0) {
        expanded += arg[i++];
        continue;
      }
      const std::size_t end = arg[i] == '{' ? arg.find('}', i) : std::string::npos;
      if (end == std::string::npos) {
        expanded += arg[i];
        continue;
      }
      expanded += value_of(arg.substr(i + 1, end - i - 1));
      i = end;
    }
    out.push_back(std::move(expanded));
  }
  return out;
}

}  // namespace wifislam::interop
