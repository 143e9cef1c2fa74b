#pragma once
// The vocabulary shipped in assets/vocabulary/orb_k10_l4.bin (its README says how it was made),
// compiled into the binary so the ORB-SLAM-style front end works from any folder and a run never
// depends on where the source tree is. Parsed (and its checksum checked) once per process.

#include <memory>
#include <string>
#include <string_view>

#include "slam/bow/vocabulary_tree.hpp"

namespace wifislam::slam::bow {

/// The shipped file's bytes.
std::string_view shipped_vocabulary_bytes();
/// The name runs record for it.
inline constexpr const char* kShippedVocabularyName = "orb_k10_l4 (shipped)";

/// The vocabulary at `path`, or the shipped one for an empty path. Loaded once per path per
/// process and shared (a vocabulary is immutable); InvalidInputError for a bad file.
std::shared_ptr<const VocabularyTree> load_vocabulary(const std::string& path);

/// SHA-256 (hex) of a vocabulary file's contents, as its trailer records it.
std::string vocabulary_checksum(const std::string& path);

}  // namespace wifislam::slam::bow
