#include "slam/place/chow_liu_tree.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <deque>
#include <sstream>

#include <fmt/format.h>
#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/kruskal_min_spanning_tree.hpp>

#include "core/error.hpp"

namespace wifislam::slam::place {

namespace {

constexpr const char* kHeader =
    "# wifislam Chow-Liu tree v1: word parent P(z=1) P(z=1|zp=1) P(z=1|zp=0)";

/// Which training observations hold each word, one bit per observation.
struct WordColumns {
  std::size_t observations = 0, blocks = 0;
  std::vector<std::vector<std::uint64_t>> bits;  // per word
  std::vector<std::size_t> count;                // observations holding the word

  WordColumns(const std::vector<BinaryObservation>& data, int word_count)
      : observations(data.size()),
        blocks((data.size() + 63) / 64),
        bits(static_cast<std::size_t>(word_count)),
        count(static_cast<std::size_t>(word_count), 0) {
    for (auto& column : bits) column.assign(blocks, 0);
    for (std::size_t i = 0; i < data.size(); ++i) {
      for (int q : data[i].present) {
        if (q < 0 || q >= word_count) {
          throw InvalidInputError(
              fmt::format("Chow-Liu training: word {} outside 0..{}", q, word_count - 1));
        }
        bits[static_cast<std::size_t>(q)][i / 64] |= std::uint64_t{1} << (i % 64);
        ++count[static_cast<std::size_t>(q)];
      }
    }
  }

