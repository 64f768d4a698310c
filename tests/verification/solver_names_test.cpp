// SPDX-License-Identifier: MIT
// The harness and the report name no solver: every role they need (exact or model, certified
// reference, accuracy target, ...) comes from the solver registry (SolverEntry), so that a solver
// added to the registry joins them without an edit (docs/contributing/architecture.md, "Solver
// skeleton"). This test reads every C++ file under src/verification and src/io/report, drops the
// comments, and fails on any string literal that contains a registered solver's name as a word
// ("fe", "shooting vs fe", "frobenius, else shooting"), printing file, line and literal.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "catena/solvers/solver_registry.hpp"

namespace catena {
namespace {

namespace fs = std::filesystem;

// The literals of one line of code, with // comments and the text of /* */ comments gone
// (`in_block` carries a block comment across lines). Character literals are skipped.
std::vector<std::string> string_literals(const std::string& line, bool& in_block) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < line.size(); ++i) {
    if (in_block) {
      if (line.compare(i, 2, "*/") == 0) in_block = false, ++i;
      continue;
    }
    if (line.compare(i, 2, "//") == 0) break;
    if (line.compare(i, 2, "/*") == 0) {
      in_block = true, ++i;
      continue;
    }
    if (line[i] == '\'') {  // '"' and '\'' must not open a string
      const std::size_t end = line.find('\'', i + (line[i + 1] == '\\' ? 3 : 2));
      i = end == std::string::npos ? line.size() : end;
      continue;
    }
    if (line[i] != '"') continue;
    std::string literal;
    for (++i; i < line.size() && line[i] != '"'; ++i) {
      if (line[i] == '\\' && i + 1 < line.size()) ++i;
      literal += line[i];
    }
    out.push_back(literal);
  }
  return out;
}

std::set<std::string> words(const std::string& text) {
  static const std::regex word("[A-Za-z0-9_]+");
  std::set<std::string> out;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), word); it != std::sregex_iterator();
       ++it)
    out.insert(it->str());
  return out;
}

// "file:line: "literal" names <solver>" for each offending literal under `folder`.
std::vector<std::string> solver_names_in_literals(const fs::path& folder) {
  std::vector<std::string> found;
  for (const auto& file : fs::recursive_directory_iterator(folder)) {
    const std::string ext = file.path().extension().string();
    if (ext != ".cpp" && ext != ".hpp") continue;
    std::ifstream in(file.path());
    std::string line;
    bool in_block = false;
    for (int number = 1; std::getline(in, line); ++number) {
      for (const std::string& literal : string_literals(line, in_block)) {
        const std::set<std::string> used = words(literal);
        for (const SolverEntry& entry : solver_registry()) {
          if (!used.count(entry.name)) continue;
          std::ostringstream message;
          message << fs::relative(file.path(), CATENA_SOURCE_DIR).string() << ":" << number
                  << ": \"" << literal << "\" names " << entry.name;
          found.push_back(message.str());
        }
      }
    }
  }
  return found;
}

TEST(SolverNames, TheLiteralScannerSeesLiteralsAndSkipsComments) {
  bool in_block = false;
  EXPECT_EQ(string_literals(R"(f("fe", "a \"b\" c"); // "shooting")", in_block),
            (std::vector<std::string>{"fe", "a \"b\" c"}));
  EXPECT_EQ(string_literals(R"(x = '"'; /* "airy" */ y = "airy";)", in_block),
            (std::vector<std::string>{"airy"}));
  EXPECT_TRUE(string_literals(R"(a /* "fe")", in_block).empty());
  EXPECT_TRUE(string_literals(R"("fe" */ b)", in_block).empty());
  EXPECT_FALSE(in_block);
  EXPECT_EQ(words("frobenius, else shooting"),
            (std::set<std::string>{"frobenius", "else", "shooting"}));
  EXPECT_FALSE(words("coefficient safe").count("fe"));
}

TEST(SolverNames, TheHarnessAndTheReportNameNoSolver) {
  ASSERT_GE(solver_registry().size(), 5u);
  for (const char* folder : {"src/verification", "src/io/report"}) {
    const fs::path path = fs::path(CATENA_SOURCE_DIR) / folder;
    ASSERT_TRUE(fs::is_directory(path)) << path;
    const std::vector<std::string> found = solver_names_in_literals(path);
    std::string list;
    for (const auto& f : found) list += "\n  " + f;
    EXPECT_TRUE(found.empty()) << folder << " names solvers in string literals (take roles and "
                               << "names from the registry, catena/solvers/solver_registry.hpp):"
                               << list;
  }
}

}  // namespace
}  // namespace catena
