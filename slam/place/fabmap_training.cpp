#include "slam/place/fabmap_training.hpp"

#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/atomic_file.hpp"
#include "core/error.hpp"

namespace wifislam::slam::place {

namespace {
constexpr const char* kHeader = "# wifislam FAB-MAP training v1";
}

std::string FabMapTraining::serialise() const {
  std::string out = std::string(kHeader) + "\nvocabulary " + vocabulary_sha256 + "\n";
  out += tree.serialise();
  out += fmt::format("observations {}\n", observations.size());
  for (const BinaryObservation& o : observations)
    out += fmt::format("{}\n", fmt::join(o.present, " "));
  return out;
}

FabMapTraining FabMapTraining::deserialise(const std::string& text, const std::string& source) {
  std::istringstream in(text);
  std::string line;
  int line_number = 0;
  const auto fail = [&](const std::string& why) {
    throw ParseError(fmt::format("{}:{}", source, line_number), "", why);
  };
  const auto next = [&] {
    ++line_number;
    if (!std::getline(in, line)) fail("truncated");
  };
  next();
  if (line != kHeader) fail("not a wifislam FAB-MAP training file");
  next();
  FabMapTraining t;
  if (line.rfind("vocabulary ", 0) != 0) fail("expected 'vocabulary <sha256>'");
  t.vocabulary_sha256 = line.substr(11);
  // The tree: its header, its size line and one line per word.
  std::string tree_text;
  next();
  tree_text += line + "\n";
  next();
  tree_text += line + "\n";
  const int tree_start = line_number - 1;
  int words = 0;
  std::string key;
  if (!(std::istringstream(line) >> key >> words) || key != "words" || words < 1) {
    fail("expected 'words N'");
  }
  for (int q = 0; q < words; ++q) {
    next();
    tree_text += line + "\n";
  }
  t.tree = ChowLiuTree::deserialise(
      tree_text, source + " (tree from line " + std::to_string(tree_start) + ")");
  next();
  std::size_t count = 0;
  if (!(std::istringstream(line) >> key >> count) || key != "observations") {
    fail("expected 'observations N'");
  }
  for (std::size_t i = 0; i < count; ++i) {
    next();
    BinaryObservation o;
    std::istringstream words_in(line);
    for (int q; words_in >> q;) {
      if (q < 0 || q >= words || (!o.present.empty() && q <= o.present.back())) {
        fail(fmt::format("word {} out of range or out of order", q));
      }
      o.present.push_back(q);
    }
    if (!words_in.eof()) fail("expected word ids");
    t.observations.push_back(std::move(o));
  }
  return t;
}

void FabMapTraining::save(const std::filesystem::path& path) const {
  write_file_atomic(path, serialise());
}

FabMapTraining FabMapTraining::load(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError(path.string() + ": cannot read");
  std::ostringstream text;
  text << in.rdbuf();
  return deserialise(text.str(), path.string());
}

std::filesystem::path shipped_fabmap_training_path() { return WIFISLAM_SHIPPED_FABMAP_TRAINING; }

}  // namespace wifislam::slam::place
