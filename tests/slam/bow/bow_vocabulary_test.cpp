// The DBoW2-style vocabulary (slam/bow): k-majority clustering finds the prototypes of noisy
// binary descriptors, the L1 score is 1 for the same words and 0 for none in common, training is
// deterministic and the file round-trips bit for bit, a corrupt or truncated file is refused, and
// on real ORB features an image scores higher against a shifted view of itself than against
// another image. Tiny vocabularies, trained here.
#include <gtest/gtest.h>

#include <cstring>
#include <set>

#include <opencv2/features2d.hpp>
#include <opencv2/imgproc.hpp>

#include "core/error.hpp"
#include "core/rng.hpp"
#include "slam/bow/vocabulary_tree.hpp"

namespace wifislam::slam::bow {
namespace {

match::PackedDescriptor random_descriptor(Rng& rng) {
  return {rng.next_u64(), rng.next_u64(), rng.next_u64(), rng.next_u64()};
}

/// `copies` copies of `prototype`, each with `flips` random bits flipped, as CV_8U rows.
cv::Mat noisy_copies(const match::PackedDescriptor& prototype, int copies, int flips, Rng& rng) {
  cv::Mat out(copies, 32, CV_8U);
  for (int r = 0; r < copies; ++r) {
    match::PackedDescriptor d = prototype;
    for (int f = 0; f < flips; ++f) {
      const auto bit = rng.uniform_int(0, 255);
      d[static_cast<std::size_t>(bit / 64)] ^= std::uint64_t{1} << (bit % 64);
    }
    std::memcpy(out.ptr(r), d.data(), 32);
  }
  return out;
}

cv::Mat rows_of(const std::vector<match::PackedDescriptor>& ds) {
  cv::Mat out(static_cast<int>(ds.size()), 32, CV_8U);
  for (std::size_t i = 0; i < ds.size(); ++i)
    std::memcpy(out.ptr(static_cast<int>(i)), ds[i].data(), 32);
  return out;
}

struct Prototypes {
  std::vector<match::PackedDescriptor> prototypes;
  std::vector<cv::Mat> images;  // image i: noisy copies of prototype i
};

Prototypes four_prototypes() {
  Rng rng = Rng::stream(7, "test/bow/prototypes");
  Prototypes p;
  for (int i = 0; i < 4; ++i) {
    p.prototypes.push_back(random_descriptor(rng));
    p.images.push_back(noisy_copies(p.prototypes.back(), 50, 10, rng));
  }
  return p;
}

TEST(BowVocabulary, KMajorityClusteringFindsThePrototypesOfNoisyDescriptors) {
  const Prototypes p = four_prototypes();
  VocabularyOptions o;
  o.branching = 4;
  o.depth = 1;
  const VocabularyTree tree = VocabularyTree::train(p.images, o);
  ASSERT_EQ(tree.word_count(), 4u);
  EXPECT_EQ(tree.training_images(), 4u);
  EXPECT_EQ(tree.training_descriptors(), 200u);
  std::set<WordId> words;
  for (std::size_t i = 0; i < 4; ++i) {
    const WordId w = tree.word_of(p.prototypes[i]);
    words.insert(w);
    for (int r = 0; r < p.images[i].rows; ++r) {
      match::PackedDescriptor d{};
      std::memcpy(d.data(), p.images[i].ptr(r), 32);
      EXPECT_EQ(tree.word_of(d), w) << "prototype " << i << ", copy " << r;
    }
    EXPECT_NEAR(tree.idf(w), std::log(4.0), 1e-12);  // each word in one of four images
  }
  EXPECT_EQ(words.size(), 4u);
}

TEST(BowVocabulary, L1ScoreIsOneForTheSameWordsAndZeroWithoutACommonWord) {
  const Prototypes p = four_prototypes();
  VocabularyOptions o;
  o.branching = 4;
  o.depth = 2;
  const VocabularyTree tree = VocabularyTree::train(p.images, o);
  const auto& q = p.prototypes;
  const BowVector a = tree.transform(rows_of({q[0], q[1]}));
  const BowVector a_again = tree.transform(rows_of({q[1], q[0], q[1], q[0]}));
  const BowVector b = tree.transform(rows_of({q[2], q[3]}));
  const BowVector c = tree.transform(rows_of({q[0], q[2]}));
  double sum = 0.0;
  for (const auto& [word, weight] : a) sum += weight;
  EXPECT_NEAR(sum, 1.0, 1e-12);
  EXPECT_NEAR(l1_score(a, a_again), 1.0, 1e-12);
  EXPECT_NEAR(l1_score(a, b), 0.0, 1e-12);
  EXPECT_NEAR(l1_score(a, c), 0.5, 1e-12);  // one of two equally weighted words in common
  EXPECT_NEAR(l1_score(c, a), 0.5, 1e-12);

  // The direct index holds every feature once.
  FeatureVector direct;
  const cv::Mat image = rows_of({q[0], q[1], q[2], q[0]});
  tree.transform(image, &direct, 1);
  std::vector<int> seen;
  for (const auto& [node, features] : direct)
    seen.insert(seen.end(), features.begin(), features.end());
  std::sort(seen.begin(), seen.end());
  EXPECT_EQ(seen, (std::vector<int>{0, 1, 2, 3}));
}

TEST(BowVocabulary, TrainingIsDeterministicAndTheFileRoundTripsBitForBit) {
  Rng rng = Rng::stream(11, "test/bow/images");
  std::vector<cv::Mat> images;
  for (int i = 0; i < 12; ++i) {
    std::vector<match::PackedDescriptor> ds;
    for (int k = 0; k < 80; ++k) ds.push_back(random_descriptor(rng));
    images.push_back(rows_of(ds));
  }
  VocabularyOptions o;
  o.branching = 5;
  o.depth = 3;
  const std::string first = VocabularyTree::train(images, o).serialise();
  const std::string second = VocabularyTree::train(images, o).serialise();
  EXPECT_EQ(first, second);
  const VocabularyTree loaded = VocabularyTree::deserialise(first, "first");
  EXPECT_EQ(loaded.serialise(), first);
  const VocabularyTree trained = VocabularyTree::train(images, o);
  EXPECT_GT(trained.word_count(), 25u);
  for (const cv::Mat& image : images) EXPECT_EQ(loaded.transform(image), trained.transform(image));
}

TEST(BowVocabulary, ACorruptOrTruncatedFileIsRefusedNamingWhatIsWrong) {
  const Prototypes p = four_prototypes();
  VocabularyOptions o;
  o.branching = 4;
  o.depth = 2;
  const std::string good = VocabularyTree::train(p.images, o).serialise();
  const auto refusal = [](const std::string& bytes) {
    try {
      VocabularyTree::deserialise(bytes, "voc.bin");
    } catch (const InvalidInputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(refusal(good.substr(0, good.size() - 10)).find("truncated"), std::string::npos);
  EXPECT_NE(refusal(good.substr(0, 20)).find("truncated"), std::string::npos);
  std::string flipped = good;
  flipped[100] = static_cast<char>(flipped[100] ^ 0x10);
  EXPECT_NE(refusal(flipped).find("checksum"), std::string::npos);
  std::string magic = good;
  magic[0] = 'X';
  EXPECT_NE(refusal(magic).find("magic"), std::string::npos);
  std::string version = good;
  version[8] = 2;
  EXPECT_NE(refusal(version).find("version 2"), std::string::npos);
  EXPECT_NE(refusal(good + "x").find("trailing"), std::string::npos);
  EXPECT_NE(refusal(flipped).find("voc.bin"), std::string::npos);
  EXPECT_EQ(refusal(good), "accepted");
}

/// A textured grey image: smoothed noise from its own stream.
cv::Mat texture(std::uint64_t seed) {
  cv::Mat noise(360, 480, CV_8U);
  cv::theRNG().state = seed;
  cv::randu(noise, 0, 256);
  cv::Mat smooth;
  cv::GaussianBlur(noise, smooth, cv::Size(0, 0), 2.0);
  cv::normalize(smooth, smooth, 0, 255, cv::NORM_MINMAX);
  return smooth;
}

cv::Mat orb_descriptors(const cv::Mat& image) {
  const cv::Ptr<cv::ORB> orb = cv::ORB::create(500);
  std::vector<cv::KeyPoint> keypoints;
  cv::Mat descriptors;
  orb->detectAndCompute(image, cv::noArray(), keypoints, descriptors);
  return descriptors;
}

TEST(BowVocabulary, RealOrbFeaturesScoreHigherAgainstAShiftedViewThanAgainstAnotherImage) {
  std::vector<cv::Mat> training;
  for (std::uint64_t s = 100; s < 110; ++s) training.push_back(orb_descriptors(texture(s)));
  VocabularyOptions o;
  o.branching = 8;
  o.depth = 3;
  const VocabularyTree tree = VocabularyTree::train(training, o);
  const cv::Mat a = texture(1), b = texture(2);
  const cv::Mat a_shifted = a(cv::Rect(12, 8, 440, 330)).clone();
  const cv::Mat a_view = a(cv::Rect(0, 0, 440, 330)).clone();
  const BowVector va = tree.transform(orb_descriptors(a_view));
  const BowVector vs = tree.transform(orb_descriptors(a_shifted));
  const BowVector vb = tree.transform(orb_descriptors(b(cv::Rect(0, 0, 440, 330)).clone()));
  const double same = l1_score(va, vs), other = l1_score(va, vb);
  EXPECT_GT(same, 1.5 * other) << "same place " << same << ", another image " << other;
}

}  // namespace
}  // namespace wifislam::slam::bow
