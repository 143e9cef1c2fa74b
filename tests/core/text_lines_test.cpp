// read_text_lines and LineCursor: the same lines as std::getline gave (CRLF, a last line without
// a newline, blank lines, lines longer than the read buffer), and a bounded read of what is not a
// text file: a folder is refused by name, and /dev/zero stops at the line cap instead of filling
// memory.

#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/line_cursor.hpp"
#include "core/text_lines.hpp"
#include "tests/support/scratch_folder.hpp"

namespace wifislam {
namespace {

namespace fs = std::filesystem;

fs::path write_lines_file(const std::string& name, const std::string& text) {
  const fs::path p = test::scratch_folder(name) / name;
  std::ofstream(p, std::ios::binary) << text;
  return p;
}

std::vector<std::string> texts(const std::vector<TextLine>& lines) {
  std::vector<std::string> out;
  for (const TextLine& l : lines) out.push_back(l.text);
  return out;
}

TEST(TextLines, SameLinesAsGetline) {
  const std::string long_line(10000, 'x');  // longer than one read piece
  const std::string text = "a b\r\n\n# c\r\n" + long_line + "\nlast";
  const fs::path p = write_lines_file("mixed.txt", text);
  std::vector<std::string> expected;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    expected.push_back(line);
  }
  ASSERT_EQ(expected.size(), 5u);
  const std::vector<TextLine> lines = read_text_lines(p.string());
  EXPECT_EQ(texts(lines), expected);
  EXPECT_EQ(lines.back().number, 5);

  // The cursor skips blank and '#' lines and keeps the file's line numbers.
  LineCursor cursor(p.string());
  TextLine line;
  std::vector<int> numbers;
  while (cursor.next(line)) numbers.push_back(line.number);
  EXPECT_EQ(numbers, (std::vector<int>{1, 4, 5}));

  const fs::path empty = write_lines_file("empty.txt", ""),
                 one_line = write_lines_file("newline.txt", "x\n");
  EXPECT_TRUE(read_text_lines(empty.string()).empty());
  EXPECT_EQ(read_text_lines(one_line.string()).size(), 1u);
  for (const fs::path& file : {p, empty, one_line}) fs::remove(file);
}

TEST(TextLines, AFolderIsRefusedByName) {
  const fs::path folder = test::scratch_folder("folder");
  try {
    read_text_lines(folder.string());
    ADD_FAILURE() << "a folder was read";
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("is a folder"), std::string::npos) << e.what();
  }
  EXPECT_THROW(LineCursor{folder.string()}, ParseError);
  fs::remove_all(folder);
}

TEST(TextLines, EndlessLineStopsAtTheCap) {
  // std::getline on /dev/zero grows one line until memory runs out.
  try {
    read_text_lines("/dev/zero");
    ADD_FAILURE() << "/dev/zero was read";
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("/dev/zero:1"), std::string::npos) << e.what();
  }
  LineCursor cursor("/dev/zero");
  TextLine line;
  EXPECT_THROW(cursor.next(line), ParseError);
}

}  // namespace
}  // namespace wifislam
