// for_each_csv_row: the shared CSV reading of eval's run files (loop closures, Wi-Fi clusters).

#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/text_lines.hpp"
#include "tests/support/scratch_folder.hpp"

namespace wifislam {
namespace {

namespace fs = std::filesystem;
constexpr std::array<const char*, 2> kColumns = {"a", "b"};

std::string write(const std::string& name, const std::string& text) {
  const fs::path p = test::scratch_folder(name) / (name + ".csv");
  std::ofstream(p) << text;
  return p.string();
}

std::string error_of(const std::string& path) {
  try {
    for_each_csv_row(path, kColumns, [](const CsvRow&) {});
  } catch (const ParseError& e) {
    return e.what();
  }
  return "";
}

TEST(CsvRows, SkipsCommentsAndBlankLinesAndReportsLineNumbers) {
  const std::string p = write("ok", "# made by a test\na,b\n\n1,2\n# note\n3,4\n");
  std::vector<std::pair<int, std::string>> rows;
  for_each_csv_row(p, kColumns, [&](const CsvRow& row) {
    rows.emplace_back(row.line, std::string(row.fields[0]) + "|" + std::string(row.fields[1]));
    EXPECT_EQ(row.where, p + ":" + std::to_string(row.line));
  });
  EXPECT_EQ(rows, (std::vector<std::pair<int, std::string>>{{4, "1|2"}, {6, "3|4"}}));
}

TEST(CsvRows, WrongHeaderShortRowAndEmptyFileNameTheFileAndLine) {
  const std::string header = write("header", "a,c\n1,2\n");
  EXPECT_NE(error_of(header).find(header + ":1"), std::string::npos) << error_of(header);
  EXPECT_NE(error_of(header).find("'a,b'"), std::string::npos) << error_of(header);
  const std::string short_row = write("short", "a,b\n1,2\n3\n");
  EXPECT_NE(error_of(short_row).find(short_row + ":3"), std::string::npos) << error_of(short_row);
  const std::string empty = write("empty", "# nothing\n");
  EXPECT_NE(error_of(empty).find("empty file"), std::string::npos) << error_of(empty);
  EXPECT_THROW(for_each_csv_row(write("x", "") + ".missing", kColumns, [](const CsvRow&) {}),
               IoError);
}

}  // namespace
}  // namespace wifislam
