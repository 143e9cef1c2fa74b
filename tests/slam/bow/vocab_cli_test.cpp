// `wifislam vocab` through the command line, and the shipped vocabulary: training on a scene
// writes a file that `vocab info` reads; an existing file is replaced only with --force; a corrupt
// file is exit 2 naming the file; assets/vocabulary/orb_k10_l4.bin loads and is the file its
// README describes (k, L, words, SHA-256).
#include <gtest/gtest.h>

#include "core/atomic_file.hpp"
#include "slam/bow/vocabulary_tree.hpp"
#include "tests/support/cli_run.hpp"
#include "tests/support/read_file.hpp"

namespace wifislam::slam::bow {
namespace {

namespace fs = std::filesystem;

const fs::path kAssets = fs::path(WIFISLAM_SCENES_DIR).parent_path() / "assets" / "vocabulary";

TEST(VocabCli, TrainOnASceneThenInfoReadsItAndBadFilesAreRefused) {
  const fs::path dir = test::scratch_folder();
  test::write_file(dir / "tiny.yaml", test::kTinyLoopYaml);
  const fs::path file = dir / "voc.bin";
  const std::string train = "vocab train " + (dir / "tiny.yaml").string() +
                            " --branching 4 --depth 3 --fps 2 --max-frames 12 -q -o " +
                            file.string();
  const auto trained = test::run_wifislam(train, dir);
  ASSERT_EQ(trained.exit_code, 0) << trained.err;
  EXPECT_NE(trained.out.find("12 images"), std::string::npos) << trained.out;
  const VocabularyTree tree = VocabularyTree::load(file);
  EXPECT_EQ(tree.branching(), 4);
  EXPECT_EQ(tree.depth(), 3);
  EXPECT_EQ(tree.training_images(), 12u);
  EXPECT_GT(tree.word_count(), 16u);

  const auto info = test::run_wifislam("vocab info " + file.string(), dir);
  ASSERT_EQ(info.exit_code, 0) << info.err;
  EXPECT_NE(info.out.find("sha256 " + sha256_file_hex(file)), std::string::npos) << info.out;

  // The same training again into the same file: refused without --force, the same bytes with it.
  const std::string before = test::read_file(file);
  EXPECT_EQ(test::run_wifislam(train, dir).exit_code, 2);
  ASSERT_EQ(test::run_wifislam(train + " --force", dir).exit_code, 0);
  EXPECT_EQ(test::read_file(file), before);

  std::string corrupt = before;
  corrupt[corrupt.size() / 2] = static_cast<char>(corrupt[corrupt.size() / 2] ^ 1);
  test::write_file(dir / "corrupt.bin", corrupt);
  const auto refused = test::run_wifislam("vocab info " + (dir / "corrupt.bin").string(), dir);
  EXPECT_EQ(refused.exit_code, 2) << refused.err;
  EXPECT_NE(refused.err.find("corrupt.bin"), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find("checksum"), std::string::npos) << refused.err;
  fs::remove_all(dir);
}

// Issue 34: `vocab info FOLDER` said the vocabulary was "truncated" (a folder opens as an empty
// stream); a device would be read without end. Both are bad input (exit 2) saying what they
// are; a missing file stays an I/O error (exit 3).
TEST(VocabCli, InfoOnAFolderOrADeviceSaysItIsNoVocabularyFile) {
  const fs::path dir = test::scratch_folder();
  fs::create_directories(dir / "folder");
  const auto folder = test::run_wifislam("vocab info " + (dir / "folder").string(), dir);
  EXPECT_EQ(folder.exit_code, 2) << folder.err;
  EXPECT_NE(folder.err.find("is a folder, not a vocabulary file"), std::string::npos) << folder.err;
  EXPECT_EQ(folder.err.find("truncated"), std::string::npos) << folder.err;
  const auto device = test::run_wifislam("vocab info /dev/zero", dir);
  EXPECT_EQ(device.exit_code, 2) << device.err;
  EXPECT_NE(device.err.find("not a regular file"), std::string::npos) << device.err;
  const auto missing = test::run_wifislam("vocab info " + (dir / "none.bin").string(), dir);
  EXPECT_EQ(missing.exit_code, 3) << missing.err;
  fs::remove_all(dir);
}

TEST(ShippedVocabulary, LoadsAndIsTheFileItsReadmeDescribes) {
  const fs::path file = kAssets / "orb_k10_l4.bin";
  const VocabularyTree tree = VocabularyTree::load(file);
  EXPECT_EQ(tree.branching(), 10);
  EXPECT_EQ(tree.depth(), 4);
  EXPECT_EQ(tree.word_count(), 10000u);
  const std::string readme = test::read_file(kAssets / "README.md");
  EXPECT_NE(readme.find(sha256_file_hex(file)), std::string::npos)
      << "assets/vocabulary/README.md does not give the file's SHA-256";
  // The README writes the size with a thin thousands separator: "533 432 bytes".
  std::string size = std::to_string(fs::file_size(file));
  for (auto at = static_cast<std::ptrdiff_t>(size.size()) - 3; at > 0; at -= 3)
    size.insert(static_cast<std::size_t>(at), " ");
  EXPECT_NE(readme.find(size + " bytes"), std::string::npos) << size;
}

}  // namespace
}  // namespace wifislam::slam::bow
