#pragma once
// One way to declare the options a user sets by name (the SLAM's options, the evaluation's
// thresholds) and one set of rules for reading them from text, after the scene schema's model
// (sim/scene/scene_schema.hpp: the fields written once, as a visitor). An options struct provides
//
//   template <class V> void visit_options(V& v, Options& o)
//
// calling, once per option and in the order the reference lists them,
//   v.integer(key, int&, help)           v.uint64(key, std::uint64_t&, help)
//   v.number(key, double&, help[, Infinity::kAllowed])
//   v.boolean(key, bool&, help)          v.text(key, std::string&, help)
//   v.choice(key, E&, Choices<E>, help)  v.number_list(key, std::vector<double>&, help)
// and the generic visitors here set one option from text and list the keys and their help;
// core/option_table_json.hpp writes the options as JSON and prints the reference (apart because
// nlohmann/json.hpp costs a second of compile time in each of the ~50 files that include this).
//
// Text rules, the same for every option: a boolean is true/false, 1/0 or on/off; an integer is a
// whole decimal number (no fraction, no exponent); a number is a finite decimal number, and "inf"
// or "infinity" only where an option means "off" by it; a choice is one of its names; a number
// list is numbers separated by commas (spaces around them allowed), or "none" for an empty list.
// An unknown key is refused naming the closest known one.

#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "core/did_you_mean.hpp"
#include "core/error.hpp"

namespace wifislam::options {

/// Whether a number option reads "inf" (an option that infinity switches off).
enum class Infinity { kRefused, kAllowed };

template <class E>
using Choices = std::vector<std::pair<E, std::string_view>>;

bool parse_boolean(std::string_view text, bool& out);
bool parse_integer(std::string_view text, int& out);
bool parse_int64(std::string_view text, std::int64_t& out);
bool parse_uint64(std::string_view text, std::uint64_t& out);
bool parse_number(std::string_view text, double& out, Infinity infinity);
/// "a,b,c" (finite numbers, spaces around each allowed) or "none": the list. False, with the
/// entry that is not a number in `bad_entry`, otherwise.
bool parse_number_list(std::string_view text, std::vector<double>& out, std::string& bad_entry);
/// The list as parse_number_list reads it: "449.2,89.84,22.46", "none" when empty.
std::string number_list_text(const std::vector<double>& values);

/// "a, b, c" of the names of `choices`.
template <class E>
std::string choice_list(const Choices<E>& choices) {
  std::string out;
  for (const auto& [value, name] : choices) out += (out.empty() ? "" : ", ") + std::string(name);
  return out;
}

/// Sets the one option named `key` from `text` (the visitor `visit_options` walks).
class TextSetter {
 public:
  TextSetter(std::string source, std::string key, std::string text)
      : source_(std::move(source)), key_(std::move(key)), text_(std::move(text)) {}
  bool found() const { return found_; }

  void integer(const char* key, int& field, const char*) {
    // The range is said: a whole number too large for the field reads as no integer at all.
    if (mine(key) && !parse_integer(text_, field)) {
      throw bad(fmt::format("an integer from {} to {}", std::numeric_limits<int>::min(),
                            std::numeric_limits<int>::max()));
    }
  }
  void uint64(const char* key, std::uint64_t& field, const char*) {
    if (mine(key) && !parse_uint64(text_, field)) {
      throw bad(fmt::format("a non-negative integer up to {}",
                            std::numeric_limits<std::uint64_t>::max()));
    }
  }
  void number(const char* key, double& field, const char*, Infinity infinity = Infinity::kRefused) {
    if (!mine(key)) return;
    double value = 0;
    if (!parse_number(text_, value, infinity)) {
      throw bad(infinity == Infinity::kAllowed ? "a finite number or inf" : "a finite number");
    }
    field = value;
  }
  void boolean(const char* key, bool& field, const char*) {
    if (mine(key) && !parse_boolean(text_, field)) throw bad("true or false");
  }
  void text(const char* key, std::string& field, const char*) {
    if (mine(key)) field = text_;
  }
  void number_list(const char* key, std::vector<double>& field, const char*) {
    if (!mine(key)) return;
    std::string bad_entry;
    if (!parse_number_list(text_, field, bad_entry)) {
      throw bad(
          fmt::format("numbers separated by commas, or none ('{}' is not a number)", bad_entry));
    }
  }
  template <class E>
  void choice(const char* key, E& field, const Choices<E>& choices, const char*) {
    if (!mine(key)) return;
    for (const auto& [value, name] : choices) {
      if (text_ == name) {
        field = value;
        return;
      }
    }
    throw bad("one of " + choice_list(choices));
  }

