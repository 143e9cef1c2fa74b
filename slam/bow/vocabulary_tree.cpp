#include "slam/bow/vocabulary_tree.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <system_error>

#include <fmt/format.h>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/rng.hpp"
#include "slam/match/packed_descriptor.hpp"

namespace wifislam::slam::bow {

namespace {

constexpr char kMagic[8] = {'W', 'S', 'L', 'A', 'M', 'V', 'O', 'C'};
constexpr std::uint32_t kFormatVersion = 1;
constexpr std::size_t kHeaderBytes = 8 + 6 * 4 + 8;
constexpr std::size_t kNodeBytes = 4 + 32 + 8 + 4;
constexpr std::size_t kChecksumBytes = 64;

void check_descriptors(const cv::Mat& m) {
  if (!m.empty() && (m.type() != CV_8U || m.cols != 32)) {
    throw std::invalid_argument("vocabulary: descriptors must be 32-byte ORB rows (CV_8U)");
  }
}

/// Bitwise majority of the members (DBoW2 FORB::meanValue: a bit is set when at least half of
/// the members have it).
match::PackedDescriptor majority(const std::vector<match::PackedDescriptor>& all,
                                 const std::vector<std::uint32_t>& members) {
  std::array<int, 256> counts{};
  for (std::uint32_t m : members) {
    const match::PackedDescriptor& d = all[m];
    for (int w = 0; w < 4; ++w)
      for (int b = 0; b < 64; ++b) counts[static_cast<std::size_t>(w * 64 + b)] += (d[w] >> b) & 1u;
  }
  match::PackedDescriptor out{};
  const int n = static_cast<int>(members.size());
  for (int i = 0; i < 256; ++i)
    if (2 * counts[static_cast<std::size_t>(i)] >= n) out[i / 64] |= std::uint64_t{1} << (i % 64);
  return out;
}

/// Index of the nearest of `centres` (ties to the lower index).
std::size_t nearest(const match::PackedDescriptor& d,
                    const std::vector<match::PackedDescriptor>& centres) {
  std::size_t best = 0;
  int best_distance = std::numeric_limits<int>::max();
  for (std::size_t c = 0; c < centres.size(); ++c) {
    const int distance = match::hamming_distance(d, centres[c]);
    if (distance < best_distance) best_distance = distance, best = c;
  }
  return best;
}

/// k-means++ seeding (Arthur & Vassilvitskii 2007, as DBoW2's initiateClustersKMpp): the first
/// centre uniformly, each next one with probability proportional to the squared distance to the
/// nearest centre chosen so far. Fewer than k centres when the members hold fewer distinct ones.
std::vector<match::PackedDescriptor> seed_centres(const std::vector<match::PackedDescriptor>& all,
                                                  const std::vector<std::uint32_t>& members, int k,
                                                  Rng& rng) {
  std::vector<match::PackedDescriptor> centres;
  const auto n = static_cast<std::int64_t>(members.size());
  centres.push_back(all[members[static_cast<std::size_t>(rng.uniform_int(0, n - 1))]]);
  std::vector<double> d2(members.size());
  for (std::size_t i = 0; i < members.size(); ++i) {
    const double d = match::hamming_distance(all[members[i]], centres[0]);
    d2[i] = d * d;
  }
  while (static_cast<int>(centres.size()) < k) {
    double total = 0.0;
    for (double v : d2) total += v;
    if (total <= 0.0) break;  // every member equals a centre
    double cut = rng.uniform() * total;
    std::size_t pick = 0;
    for (; pick + 1 < d2.size(); ++pick) {
      if (cut < d2[pick]) break;
      cut -= d2[pick];
    }
    while (d2[pick] <= 0.0) --pick;  // rounding at the end of the sum: the last positive one
    centres.push_back(all[members[pick]]);
    for (std::size_t i = 0; i < members.size(); ++i) {
      const double d = match::hamming_distance(all[members[i]], centres.back());
      d2[i] = std::min(d2[i], d * d);
    }
  }
  return centres;
}

// Little-endian field writers and readers.
template <typename T>
void put(std::string& out, T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

template <typename T>
T get(std::string_view bytes, std::size_t& at) {
  T value;
  std::memcpy(&value, bytes.data() + at, sizeof(T));
  at += sizeof(T);
  return value;
}

}  // namespace

VocabularyTree VocabularyTree::train(const std::vector<cv::Mat>& images,
                                     const VocabularyOptions& options) {
  if (options.branching < 2 || options.branching > 64 || options.depth < 1 || options.depth > 10 ||
      options.max_iterations < 1) {
    throw std::invalid_argument(
        fmt::format("vocabulary: branching {} (2-64), depth {} (1-10), max_iterations {} (>= 1)",
                    options.branching, options.depth, options.max_iterations));
  }
  VocabularyTree tree;
  tree.branching_ = options.branching;
  tree.depth_ = options.depth;
  tree.training_images_ = static_cast<std::uint32_t>(images.size());

  std::vector<match::PackedDescriptor> all;
  std::vector<std::uint32_t> image_of;
  for (std::size_t i = 0; i < images.size(); ++i) {
    check_descriptors(images[i]);
    for (int r = 0; r < images[i].rows; ++r) {
      all.push_back(match::packed_descriptor(images[i], r));
      image_of.push_back(static_cast<std::uint32_t>(i));
    }
  }
  tree.training_descriptors_ = all.size();
  tree.nodes_.push_back(Node{});
  if (all.empty()) return tree;

  // Depth first from the root; each node's members are the descriptors that reached it.
  struct Pending {
    NodeId node;
    std::vector<std::uint32_t> members;
  };
  std::vector<Pending> stack;
  std::vector<std::uint32_t> everything(all.size());
  for (std::size_t i = 0; i < all.size(); ++i) everything[i] = static_cast<std::uint32_t>(i);
  stack.push_back({0, std::move(everything)});
  std::map<NodeId, std::vector<std::uint32_t>> leaf_members;
  while (!stack.empty()) {
    Pending p = std::move(stack.back());
    stack.pop_back();
    const int level = tree.nodes_[p.node].level;
    std::vector<std::vector<std::uint32_t>> groups;
    std::vector<match::PackedDescriptor> centres;
    if (static_cast<int>(p.members.size()) <= options.branching) {
      for (std::uint32_t m : p.members) {
        groups.push_back({m});
        centres.push_back(all[m]);
      }
    } else {
      Rng rng = Rng::stream(options.seed, fmt::format("bow/kmeans++/node{}", p.node));
      centres = seed_centres(all, p.members, options.branching, rng);
      std::vector<std::size_t> assignment(p.members.size(), centres.size());
      for (int iteration = 0; iteration < options.max_iterations; ++iteration) {
        bool changed = false;
        for (std::size_t i = 0; i < p.members.size(); ++i) {
          const std::size_t c = nearest(all[p.members[i]], centres);
          changed |= c != assignment[i];
          assignment[i] = c;
        }
        groups.assign(centres.size(), {});
        for (std::size_t i = 0; i < p.members.size(); ++i)
          groups[assignment[i]].push_back(p.members[i]);
        if (!changed) break;
        for (std::size_t c = 0; c < centres.size(); ++c)
          if (!groups[c].empty()) centres[c] = majority(all, groups[c]);
      }
    }
    // Children in centre order; pushed in reverse so the first child is expanded first.
    std::vector<Pending> children;
    for (std::size_t c = 0; c < groups.size(); ++c) {
      if (groups[c].empty()) continue;
      Node child;
      child.parent = p.node;
      child.descriptor = centres[c];
      child.level = level + 1;
      const auto id = static_cast<NodeId>(tree.nodes_.size());
      tree.nodes_.push_back(child);
      tree.nodes_[p.node].children.push_back(id);
      if (child.level < options.depth && groups[c].size() > 1) {
        children.push_back({id, std::move(groups[c])});
      } else {
        leaf_members[id] = std::move(groups[c]);
      }
    }
    for (auto it = children.rbegin(); it != children.rend(); ++it) stack.push_back(std::move(*it));
  }

  // Words in node order, with idf = ln(N / images holding the word).
  for (NodeId id = 0; id < tree.nodes_.size(); ++id) {
    Node& node = tree.nodes_[id];
    if (id == 0 || !node.children.empty()) continue;
    std::set<std::uint32_t> holders;
    for (std::uint32_t m : leaf_members.at(id)) holders.insert(image_of[m]);
    node.word = static_cast<WordId>(tree.word_nodes_.size());
    node.idf = std::log(static_cast<double>(images.size()) / static_cast<double>(holders.size()));
    tree.word_nodes_.push_back(id);
  }
  return tree;
}

NodeId VocabularyTree::descend(const match::PackedDescriptor& d, int stop_level,
                               NodeId* at_level) const {
  NodeId id = 0;
  while (!nodes_[id].children.empty()) {
    NodeId best = nodes_[id].children.front();
    int best_distance = std::numeric_limits<int>::max();
    for (NodeId child : nodes_[id].children) {
      const int distance = match::hamming_distance(d, nodes_[child].descriptor);
      if (distance < best_distance) best_distance = distance, best = child;
    }
    id = best;
    if (at_level && nodes_[id].level <= stop_level) *at_level = id;
  }
  return id;
}

WordId VocabularyTree::word_of(const match::PackedDescriptor& descriptor) const {
  if (word_nodes_.empty()) throw std::logic_error("vocabulary: no words (trained on nothing)");
  return nodes_[descend(descriptor, 0, nullptr)].word;
}

BowVector VocabularyTree::transform(const cv::Mat& descriptors, FeatureVector* direct_index,
                                    int levels_up) const {
  check_descriptors(descriptors);
  BowVector v;
  if (direct_index) direct_index->clear();
  if (word_nodes_.empty()) return v;
  const int direct_level = std::max(1, depth_ - levels_up);
  for (int r = 0; r < descriptors.rows; ++r) {
    NodeId at_level = 0;
    const NodeId leaf = descend(match::packed_descriptor(descriptors, r), direct_level, &at_level);
    const Node& node = nodes_[leaf];
    v[node.word] += node.idf;
    if (direct_index) (*direct_index)[at_level].push_back(r);
  }
  // A word every training image holds has idf 0 and carries no information, as in DBoW2.
  for (auto it = v.begin(); it != v.end();) it = it->second > 0.0 ? std::next(it) : v.erase(it);
  l1_normalise(v);
  return v;
}

std::string VocabularyTree::serialise() const {
  std::string out(kMagic, sizeof kMagic);
  put<std::uint32_t>(out, kFormatVersion);
  put<std::uint32_t>(out, static_cast<std::uint32_t>(branching_));
  put<std::uint32_t>(out, static_cast<std::uint32_t>(depth_));
  put<std::uint32_t>(out, static_cast<std::uint32_t>(nodes_.size()));
  put<std::uint32_t>(out, static_cast<std::uint32_t>(word_nodes_.size()));
  put<std::uint32_t>(out, training_images_);
  put<std::uint64_t>(out, training_descriptors_);
  for (const Node& n : nodes_) {
    put<std::uint32_t>(out, n.parent);
    for (std::uint64_t w : n.descriptor) put<std::uint64_t>(out, w);
    put<double>(out, n.idf);
    put<std::uint32_t>(out, n.word);
  }
  out += sha256_hex(out);
  return out;
}

VocabularyTree VocabularyTree::deserialise(std::string_view bytes, const std::string& source) {
  const auto bad = [&](const std::string& what) {
    return InvalidInputError(fmt::format("{}: not a usable wifislam vocabulary: {}", source, what));
  };
  if (bytes.size() < kHeaderBytes + kChecksumBytes)
    throw bad("truncated (shorter than its header)");
  if (std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0) throw bad("wrong magic bytes");
  std::size_t at = sizeof kMagic;
  const auto version = get<std::uint32_t>(bytes, at);
  if (version != kFormatVersion) {
    throw bad(
        fmt::format("format version {}; this build reads version {}", version, kFormatVersion));
  }
  VocabularyTree tree;
  const auto branching = get<std::uint32_t>(bytes, at);
  const auto depth = get<std::uint32_t>(bytes, at);
  const auto nodes = get<std::uint32_t>(bytes, at);
  const auto words = get<std::uint32_t>(bytes, at);
  tree.training_images_ = get<std::uint32_t>(bytes, at);
  tree.training_descriptors_ = get<std::uint64_t>(bytes, at);
  if (branching < 2 || branching > 64 || depth < 1 || depth > 10 || nodes < 1 || words >= nodes) {
    throw bad(fmt::format("header out of range (branching {}, depth {}, nodes {}, words {})",
                          branching, depth, nodes, words));
  }
  const std::size_t expected =
      kHeaderBytes + static_cast<std::size_t>(nodes) * kNodeBytes + kChecksumBytes;
  if (bytes.size() != expected) {
    throw bad(fmt::format("{} bytes where its header promises {} ({})", bytes.size(), expected,
                          bytes.size() < expected ? "truncated" : "trailing data"));
  }
  const std::string_view body = bytes.substr(0, expected - kChecksumBytes);
  if (sha256_hex(body) != bytes.substr(expected - kChecksumBytes)) {
    throw bad("checksum mismatch (the file is corrupt)");
  }
  tree.branching_ = static_cast<int>(branching);
  tree.depth_ = static_cast<int>(depth);
  tree.nodes_.resize(nodes);
  tree.word_nodes_.assign(words, kNone);
  for (std::uint32_t i = 0; i < nodes; ++i) {
    Node& n = tree.nodes_[i];
    n.parent = get<std::uint32_t>(bytes, at);
    for (std::uint64_t& w : n.descriptor) w = get<std::uint64_t>(bytes, at);
    n.idf = get<double>(bytes, at);
    n.word = get<std::uint32_t>(bytes, at);
    if ((i == 0) != (n.parent == kNone) || (i > 0 && n.parent >= i)) {
      throw bad(fmt::format("node {} has parent {}", i, n.parent));
    }
    if (i > 0) {
      Node& parent = tree.nodes_[n.parent];
      n.level = parent.level + 1;
      if (n.level > tree.depth_ || parent.word != kNone ||
          static_cast<int>(parent.children.size()) >= tree.branching_) {
        throw bad(fmt::format("node {} does not fit the tree (level {}, parent {})", i, n.level,
                              n.parent));
      }
      parent.children.push_back(i);
    }
    if (n.word != kNone) {
      if (n.word >= words || tree.word_nodes_[n.word] != kNone || !std::isfinite(n.idf) ||
          n.idf < 0.0) {
        throw bad(fmt::format("node {}: word {} with idf {}", i, n.word, n.idf));
      }
      tree.word_nodes_[n.word] = i;
    }
  }
  for (WordId w = 0; w < words; ++w) {
    if (tree.word_nodes_[w] == kNone) throw bad(fmt::format("word {} has no node", w));
  }
  for (std::uint32_t i = 0; i < nodes; ++i) {
    const Node& n = tree.nodes_[i];
    if (i > 0 && n.children.empty() != (n.word != kNone)) {
      throw bad(fmt::format("node {}: a leaf must be a word and a word a leaf", i));
    }
  }
  return tree;
}

void VocabularyTree::save(const std::filesystem::path& path) const {
  write_file_atomic(path, serialise());
}

VocabularyTree VocabularyTree::load(const std::filesystem::path& path) {
  // A folder opens as an empty stream on Linux and would read as a "truncated" vocabulary; a
  // device (/dev/zero) would be read without end.
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status)) {
    throw InvalidInputError(
        fmt::format("{}: is {}, not a vocabulary file", path.string(),
                    std::filesystem::is_directory(status) ? "a folder" : "not a regular file"));
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError(fmt::format("{}: cannot open the vocabulary", path.string()));
  std::stringstream buffer;
  buffer << in.rdbuf();
  return deserialise(buffer.str(), path.string());
}

}  // namespace wifislam::slam::bow
