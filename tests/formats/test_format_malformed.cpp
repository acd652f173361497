// The table of malformed cemv-matrix/1 files (tests/formats/malformed/EXPECTED.tsv):
// each file must be rejected with a LoadError, never a crash, and one of its
// issue lines (as `cemv fmt` prints them: "error: <where>: <what>") must match
// the expected regex. The same table drives the CLI tests in format.cmake.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "formats/matrix_json.hpp"

using namespace cemv::model;
using namespace cemv::formats;
namespace fs = std::filesystem;

namespace {

struct Row {
  std::string file;
  std::string regex;
};

// Names the row in gtest's messages instead of dumping its bytes.
void PrintTo(const Row& row, std::ostream* os) { *os << row.file; }

const fs::path kDir = fs::path(CEMV_SOURCE_DIR) / "tests" / "formats" / "malformed";

std::vector<Row> read_table() {
  std::vector<Row> rows;
  std::ifstream in(kDir / "EXPECTED.tsv");
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    auto tab = line.find('\t');
    if (tab == std::string::npos) continue;
    rows.push_back({line.substr(0, tab), line.substr(tab + 1)});
  }
  return rows;
}

std::string test_name(const testing::TestParamInfo<Row>& info) {
  std::string name = info.param.file.substr(0, info.param.file.rfind('.'));
  for (auto& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

class Malformed : public testing::TestWithParam<Row> {};

TEST_P(Malformed, IsRejectedWithTheExpectedMessage) {
  const Row& row = GetParam();
  std::vector<std::string> lines;
  try {
    load_matrix(kDir / row.file);
    FAIL() << row.file << " was accepted";
  } catch (const LoadError& e) {
    ASSERT_FALSE(e.issues().empty());
    for (const auto& issue : e.issues()) lines.push_back("error: " + issue.str());
  }
  std::regex expected(row.regex, std::regex::ECMAScript);
  bool matched = false;
  for (const auto& l : lines) matched = matched || std::regex_search(l, expected);
  std::string all;
  for (const auto& l : lines) all += l + "\n";
  EXPECT_TRUE(matched) << "no line matches /" << row.regex << "/ in:\n" << all;
}

INSTANTIATE_TEST_SUITE_P(Table, Malformed, testing::ValuesIn(read_table()), test_name);

TEST(MalformedTable, CoversEveryFileAndEnoughCases) {
  auto rows = read_table();
  EXPECT_GE(rows.size(), 45u);
  std::set<std::string> listed;
  for (const auto& r : rows) EXPECT_TRUE(listed.insert(r.file).second) << "listed twice: " << r.file;
  for (const auto& entry : fs::directory_iterator(kDir)) {
    std::string name = entry.path().filename().string();
    if (entry.path().extension() != ".json") continue;
    EXPECT_TRUE(listed.count(name)) << name << " has no row in EXPECTED.tsv";
  }
  for (const auto& r : rows) EXPECT_TRUE(fs::exists(kDir / r.file)) << r.file;
}

}  // namespace
