// `wifislam vocab ...`: the ORB-SLAM family's visual vocabulary (slam/bow/vocabulary_tree.hpp).
//
//   vocab train INPUT... -o FILE    train on frames rendered from scene files or read from dataset
//                                   (or plain TUM) folders
//   vocab info FILE                 what a vocabulary file holds, and its SHA-256
#include <chrono>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "apps/command_registry.hpp"
#include "apps/option_validators.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/output_folder.hpp"
#include "core/wall_clock.hpp"
#include "sim/generate/sensor_input.hpp"
#include "slam/bow/shipped_vocabulary.hpp"
#include "slam/bow/vocabulary_tree.hpp"
#include "slam/feature/orb_feature_extractor.hpp"
#include "slam/place/fabmap_training.hpp"

namespace wifislam::cli {

namespace {

namespace fs = std::filesystem;

struct TrainArgs {
  std::vector<std::string> inputs;
  std::string output;
  int branching = 10, depth = 4, max_keypoints = 1000, every = 10;
  double fps = 1.0;
  std::int64_t max_frames = -1;
  std::uint64_t seed = 1;
  bool force = false, quiet = false;
};

/// A scene is rendered at --fps; a folder is read, every --every-th frame.
sim::generate::SensorInput open_input(const TrainArgs& args, const fs::path& input) {
  sim::generate::SensorInputOptions options;
  options.fps = args.fps;
  options.refuse_scene_options_for_datasets = false;  // --fps is the scenes' rate
  return sim::generate::open_sensor_input(input, options);
}

/// ORB descriptors of every training frame of `inputs`: scenes rendered at --fps, folders read
/// every --every-th frame (at most --max-frames frames an input).
std::vector<cv::Mat> training_descriptors(const TrainArgs& args,
                                          const std::vector<fs::path>& inputs) {
  slam::feature::FeatureOptions features;
  features.max_keypoints = args.max_keypoints;
  std::vector<cv::Mat> images;
  for (const fs::path& input : inputs) {
    const sim::generate::SensorInput opened = open_input(args, input);
    SensorStream* stream = opened.stream.get();
    const int every = opened.is_scene ? 1 : args.every;
    const slam::feature::OrbFeatureExtractor orb(features, stream->intrinsics());
    std::int64_t frames = 0, used = 0;
    while (auto event = stream->next()) {
      const auto* frame = std::get_if<RgbdFrame>(&*event);
      if (!frame) continue;
      if (args.max_frames >= 0 && frames >= args.max_frames) break;
      if (frames++ % every != 0) continue;
      images.push_back(orb.extract(*frame).descriptors);
      ++used;
    }
    if (!args.quiet) {
      fmt::print(stderr, "vocab: {}: {} frames, {} used\n", input.string(), frames, used);
    }
  }
  return images;
}

/// Refuses an output that is an input, or exists without --force.
void check_output(const TrainArgs& args, const std::vector<fs::path>& inputs) {
  check_output_file(args.output, inputs);
  std::error_code ec;
  if (fs::exists(args.output, ec) && !args.force) {
    throw InvalidInputError(args.output + ": exists; give --force to replace it");
  }
}

void train(const TrainArgs& args) {
  std::vector<fs::path> inputs(args.inputs.begin(), args.inputs.end());
  check_output(args, inputs);
  const auto start = std::chrono::steady_clock::now();
  const std::vector<cv::Mat> images = training_descriptors(args, inputs);
  std::size_t descriptors = 0;
  for (const cv::Mat& m : images) descriptors += static_cast<std::size_t>(m.rows);
  if (descriptors == 0) throw InvalidInputError("vocab train: the inputs gave no ORB features");
  slam::bow::VocabularyOptions options;
  options.branching = args.branching;
  options.depth = args.depth;
  options.seed = args.seed;
  const slam::bow::VocabularyTree tree = slam::bow::VocabularyTree::train(images, options);
  tree.save(args.output);
  const double seconds = seconds_since(start);
  fmt::print(
      "vocabulary: {} images, {} descriptors -> {} words ({} nodes, k {}, L {}), {} bytes, "
      "{:.1f} s -> {}\nsha256 {}\n",
      images.size(), descriptors, tree.word_count(), tree.node_count(), tree.branching(),
      tree.depth(), fs::file_size(args.output), seconds, args.output, sha256_file_hex(args.output));
}

/// FAB-MAP's training: the Chow-Liu tree over the vocabulary's words, learnt from the word
/// observations of the training frames, and those observations (slam/place/fabmap_training.hpp).
void train_fabmap(const TrainArgs& args, const std::string& vocabulary_path) {
  std::vector<fs::path> inputs(args.inputs.begin(), args.inputs.end());
  check_output(args, inputs);
  const auto start = std::chrono::steady_clock::now();
  const auto vocabulary = slam::bow::load_vocabulary(vocabulary_path);
  slam::place::FabMapTraining training;
  training.vocabulary_sha256 = slam::bow::vocabulary_checksum(vocabulary_path);
  for (const cv::Mat& descriptors : training_descriptors(args, inputs)) {
    training.observations.push_back(slam::place::visual_words(*vocabulary, descriptors));
  }
  if (training.observations.empty()) throw InvalidInputError("vocab fabmap: no training frames");
  const int words = static_cast<int>(vocabulary->word_count());
  training.tree = slam::place::learn_chow_liu_tree(training.observations, words);
  training.save(args.output);
  int roots = 0;
  for (int q = 0; q < words; ++q) roots += training.tree.parent[static_cast<std::size_t>(q)] == q;
  fmt::print(
      "FAB-MAP training: {} observations, {} words, {} trees (roots), {:.1f} s -> {}\n"
      "sha256 {}\n",
      training.observations.size(), words, roots, seconds_since(start), args.output,
      sha256_file_hex(args.output));
}

void info(const std::string& file) {
  const auto start = std::chrono::steady_clock::now();
  const slam::bow::VocabularyTree tree = slam::bow::VocabularyTree::load(file);
  const double load_s = seconds_since(start);
  fmt::print(
      "{}: k {}, L {}, {} words, {} nodes, trained on {} images ({} descriptors); loaded "
      "in {:.3f} s\nsha256 {}\n",
      file, tree.branching(), tree.depth(), tree.word_count(), tree.node_count(),
      tree.training_images(), tree.training_descriptors(), load_s, sha256_file_hex(file));
}

}  // namespace

WIFISLAM_COMMAND(vocab, 75) {
  CLI::App* app = parent.add_subcommand(
      "vocab",
      "Visual vocabularies for the ORB-SLAM front end (a DBoW2-style tree of ORB words with\n"
      "tf-idf weights): train one, or say what a file holds");
  app->require_subcommand(1);
  {
    auto args = std::make_shared<TrainArgs>();
    CLI::App* train_app = app->add_subcommand(
        "train",
        "Train a vocabulary on ORB features of frames rendered from scene files or read from\n"
        "dataset or plain TUM RGB-D folders. Train on scenes you will not evaluate on, so no\n"
        "evaluation sees its own images in training; a vocabulary trained on synthetic frames is\n"
        "not meant for real images (train one on real frames for those)");
    train_app->add_option("inputs", args->inputs, "Scene files (YAML) and dataset / TUM folders")
        ->required()
        ->check(kNonEmptyInput);
    train_app->add_option("-o,--output", args->output, "Vocabulary file (binary)")->required();
    train_app->add_option("--branching", args->branching, "k: children per node")
        ->capture_default_str()
        ->check(CLI::Range(2, 64));
    train_app->add_option("--depth", args->depth, "L: levels (k^L words at most)")
        ->capture_default_str()
        ->check(CLI::Range(1, 10));
    train_app
        ->add_option("--max-keypoints", args->max_keypoints,
                     "ORB features per frame (ORB-SLAM2: 1000)")
        ->capture_default_str()
        ->check(CLI::Range(10, 100000));
    train_app->add_option("--fps", args->fps, "Frames per second rendered from a scene")
        ->capture_default_str()
        ->check(finite_range(0.01, 120.0));
    train_app->add_option("--every", args->every, "Every n-th frame of a folder")
        ->capture_default_str()
        ->check(CLI::Range(1, 1000000));
    train_app->add_option("--max-frames", args->max_frames, "Frames per input (-1: all)")
        ->capture_default_str()
        ->check(CLI::Range(std::int64_t{-1}, std::int64_t{100000000}));
    train_app->add_option("--seed", args->seed, "Seed of the k-means++ seeding")
        ->capture_default_str()
        ->check(cli::kSeedValidator);
    train_app->add_flag("--force", args->force, "Replace an existing file");
    train_app->add_flag("-q,--quiet", args->quiet, "No progress lines on stderr");
    train_app->callback([args] { train(*args); });
  }
  {
    auto args = std::make_shared<TrainArgs>();
    auto vocabulary = std::make_shared<std::string>();
    args->fps = 2.0;
    CLI::App* fabmap_app = app->add_subcommand(
        "fabmap",
        "Train FAB-MAP (wifislam localize) for a vocabulary: the Chow-Liu tree over its words "
        "from\n"
        "the word observations of frames of scenes you will not evaluate on, and those\n"
        "observations for FAB-MAP's new-place term, in one text file. Deterministic");
    fabmap_app->add_option("inputs", args->inputs, "Scene files (YAML) and dataset / TUM folders")
        ->required()
        ->check(kNonEmptyInput);
    fabmap_app->add_option("-o,--output", args->output, "Training file (text)")->required();
    fabmap_app
        ->add_option("--vocabulary", *vocabulary, "Vocabulary file (default: the shipped one)")
        ->check(kNonEmptyInput);
    fabmap_app->add_option("--fps", args->fps, "Frames per second rendered from a scene")
        ->capture_default_str()
        ->check(finite_range(0.01, 120.0));
    fabmap_app->add_option("--every", args->every, "Every n-th frame of a folder")
        ->capture_default_str()
        ->check(CLI::Range(1, 1000000));
    fabmap_app->add_option("--max-keypoints", args->max_keypoints, "ORB features per frame")
        ->capture_default_str()
        ->check(CLI::Range(10, 100000));
    fabmap_app->add_flag("--force", args->force, "Replace an existing file");
    fabmap_app->add_flag("-q,--quiet", args->quiet, "No progress lines on stderr");
    fabmap_app->callback([args, vocabulary] { train_fabmap(*args, *vocabulary); });
  }
  {
    auto file = std::make_shared<std::string>();
    CLI::App* info_app = app->add_subcommand("info", "What a vocabulary file holds");
    info_app->add_option("file", *file, "Vocabulary file")->required()->check(kNonEmptyInput);
    info_app->callback([file] { info(*file); });
  }
}

}  // namespace wifislam::cli
