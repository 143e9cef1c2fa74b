// The one set of rules for options given as text (core/option_table.hpp), on a small options
// struct of every kind, and the same rules through the SLAM's and the evaluation's own tables.
#include "core/option_table_json.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <vector>

namespace wifislam::options {
namespace {

enum class Colour { kRed, kBlue };

struct ToyOptions {
  int count = 3;
  std::uint64_t seed = 7;
  double size_m = 1.5;
  double budget_ms = std::numeric_limits<double>::infinity();
  bool enabled = false;
  std::string name = "toy";
  Colour colour = Colour::kRed;
  std::vector<double> stages = {449.2, 89.84, 22.46};
};

template <class V>
void visit_options(V& v, ToyOptions& o) {
  v.integer("count", o.count, "how many");
  v.uint64("seed", o.seed, "draws");
  v.number("size_m", o.size_m, "how big (m)");
  v.number("budget_ms", o.budget_ms, "time budget (ms); inf = off", Infinity::kAllowed);
  v.boolean("enabled", o.enabled, "on or off");
  v.text("name", o.name, "what it is called");
  v.choice("colour", o.colour, Choices<Colour>{{Colour::kRed, "red"}, {Colour::kBlue, "blue"}},
           "which colour");
  v.number_list("stages", o.stages, "thresholds in order; none = no stage");
}

std::string error_of(ToyOptions& o, const std::string& key, const std::string& text) {
  try {
    set_from_text(o, "--set", "toy option", key, text);
  } catch (const ParseError& e) {
    return e.what();
  }
  return "";
}

TEST(OptionTable, BooleansAreTrueFalseOneZeroOnOff) {
  ToyOptions o;
  for (const char* yes : {"true", "1", "on"}) {
    o.enabled = false;
    set_from_text(o, "--set", "toy option", "enabled", yes);
    EXPECT_TRUE(o.enabled) << yes;
  }
  for (const char* no : {"false", "0", "off"}) {
    o.enabled = true;
    set_from_text(o, "--set", "toy option", "enabled", no);
    EXPECT_FALSE(o.enabled) << no;
  }
  for (const char* bad : {"yes", "True", "2", ""}) {
    EXPECT_NE(error_of(o, "enabled", bad).find("expected true or false"), std::string::npos) << bad;
  }
}

TEST(OptionTable, IntegersAreWholeNumbersAndNumbersAreFinite) {
  ToyOptions o;
  set_from_text(o, "--set", "toy option", "count", "-4");
  EXPECT_EQ(o.count, -4);
  for (const char* bad : {"1.5", "8.0", "1e2", "", "4x", "99999999999"}) {
    EXPECT_NE(error_of(o, "count", bad).find("expected an integer"), std::string::npos) << bad;
  }
  EXPECT_EQ(o.count, -4);  // a refused value changes nothing
  // A whole number too large for the field is told the range, not that it is no integer.
  EXPECT_NE(error_of(o, "count", "99999999999").find("from -2147483648 to 2147483647"),
            std::string::npos);
  EXPECT_NE(error_of(o, "seed", "-1").find("non-negative integer up to 18446744073709551615"),
            std::string::npos);
  set_from_text(o, "--set", "toy option", "size_m", "2.5e-1");
  EXPECT_DOUBLE_EQ(o.size_m, 0.25);
  for (const char* bad : {"inf", "nan", "-inf", "abc", ""}) {
    EXPECT_NE(error_of(o, "size_m", bad).find("expected a finite number"), std::string::npos)
        << bad;
  }
  set_from_text(o, "--set", "toy option", "budget_ms", "70");
  EXPECT_DOUBLE_EQ(o.budget_ms, 70.0);
  set_from_text(o, "--set", "toy option", "budget_ms", "inf");
  EXPECT_TRUE(std::isinf(o.budget_ms));
}

TEST(OptionTable, ChoicesByNameAndUnknownKeysNameTheClosest) {
  ToyOptions o;
  set_from_text(o, "--set", "toy option", "colour", "blue");
  EXPECT_EQ(o.colour, Colour::kBlue);
  EXPECT_NE(error_of(o, "colour", "green").find("one of red, blue"), std::string::npos);
  const std::string unknown = error_of(o, "sise_m", "2");
  EXPECT_NE(unknown.find("unknown toy option; did you mean 'size_m'?"), std::string::npos)
      << unknown;
  EXPECT_NE(unknown.find("known: count, seed, size_m"), std::string::npos) << unknown;
}

TEST(OptionTable, NumberListsAreParsedOnceAndReadBackAsTheyWereWritten) {
  ToyOptions o;
  set_from_text(o, "--set", "toy option", "stages", " 30, 10 ,2.5");
  EXPECT_EQ(o.stages, (std::vector<double>{30.0, 10.0, 2.5}));
  set_from_text(o, "--set", "toy option", "stages", "none");
  EXPECT_TRUE(o.stages.empty());
  EXPECT_EQ(to_json<nlohmann::ordered_json>(o).at("stages"), "none");
  set_from_text(o, "--set", "toy option", "stages", "7");
  EXPECT_EQ(o.stages, (std::vector<double>{7.0}));
  // JSON's text is the text that sets it again: a run.json value can go back to --set.
  ToyOptions again;
  set_from_text(again, "--set", "toy option", "stages",
                to_json<nlohmann::ordered_json>(ToyOptions{}).at("stages").get<std::string>());
  EXPECT_EQ(again.stages, ToyOptions{}.stages);
  for (const char* bad : {"5,,1", "", "1e999", "inf", "5;1", "x", "5,"}) {
    ToyOptions kept;
    const std::string error = error_of(kept, "stages", bad);
    EXPECT_NE(error.find("expected numbers separated by commas, or none"), std::string::npos)
        << bad << ": " << error;
    EXPECT_EQ(kept.stages, ToyOptions{}.stages) << "a refused list leaves the option as it was";
  }
}

TEST(OptionTable, JsonAndReferenceReadBack) {
  ToyOptions o;
  const nlohmann::ordered_json j = to_json<nlohmann::ordered_json>(o);
  EXPECT_EQ(j.dump(),
            R"({"count":3,"seed":7,"size_m":1.5,"budget_ms":"inf","enabled":false,"name":"toy",)"
            R"("colour":"red","stages":"449.2,89.84,22.46"})");
  const std::string reference = options::reference<ToyOptions>();
  EXPECT_NE(reference.find("  budget_ms=inf\n      time budget (ms); inf = off\n"),
            std::string::npos)
      << reference;
  EXPECT_EQ(option_keys<ToyOptions>().size(), 8u);
  EXPECT_THROW(split_assignment("--set", "count"), ParseError);
  EXPECT_THROW(split_assignment("--set", "=3"), ParseError);
  EXPECT_EQ(split_assignment("--set", "name=a=b").second, "a=b");
}

}  // namespace
}  // namespace wifislam::options
