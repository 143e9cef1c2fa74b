// The recording a dataset holds (core/dataset_recording.hpp): read from manifest.json's
// parameters as the generator writes them, kept in run.json and read back, and refused in
// run.json when malformed.

#include "core/dataset_recording.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"

namespace wifislam {
namespace {

DatasetManifest manifest_with(const std::string& parameters_json) {
  DatasetManifest m;
  m.parameters_json = parameters_json;
  return m;
}

TEST(DatasetRecording, IsReadFromTheManifestsParametersAndSurvivesRunJson) {
  const DatasetManifest m =
      manifest_with(R"({"scene": "c_hall", "seed": 1001, "session": 2, "fps": 3.0,)"
                    R"( "time_origin_s": 1700000000, "max_frames": -1, "images": true})");
  const std::optional<DatasetRecording> r = recording_of(m);
  ASSERT_TRUE(r.has_value());
  EXPECT_EQ(r->scene, "c_hall");
  EXPECT_EQ(r->seed, 1001u);
  EXPECT_EQ(r->session, std::optional<std::uint64_t>(2));
  EXPECT_EQ(r->fps, 3.0);
  EXPECT_EQ(r->time_origin_s, 1700000000u);
  // run.json keeps it and gives it back unchanged, through text as a file would.
  const nlohmann::json back = nlohmann::json::parse(recording_json(*r).dump());
  EXPECT_EQ(recording_from_json(back, "run.json", "input.recording"), *r);
  EXPECT_EQ(describe(*r), "scene c_hall, seed 1001, session 2, 3 fps, time origin 1700000000 s");
}

TEST(DatasetRecording, EveryFieldTellsRecordingsApart) {
  DatasetRecording a{"c_hall", 1001, std::nullopt, 3.0, 1700000000};
  for (int field = 0; field < 5; ++field) {
    DatasetRecording b = a;
    if (field == 0) b.scene = "b_hall";
    if (field == 1) b.seed = 1002;
    if (field == 2) b.session = 1;
    if (field == 3) b.fps = 2.0;
    if (field == 4) b.time_origin_s = 1700000001;
    EXPECT_FALSE(a == b) << "field " << field;
  }
}

TEST(DatasetRecording, AManifestThatNamesNoRecordingHasNone) {
  EXPECT_FALSE(recording_of(manifest_with("{}")).has_value());
  EXPECT_FALSE(recording_of(manifest_with(R"({"scene": "x", "seed": 1, "fps": 3.0})")).has_value());
  EXPECT_FALSE(
      recording_of(manifest_with(R"({"scene": "x", "seed": -1, "fps": 3, "time_origin_s": 0})"))
          .has_value());
  EXPECT_FALSE(recording_of(manifest_with("not json")).has_value());
}

TEST(DatasetRecording, AMalformedRecordingInRunJsonIsLocated) {
  const auto message = [](const std::string& text) {
    try {
      recording_from_json(nlohmann::json::parse(text), "r/run.json", "input.recording");
    } catch (const ParseError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(message(R"({"scene": "x", "seed": "1", "fps": 3, "time_origin_s": 0})")
                .find("input.recording.seed"),
            std::string::npos);
  EXPECT_NE(message(R"({"seed": 1, "fps": 3, "time_origin_s": 0})").find("input.recording.scene"),
            std::string::npos);
  EXPECT_NE(message("[1, 2]").find("input.recording"), std::string::npos);
  EXPECT_NE(message(R"({"scene": "x", "seed": 1, "session": -2, "fps": 3, "time_origin_s": 0})")
                .find("input.recording.session"),
            std::string::npos);
}

}  // namespace
}  // namespace wifislam