 private:
  bool mine(const char* key) {
    if (found_ || key_ != key) return false;
    found_ = true;
    return true;
  }
  ParseError bad(const std::string& expected) const {
    return ParseError(source_, key_, fmt::format("expected {}, got '{}'", expected, text_));
  }
  std::string source_, key_, text_;
  bool found_ = false;
};

/// The keys, in visiting order.
class KeyLister {
 public:
  std::vector<std::string> keys;
  template <class... Rest>
  void integer(const char* key, Rest&&...) {
    keys.emplace_back(key);
  }
  template <class... Rest>
  void uint64(const char* key, Rest&&...) {
    keys.emplace_back(key);
  }
  template <class... Rest>
  void number(const char* key, Rest&&...) {
    keys.emplace_back(key);
  }
  template <class... Rest>
  void boolean(const char* key, Rest&&...) {
    keys.emplace_back(key);
  }
  template <class... Rest>
  void text(const char* key, Rest&&...) {
    keys.emplace_back(key);
  }
  template <class... Rest>
  void choice(const char* key, Rest&&...) {
    keys.emplace_back(key);
  }
  template <class... Rest>
  void number_list(const char* key, Rest&&...) {
    keys.emplace_back(key);
  }
};

/// (key, help) of every option, in visiting order.
class HelpLister {
 public:
  std::vector<std::pair<std::string, std::string>> entries;
  void integer(const char* key, int&, const char* help) { entries.emplace_back(key, help); }
  void uint64(const char* key, std::uint64_t&, const char* help) {
    entries.emplace_back(key, help);
  }
  void number(const char* key, double&, const char* help, Infinity = Infinity::kRefused) {
    entries.emplace_back(key, help);
  }
  void boolean(const char* key, bool&, const char* help) { entries.emplace_back(key, help); }
  void text(const char* key, std::string&, const char* help) { entries.emplace_back(key, help); }
  void number_list(const char* key, std::vector<double>&, const char* help) {
    entries.emplace_back(key, help);
  }
  template <class E>
  void choice(const char* key, E&, const Choices<E>&, const char* help) {
    entries.emplace_back(key, help);
  }
};

/// The names of every option of `Options`.
template <class Options>
std::vector<std::string> option_keys() {
  Options scratch;
  KeyLister lister;
  visit_options(lister, scratch);
  return lister.keys;
}

/// Sets option `key` of `o` from `text`. Throws ParseError(`source`, key, ...) when the text does
/// not read as the option's type, or when no option has that name (`what` names the kind of
/// option, e.g. "SLAM option"; the closest key and the known ones are listed).
template <class Options>
void set_from_text(Options& o, const std::string& source, const std::string& what,
                   const std::string& key, const std::string& text) {
  TextSetter setter(source, key, text);
  visit_options(setter, o);
  if (setter.found()) return;
  const std::vector<std::string> known = option_keys<Options>();
  std::string list;
  for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
  throw ParseError(source, key,
                   fmt::format("unknown {}{}; known: {}", what, did_you_mean(key, known), list));
}

/// Splits "key=value"; throws ParseError(`source`, text, ...) without a key or an '='.
std::pair<std::string, std::string> split_assignment(const std::string& source,
                                                     const std::string& assignment);

/// (key, help) of every option, in visiting order.
template <class Options>
std::vector<std::pair<std::string, std::string>> option_help() {
  Options scratch;
  HelpLister lister;
  visit_options(lister, scratch);
  return lister.entries;
}

}  // namespace wifislam::options
