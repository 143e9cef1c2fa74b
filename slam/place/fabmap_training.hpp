#pragma once
// What FAB-MAP learns before it sees a map (openFABMAP's training stage), in one file next to the
// vocabulary it was made with: the Chow-Liu tree over the vocabulary's words and the training
// observations the new-place term samples. Made by `wifislam vocab fabmap` from frames of scenes
// that are never evaluated (the vocabulary's training scenes), deterministically.
//
// File (text):
//   # wifislam FAB-MAP training v1
//   vocabulary <sha256 of the vocabulary file>
//   <the Chow-Liu tree, chow_liu_tree.hpp's text form>
//   observations N
//   <one line per observation: its present word ids, ascending, space-separated>

#include <filesystem>
#include <string>
#include <vector>

#include "slam/place/binary_observation.hpp"
#include "slam/place/chow_liu_tree.hpp"

namespace wifislam::slam::place {

struct FabMapTraining {
  std::string vocabulary_sha256;
  ChowLiuTree tree;
  std::vector<BinaryObservation> observations;

  std::string serialise() const;
  static FabMapTraining deserialise(const std::string& text, const std::string& source);
  void save(const std::filesystem::path& path) const;  // atomic
  static FabMapTraining load(const std::filesystem::path& path);
};

/// The shipped training file for the shipped vocabulary (assets/vocabulary/).
std::filesystem::path shipped_fabmap_training_path();

}  // namespace wifislam::slam::place
