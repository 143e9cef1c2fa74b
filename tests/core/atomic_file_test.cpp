#include <gtest/gtest.h>

#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/output_folder.hpp"
#include "tests/support/scratch_folder.hpp"

namespace wifislam {
namespace {

namespace fs = std::filesystem;

fs::path fresh_dir(const std::string& name) {
  return test::scratch_folder(name) / name;  // not made yet: the test makes it
}

TEST(AtomicDirectory, NothingVisibleUntilCommitAndNothingLeftWhenAbandoned) {
  const fs::path out = fresh_dir("abandon");
  {
    AtomicDirectory dir(out, false);
    std::ofstream(dir.staging_path() / "a.txt") << "x";
    EXPECT_FALSE(fs::exists(out));
  }  // abandoned, e.g. by an exception
  EXPECT_FALSE(fs::exists(out));
  EXPECT_FALSE(fs::exists(out.string() + ".partial"));
}

// An output under folders that did not exist: abandoned, it left those (empty) folders behind.
// They go with it, up to the first that was there before, and a parent that got other files
// meanwhile stays.
TEST(AtomicDirectory, AbandonedItRemovesTheEmptyParentsItMade) {
  const fs::path root = test::scratch_folder("parents");
  {
    AtomicDirectory dir(root / "a" / "b" / "out", false);
    EXPECT_TRUE(fs::is_directory(root / "a" / "b"));
  }
  EXPECT_TRUE(fs::is_directory(root));
  EXPECT_FALSE(fs::exists(root / "a"));
  {
    AtomicDirectory dir(root / "c" / "d" / "out", false);
    std::ofstream(root / "c" / "notes.txt") << "written meanwhile";
  }
  EXPECT_FALSE(fs::exists(root / "c" / "d"));
  EXPECT_TRUE(fs::exists(root / "c" / "notes.txt"));
  {
    AtomicDirectory dir(root / "e" / "out", false);
    dir.commit();
  }
  EXPECT_TRUE(fs::is_directory(root / "e" / "out"));  // committed: everything stays
  fs::remove_all(root);
}

TEST(AtomicDirectory, CommitMovesTheFolderIntoPlace) {
  const fs::path out = fresh_dir("commit");
  {
    AtomicDirectory dir(out, false);
    std::ofstream(dir.staging_path() / "a.txt") << "x";
    dir.commit();
  }
  EXPECT_TRUE(fs::exists(out / "a.txt"));
  EXPECT_THROW(AtomicDirectory(out, false), InvalidInputError);  // no silent overwrite
  {
    AtomicDirectory dir(out, true);
    std::ofstream(dir.staging_path() / "b.txt") << "y";
    dir.commit();
  }
  EXPECT_FALSE(fs::exists(out / "a.txt"));
  EXPECT_TRUE(fs::exists(out / "b.txt"));
  fs::remove_all(out);
}

TEST(WriteFileAtomic, ReplacesAFileButRefusesAFolderOrAPipeAndLeavesThemAsTheyWere) {
  const fs::path root = fresh_dir("targets");
  fs::create_directories(root);
  write_file_atomic(root / "file.txt", "old");
  write_file_atomic(root / "file.txt", "new");
  EXPECT_EQ(sha256_file_hex(root / "file.txt"), sha256_hex("new"));

  // Renaming over a pipe or device would replace it with a regular file (as root, /dev/null).
  const fs::path pipe = root / "pipe";
  ASSERT_EQ(::mkfifo(pipe.c_str(), 0600), 0);
  EXPECT_THROW(write_file_atomic(pipe, "x"), InvalidInputError);
  EXPECT_TRUE(fs::is_fifo(pipe));
  fs::create_symlink(pipe, root / "link_to_pipe");
  EXPECT_THROW(write_file_atomic(root / "link_to_pipe", "x"), InvalidInputError);
  EXPECT_TRUE(fs::is_fifo(pipe));

  fs::create_directory(root / "folder");
  EXPECT_THROW(write_file_atomic(root / "folder", "x"), InvalidInputError);
  EXPECT_TRUE(fs::is_directory(root / "folder"));
  EXPECT_FALSE(fs::exists(root / "folder.partial"));
  EXPECT_FALSE(fs::exists(root / "pipe.partial"));
  fs::remove_all(root);
}

// A file is written as <file>.partial first, which truncated a file of the user's by that name.
// Inside a folder of ours (a resumed `paper` folder) such a file is an interrupted write of ours.
TEST(WriteFileAtomic, APartialFileOfTheUsersIsNeverWrittenOver) {
  const fs::path root = fresh_dir("partials");
  fs::create_directories(root);
  { std::ofstream(root / "map.png.partial") << "the user's"; }
  EXPECT_THROW(write_file_atomic(root / "map.png", "png"), InvalidInputError);
  EXPECT_FALSE(fs::exists(root / "map.png"));
  std::ifstream kept(root / "map.png.partial");
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(kept), {}), "the user's");
  fs::create_symlink(root / "map.png.partial", root / "b.png.partial");
  EXPECT_THROW(write_file_atomic(root / "b.png", "png"), InvalidInputError);

  // Below a folder holding the output marker: left by an interrupted write, replaced.
  const fs::path ours = root / "paper";
  fs::create_directories(ours / "results");
  { std::ofstream(ours / kOutputMarkerFile) << "x"; }
  { std::ofstream(ours / "results" / "t.json.partial") << "half"; }
  write_file_atomic(ours / "results" / "t.json", "whole");
  EXPECT_EQ(sha256_file_hex(ours / "results" / "t.json"), sha256_hex("whole"));
  EXPECT_FALSE(fs::exists(ours / "results" / "t.json.partial"));
  fs::remove_all(root);
}

TEST(Sha256, MatchesTheStandardTestVectors) {
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  const fs::path f = test::scratch_folder() / "sha_test.txt";
  write_file_atomic(f, "abc");
  EXPECT_EQ(sha256_file_hex(f), sha256_hex("abc"));
  fs::remove(f);
}

}  // namespace
}  // namespace wifislam
