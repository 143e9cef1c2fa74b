// FAB-MAP's parts (slam/place/): the Chow-Liu learner recovers the tree a sample was drawn from;
// the observation likelihood of a three-word example equals the value worked out by hand, with
// and without the tree; FabMap2's inverted-index likelihoods equal the direct sum up to the
// query's constant; the new-place sample is seeded.
#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "core/rng.hpp"
#include "slam/place/chow_liu_tree.hpp"
#include "slam/place/fabmap.hpp"

namespace wifislam::slam::place {
namespace {

/// Observations drawn from a tree-shaped distribution: each word present with one probability
/// when its parent is present and another when it is absent.
std::vector<BinaryObservation> sample_tree(const std::vector<int>& parent, std::size_t count,
                                           std::uint64_t seed) {
  Rng rng = Rng::stream(seed, "test/chow_liu_samples");
  std::vector<BinaryObservation> out(count);
  for (BinaryObservation& o : out) {
    std::vector<bool> z(parent.size());
    for (std::size_t q = 0; q < parent.size(); ++q) {  // parents come before children
      const bool root = parent[q] == static_cast<int>(q);
      const double p = root ? 0.5 : (z[static_cast<std::size_t>(parent[q])] ? 0.85 : 0.1);
      z[q] = rng.bernoulli(p);
      if (z[q]) o.present.push_back(static_cast<int>(q));
    }
  }
  return out;
}

std::set<std::pair<int, int>> edges_of(const std::vector<int>& parent) {
  std::set<std::pair<int, int>> out;
  for (std::size_t q = 0; q < parent.size(); ++q) {
    const int p = parent[q];
    if (p != static_cast<int>(q)) out.insert({std::min<int>(p, q), std::max<int>(p, q)});
  }
  return out;
}

TEST(ChowLiuTree, RecoversTheTreeItsSampleWasDrawnFrom) {
  const std::vector<int> truth = {0, 0, 0, 1, 1, 2, 2, 3, 5, 6};
  const ChowLiuTree learned = learn_chow_liu_tree(sample_tree(truth, 20000, 7), 10);
  EXPECT_EQ(edges_of(learned.parent), edges_of(truth));
  // Rooted at word 0 (the lowest), so word 3's parent is word 1: 0.85 / 0.1 in the sample,
  // smoothed 0.98 f + 0.01.
  ASSERT_EQ(learned.parent[3], 1);
  EXPECT_NEAR(learned.p_present_parent_present[3], 0.98 * 0.85 + 0.01, 0.02);
  EXPECT_NEAR(learned.p_present_parent_absent[3], 0.98 * 0.1 + 0.01, 0.02);
  // Exactly one root, and the file form reads back to the same tree.
  EXPECT_EQ(std::count_if(learned.parent.begin(), learned.parent.end(),
                          [&, i = 0](int p) mutable { return p == i++; }),
            1);
  const ChowLiuTree back = ChowLiuTree::deserialise(learned.serialise(), "test");
  EXPECT_EQ(back.serialise(), learned.serialise());
}

// A file whose parents form a cycle (0 -> 1 -> 2 -> 1) is no tree: refused at the first word
// whose chain loops, whatever leads into the loop; a chain into a root is accepted.
TEST(ChowLiuTree, AFileWhoseParentsFormACycleIsRefused) {
  const auto file = [](const std::vector<int>& parent) {
    const ChowLiuTree learned = learn_chow_liu_tree(sample_tree({0, 0, 1}, 2000, 5), 3);
    std::string text = learned.serialise();
    ChowLiuTree edited = ChowLiuTree::deserialise(text, "test");
    edited.parent = parent;
    return edited.serialise();
  };
  EXPECT_NO_THROW(ChowLiuTree::deserialise(file({0, 0, 1}), "test"));
  EXPECT_NO_THROW(ChowLiuTree::deserialise(file({0, 1, 2}), "test"));
  for (const std::vector<int>& cyclic :
       {std::vector<int>{1, 0, 2}, std::vector<int>{0, 2, 1}, std::vector<int>{1, 2, 0}}) {
    try {
      ChowLiuTree::deserialise(file(cyclic), "tree.txt");
      ADD_FAILURE() << "accepted parents " << cyclic[0] << cyclic[1] << cyclic[2];
    } catch (const ParseError& e) {
      EXPECT_NE(std::string(e.what()).find("the tree has a cycle"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("tree.txt:"), std::string::npos) << e.what();
    }
  }
}

TEST(ChowLiuTree, UnrelatedWordsStayIndependent) {
  // Two independent words: their information is below LowerInfoBound, so no edge.
  std::vector<BinaryObservation> data;
  Rng rng = Rng::stream(3, "test/independent");
  for (int i = 0; i < 20000; ++i) {
    BinaryObservation o;
    if (rng.bernoulli(0.5)) o.present.push_back(0);
    if (rng.bernoulli(0.3)) o.present.push_back(1);
    data.push_back(o);
  }
  const ChowLiuTree tree = learn_chow_liu_tree(data, 3);  // word 2 never seen
  EXPECT_EQ(tree.parent, (std::vector<int>{0, 1, 2}));
  EXPECT_NEAR(tree.p_present[2], 0.01, 1e-12);
}

/// Three words in a chain 0 -> 1 -> 2 with chosen probabilities.
ChowLiuTree three_word_chain() {
  ChowLiuTree t;
  t.parent = {0, 0, 1};
  t.p_present = {0.5, 0.3, 0.2};
  t.p_present_parent_present = {0.5, 0.6, 0.4};
  t.p_present_parent_absent = {0.5, 0.1, 0.05};
  return t;
}

TEST(FabMapLikelihood, ThreeWordsByHand) {
  // Query Z = (1, 0, 1); the place saw L = (1, 1, 0); PzGe 0.39, PzGNe 0.
  const ChowLiuTree tree = three_word_chain();
  const BinaryObservation query{{0, 2}}, place{{0, 1}};
  FabMapOptions o;
  // Generator: P(e=1 | L=1) = 0.39 p / (0.39 p + 0 (1-p)) = 1 for words 0 and 1;
  // P(e=1 | L=0) for word 2 = 0.61 x 0.2 / (0.61 x 0.2 + 1 x 0.8) = 0.122 / 0.922.
  const double e2 = 0.122 / 0.922;
  // Naive Bayes: P(z | L) = sum_e P(e | L) P(z | e).
  //   word 0, z=1: 1 x 0.39;  word 1, z=0: 1 x 0.61;  word 2, z=1: e2 x 0.39 (+ (1-e2) x 0).
  o.naive_bayes = true;
  EXPECT_NEAR(word_likelihood(tree, o, 0, true, true, true), 0.39, 1e-12);
  EXPECT_NEAR(word_likelihood(tree, o, 1, false, true, true), 0.61, 1e-12);
  EXPECT_NEAR(word_likelihood(tree, o, 2, true, false, false), e2 * 0.39, 1e-12);
  EXPECT_NEAR(full_log_likelihood(tree, o, query, place),
              std::log(0.39) + std::log(0.61) + std::log(e2 * 0.39), 1e-12);
  // Chow-Liu: per e, beta / (alpha + beta) with
  //   alpha = P(z_q) P(!z | e) P(!z | z_p),  beta = P(!z_q) P(z | e) P(z | z_p):
  //   word 0 (root, its conditional is its marginal): e=1: alpha = .5 x .61 x .5,
  //     beta = .5 x .39 x .5 -> 0.39 (e=0 has P(e|L) = 0)
  //   word 1 (z=0, parent present): e=1: alpha = .7 x .39 x .6 = .1638, beta = .3 x .61 x .4 =
  //     .0732 -> .0732 / .2370
  //   word 2 (z=1, parent absent): e=1: alpha = .2 x .61 x .95 = .1159, beta = .8 x .39 x .05 =
  //     .0156 -> e2 x .0156 / .1315; e=0: beta = .8 x 0 = 0
  o.naive_bayes = false;
  const double w1 = 0.0732 / 0.2370, w2 = e2 * 0.0156 / 0.1315;
  EXPECT_NEAR(word_likelihood(tree, o, 0, true, true, true), 0.39, 1e-12);
  EXPECT_NEAR(word_likelihood(tree, o, 1, false, true, true), w1, 1e-12);
  EXPECT_NEAR(word_likelihood(tree, o, 2, true, false, false), w2, 1e-12);
  EXPECT_NEAR(full_log_likelihood(tree, o, query, place),
              std::log(0.39) + std::log(w1) + std::log(w2), 1e-12);
}

TEST(FabMapLikelihood, InvertedIndexEqualsTheDirectSumUpToTheQuerysConstant) {
  const std::vector<int> truth = {0, 0, 0, 1, 1, 2, 2, 3, 5, 6};
  const std::vector<BinaryObservation> training = sample_tree(truth, 2000, 11);
  const ChowLiuTree tree = learn_chow_liu_tree(training, 10);
  const std::vector<BinaryObservation> places = sample_tree(truth, 20, 12);
  const std::vector<BinaryObservation> queries = sample_tree(truth, 5, 13);
  for (bool naive : {false, true}) {
    FabMapOptions o;
    o.naive_bayes = naive;
    FabMap fabmap(tree, o, training);
    for (const BinaryObservation& p : places) fabmap.add_place(p);
    const BinaryObservation empty;
    for (const BinaryObservation& query : queries) {
      const std::vector<double> relative = fabmap.place_log_likelihoods(query);
      const double constant = full_log_likelihood(tree, o, query, empty);
      for (std::size_t i = 0; i < places.size(); ++i) {
        EXPECT_NEAR(relative[i] + constant, full_log_likelihood(tree, o, query, places[i]), 1e-9);
      }
      // The posterior sums to one over the new place and the map.
      double sum = 0;
      for (const PlaceMatch& m : fabmap.match(query)) sum += m.probability;
      EXPECT_NEAR(sum, 1.0, 1e-9);
    }
  }
}

TEST(FabMapLikelihood, NewPlaceSampleIsSeeded) {
  const std::vector<int> truth = {0, 0, 0, 1, 1, 2, 2, 3, 5, 6};
  const std::vector<BinaryObservation> training = sample_tree(truth, 500, 21);
  const ChowLiuTree tree = learn_chow_liu_tree(training, 10);
  FabMapOptions o;
  o.new_place_samples = 50;
  const BinaryObservation query{{0, 1, 3}};
  const double a = FabMap(tree, o, training).new_place_log_likelihood(query);
  EXPECT_EQ(a, FabMap(tree, o, training).new_place_log_likelihood(query));
  o.seed = 2;
  EXPECT_NE(a, FabMap(tree, o, training).new_place_log_likelihood(query));
}

}  // namespace
}  // namespace wifislam::slam::place