  std::size_t both(int a, int b) const {
    std::size_t n = 0;
    const auto& x = bits[static_cast<std::size_t>(a)];
    const auto& y = bits[static_cast<std::size_t>(b)];
    for (std::size_t k = 0; k < blocks; ++k)
      n += static_cast<std::size_t>(std::popcount(x[k] & y[k]));
    return n;
  }
  double marginal(int q) const {
    return smoothed_marginal(count[static_cast<std::size_t>(q)], observations);
  }
  /// P(z_a = 1 | z_b = zb), smoothed as openFABMAP's ChowLiuTree::CP.
  double conditional(int a, int b, bool zb) const {
    const std::size_t n_b =
        zb ? count[static_cast<std::size_t>(b)] : observations - count[static_cast<std::size_t>(b)];
    if (n_b == 0) return 0.01;
    const std::size_t n_ab = zb ? both(a, b) : count[static_cast<std::size_t>(a)] - both(a, b);
    return 0.98 * static_cast<double>(n_ab) / static_cast<double>(n_b) + 0.01;
  }
  /// Mutual information of two words: raw joint frequencies against smoothed marginals, each
  /// empty cell contributing nothing (openFABMAP's ChowLiuTree::calcMutInfo).
  double mutual_information(int a, int b) const {
    const double n = static_cast<double>(observations);
    const double n11 = static_cast<double>(both(a, b));
    const double na = static_cast<double>(count[static_cast<std::size_t>(a)]);
    const double nb = static_cast<double>(count[static_cast<std::size_t>(b)]);
    const double pa1 = marginal(a), pb1 = marginal(b);
    const double cells[4][3] = {{(n - na - nb + n11) / n, 1 - pa1, 1 - pb1},
                                {(nb - n11) / n, 1 - pa1, pb1},
                                {(na - n11) / n, pa1, 1 - pb1},
                                {n11 / n, pa1, pb1}};
    double info = 0.0;
    for (const auto& c : cells) {
      if (c[0] > 0) info += c[0] * std::log(c[0] / (c[1] * c[2]));
    }
    return info;
  }
};

/// The kept edges of the maximum spanning forest (Kruskal on negated information).
std::vector<std::pair<int, int>> spanning_forest(const WordColumns& columns, int word_count,
                                                 double lower_info_bound) {
  using Graph =
      boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, boost::no_property,
                            boost::property<boost::edge_weight_t, double>>;
  Graph graph(static_cast<std::size_t>(word_count));
  // A word no training observation holds has no statistics: its information with any word is an
  // artefact of the smoothing, so it gets no edge and stays independent.
  std::vector<int> seen;
  for (int q = 0; q < word_count; ++q) {
    if (columns.count[static_cast<std::size_t>(q)] > 0) seen.push_back(q);
  }
  for (std::size_t i = 0; i < seen.size(); ++i) {
    for (std::size_t j = i + 1; j < seen.size(); ++j) {
      const double info = columns.mutual_information(seen[i], seen[j]);
      if (info >= lower_info_bound) boost::add_edge(seen[i], seen[j], -info, graph);
    }
  }
  std::vector<boost::graph_traits<Graph>::edge_descriptor> tree;
  boost::kruskal_minimum_spanning_tree(graph, std::back_inserter(tree));
  std::vector<std::pair<int, int>> edges;
  for (const auto& e : tree) {
    edges.emplace_back(static_cast<int>(boost::source(e, graph)),
                       static_cast<int>(boost::target(e, graph)));
  }
  return edges;
}

}  // namespace

double smoothed_marginal(std::size_t count, std::size_t total) {
  return total == 0 ? 0.01 : 0.98 * static_cast<double>(count) / static_cast<double>(total) + 0.01;
}

ChowLiuTree learn_chow_liu_tree(const std::vector<BinaryObservation>& observations, int word_count,
                                double lower_info_bound) {
  if (observations.empty()) throw InvalidInputError("Chow-Liu training: no observations");
  const WordColumns columns(observations, word_count);
  std::vector<std::vector<int>> neighbours(static_cast<std::size_t>(word_count));
  for (const auto& [a, b] : spanning_forest(columns, word_count, lower_info_bound)) {
    neighbours[static_cast<std::size_t>(a)].push_back(b);
    neighbours[static_cast<std::size_t>(b)].push_back(a);
  }
  ChowLiuTree tree;
  tree.parent.assign(static_cast<std::size_t>(word_count), -1);
  tree.p_present.resize(static_cast<std::size_t>(word_count));
  tree.p_present_parent_present.resize(static_cast<std::size_t>(word_count));
  tree.p_present_parent_absent.resize(static_cast<std::size_t>(word_count));
  for (int root = 0; root < word_count; ++root) {
    if (tree.parent[static_cast<std::size_t>(root)] >= 0) continue;
    // A root is conditioned on nothing: both conditionals are its marginal (openFABMAP).
    tree.parent[static_cast<std::size_t>(root)] = root;
    std::deque<int> queue = {root};
    while (!queue.empty()) {
      const int q = queue.front();
      queue.pop_front();
      const auto u = static_cast<std::size_t>(q);
      const int p = tree.parent[u];
      tree.p_present[u] = columns.marginal(q);
      tree.p_present_parent_present[u] =
          p == q ? tree.p_present[u] : columns.conditional(q, p, true);
      tree.p_present_parent_absent[u] =
          p == q ? tree.p_present[u] : columns.conditional(q, p, false);
      std::vector<int> children = neighbours[u];
      std::sort(children.begin(), children.end());
      for (int c : children) {
        if (tree.parent[static_cast<std::size_t>(c)] >= 0) continue;
        tree.parent[static_cast<std::size_t>(c)] = q;
        queue.push_back(c);
      }
    }
  }
  return tree;
}

ChowLiuTree independent_words(const std::vector<BinaryObservation>& observations, int word_count) {
  ChowLiuTree tree;
  std::vector<std::size_t> count(static_cast<std::size_t>(word_count), 0);
  for (const BinaryObservation& o : observations) {
    for (int q : o.present) ++count.at(static_cast<std::size_t>(q));
  }
  std::vector<double> marginals;
  for (std::size_t c : count) marginals.push_back(smoothed_marginal(c, observations.size()));
  tree.append_independent(marginals);
  return tree;
}

void ChowLiuTree::append_independent(const std::vector<double>& marginals) {
  for (double p : marginals) {
    parent.push_back(word_count());
    p_present.push_back(p);
    p_present_parent_present.push_back(p);
    p_present_parent_absent.push_back(p);
  }
}

std::string ChowLiuTree::serialise() const {
  std::string out = std::string(kHeader) + "\n" + fmt::format("words {}\n", word_count());
  for (int q = 0; q < word_count(); ++q) {
    const auto u = static_cast<std::size_t>(q);
    out += fmt::format("{} {} {:.17g} {:.17g} {:.17g}\n", q, parent[u], p_present[u],
                       p_present_parent_present[u], p_present_parent_absent[u]);
  }
  return out;
}

ChowLiuTree ChowLiuTree::deserialise(const std::string& text, const std::string& source) {
  std::istringstream in(text);
  std::string line;
  int line_number = 1;
  const auto fail = [&](const std::string& why) {
    throw ParseError(fmt::format("{}:{}", source, line_number), "", why);
  };
  if (!std::getline(in, line) || line != kHeader) fail("not a wifislam Chow-Liu tree file");
  ++line_number;
  int words = -1;
  std::string key;
  if (!std::getline(in, line) || !(std::istringstream(line) >> key >> words) || key != "words" ||
      words < 1) {
    fail("expected 'words N'");
  }
  ChowLiuTree tree;
  for (int q = 0; q < words; ++q) {
    ++line_number;
    int index = -1, parent = -1;
    double p = 0, p1 = 0, p0 = 0;
    if (!std::getline(in, line) ||
        !(std::istringstream(line) >> index >> parent >> p >> p1 >> p0)) {
      fail("expected 'word parent p p|1 p|0'");
    }
    const auto probability = [](double x) { return x > 0.0 && x < 1.0; };
    if (index != q || parent < 0 || parent >= words || !probability(p) || !probability(p1) ||
        !probability(p0)) {
      fail(fmt::format("word {}: index, parent or probabilities out of range", q));
    }
    tree.parent.push_back(parent);
    tree.p_present.push_back(p);
    tree.p_present_parent_present.push_back(p1);
    tree.p_present_parent_absent.push_back(p0);
  }
  // A forest: every word's chain of parents ends at a root (a word that is its own parent). A
  // cycle would make the product of conditionals no distribution at all. Each chain is walked
  // once: `state` 1 marks the chain being walked, 2 a word known to reach a root.
  std::vector<char> state(static_cast<std::size_t>(words), 0);
  for (int q = 0; q < words; ++q) {
    std::vector<int> chain;
    int u = q;
    while (state[static_cast<std::size_t>(u)] == 0) {
      state[static_cast<std::size_t>(u)] = 1;
      chain.push_back(u);
      const int up = tree.parent[static_cast<std::size_t>(u)];
      if (up == u) break;
      u = up;
    }
    if (state[static_cast<std::size_t>(u)] == 1 && tree.parent[static_cast<std::size_t>(u)] != u) {
      line_number = 3 + q;
      fail(
          fmt::format("word {}: its chain of parents returns to word {} without reaching a root "
                      "(a word that is its own parent): the tree has a cycle",
                      q, u));
    }
    for (const int w : chain) state[static_cast<std::size_t>(w)] = 2;
  }
  return tree;
}

}  // namespace wifislam::slam::place
