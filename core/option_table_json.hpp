#pragma once
// The options of an options struct (core/option_table.hpp) as JSON, and the reference a --help
// prints from their defaults. Apart from option_table.hpp so that only the files that write
// options pay for nlohmann/json.hpp.

#include <cmath>
#include <cstdint>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/option_table.hpp"

namespace wifislam::options {

/// Every option as a JSON value keyed by its name: choices by name, an infinite number as "inf"
/// (JSON has no infinity; "inf" reads back through TextSetter).
template <class Json>
class JsonWriter {
 public:
  Json out = Json::object();
  void integer(const char* key, int& field, const char*) { out[key] = field; }
  void uint64(const char* key, std::uint64_t& field, const char*) { out[key] = field; }
  void number(const char* key, double& field, const char*, Infinity = Infinity::kRefused) {
    if (std::isinf(field)) {
      out[key] = "inf";
    } else {
      out[key] = field;
    }
  }
  void boolean(const char* key, bool& field, const char*) { out[key] = field; }
  void text(const char* key, std::string& field, const char*) { out[key] = field; }
  /// As the text it is set from, so a run.json's value can be given back to --set.
  void number_list(const char* key, std::vector<double>& field, const char*) {
    out[key] = number_list_text(field);
  }
  template <class E>
  void choice(const char* key, E& field, const Choices<E>& choices, const char*) {
    for (const auto& [value, name] : choices)
      if (value == field) out[key] = std::string(name);
  }
};

/// Every option of `o` as JSON (nlohmann::json or nlohmann::ordered_json, which keeps the
/// visiting order).
template <class Json, class Options>
Json to_json(const Options& o) {
  Options copy = o;  // the visitors take fields by reference
  JsonWriter<Json> writer;
  visit_options(writer, copy);
  return writer.out;
}

/// The reference a --help prints: "  key=default\n      help\n" for every option.
template <class Options>
std::string reference() {
  const Options defaults;
  const nlohmann::ordered_json values = to_json<nlohmann::ordered_json>(defaults);
  std::string out;
  for (const auto& [key, help] : option_help<Options>()) {
    const nlohmann::ordered_json& v = values.at(key);
    out += fmt::format("  {}={}\n      {}\n", key, v.is_string() ? v.get<std::string>() : v.dump(),
                       help);
  }
  return out;
}

}  // namespace wifislam::options
