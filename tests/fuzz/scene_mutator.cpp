// SPDX-License-Identifier: MIT
// Deterministic scene mutations (see scene_mutator.hpp). Each operator changes one thing and says
// what it did, so that a failing mutant can be understood without diffing it.
#include "scene_mutator.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace catena::fuzz {

std::uint64_t Random::next() {
  std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

std::vector<SeedScene> read_seed_corpus(const std::filesystem::path& directory) {
  std::vector<SeedScene> corpus;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(directory)) {
    if (!entry.is_regular_file() || entry.path().extension() != ".toml") continue;
    std::ostringstream text;
    text << std::ifstream(entry.path(), std::ios::binary).rdbuf();
    corpus.push_back({entry.path(), text.str()});
  }
  std::sort(corpus.begin(), corpus.end(),
            [](const SeedScene& x, const SeedScene& y) { return x.file < y.file; });
  return corpus;
}

namespace {

struct Span {
  std::size_t begin;
  std::size_t end;
};

bool starts_number(const std::string& text, std::size_t i) {
  const auto digit = [&](std::size_t k) {
    return k < text.size() && std::isdigit(static_cast<unsigned char>(text[k]));
  };
  if (i > 0) {
    const unsigned char before = static_cast<unsigned char>(text[i - 1]);
    if (std::isalnum(before) || before == '_' || before == '.') return false;
  }
  if (digit(i)) return true;
  return (text[i] == '-' || text[i] == '+' || text[i] == '.') && digit(i + 1);
}

/// Numeric literals (TOML integers and floats; also digits inside strings, which is fine here).
std::vector<Span> number_spans(const std::string& text) {
  std::vector<Span> spans;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (!starts_number(text, i)) continue;
    std::size_t j = i + 1;
    while (j < text.size()) {
      const char c = text[j];
      const bool exponent_sign =
          (c == '+' || c == '-') && (text[j - 1] == 'e' || text[j - 1] == 'E');
      if (!(std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == 'e' || c == 'E' ||
            c == '_' || exponent_sign)) {
        break;
      }
      ++j;
    }
    spans.push_back({i, j});
    i = j;
  }
  return spans;
}

/// Quoted strings "..." (no escapes handled: good enough to find the corpus's words).
std::vector<Span> string_spans(const std::string& text) {
  std::vector<Span> spans;
  for (std::size_t i = text.find('"'); i != std::string::npos; i = text.find('"', i + 1)) {
    const std::size_t close = text.find('"', i + 1);
    if (close == std::string::npos || text.find('\n', i) < close) continue;
    spans.push_back({i, close + 1});
    i = close;
  }
  return spans;
}

std::vector<Span> line_spans(const std::string& text) {
  std::vector<Span> spans;
  std::size_t begin = 0;
  while (begin < text.size()) {
    const std::size_t newline = text.find('\n', begin);
    const std::size_t end = newline == std::string::npos ? text.size() : newline + 1;
    spans.push_back({begin, end});
    begin = end;
  }
  return spans;
}

// Values at the edges of what the reader and the solvers accept: zero, signs, the limits of
// double and of 32/64-bit integers, non-finite values, and large mode or frequency counts.
constexpr std::array<const char*, 30> kEdgeValues = {"0",
                                                     "-1",
                                                     "1",
                                                     "-0.0",
                                                     "0.0",
                                                     "1e308",
                                                     "-1e308",
                                                     "1e-308",
                                                     "5e-324",
                                                     "1.7976931348623157e308",
                                                     "2147483647",
                                                     "2147483648",
                                                     "-2147483649",
                                                     "4294967304",
                                                     "9223372036854775807",
                                                     "1e20",
                                                     "nan",
                                                     "inf",
                                                     "-inf",
                                                     "+inf",
                                                     "0.5",
                                                     "1e6",
                                                     "600",
                                                     "3",
                                                     "2",
                                                     "1.0000000001",
                                                     "0.999999999999",
                                                     "1e-12",
                                                     "100000",
                                                     "-1e-300"};

// Fragments that break TOML in different ways.
constexpr std::array<const char*, 16> kTokens = {"[",    "]",   "{",       "}",       "\"", "=",
                                                 ",",    "\n",  "#",       "[[",      "]]", "inf",
                                                 "true", "'''", "\\u0000", "\xff\xfe"};

using Operator = std::string (*)(std::string&, Random&, const std::vector<SeedScene>&);

std::string replace_span(std::string& text, Span span, const std::string& with) {
  const std::string old = text.substr(span.begin, span.end - span.begin);
  text.replace(span.begin, span.end - span.begin, with);
  return old;
}

std::string edge_number(std::string& text, Random& random, const std::vector<SeedScene>&) {
  const auto spans = number_spans(text);
  if (spans.empty()) return "no number";
  const std::string with = kEdgeValues[random.below(kEdgeValues.size())];
  return "number " + replace_span(text, spans[random.below(spans.size())], with) + " -> " + with;
}

std::string rescale_number(std::string& text, Random& random, const std::vector<SeedScene>&) {
  const auto spans = number_spans(text);
  if (spans.empty()) return "no number";
  const Span span = spans[random.below(spans.size())];
  const double value = std::strtod(text.substr(span.begin, span.end - span.begin).c_str(), nullptr);
  constexpr std::array<double, 9> kFactors = {1e-6, 1e-3, 0.1,  10.0,       1e3,
                                              1e6,  1e12, -1.0, 1.0 + 1e-12};
  const double factor = kFactors[random.below(kFactors.size())];
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.17g", value * factor);
  return "number " + replace_span(text, span, buffer) + " -> " + buffer;
}

std::string flip_byte(std::string& text, Random& random, const std::vector<SeedScene>&) {
  if (text.empty()) return "empty";
  const std::size_t at = random.below(text.size());
  const char with = static_cast<char>(random.one_in(4) ? random.below(256) : 32 + random.below(95));
  text[at] = with;
  return "byte " + std::to_string(at) + " -> " + std::to_string(static_cast<unsigned char>(with));
}

std::string delete_line(std::string& text, Random& random, const std::vector<SeedScene>&) {
  const auto lines = line_spans(text);
  if (lines.empty()) return "no line";
  const std::size_t k = random.below(lines.size());
  replace_span(text, lines[k], "");
  return "delete line " + std::to_string(k + 1);
}

std::string duplicate_line(std::string& text, Random& random, const std::vector<SeedScene>&) {
  const auto lines = line_spans(text);
  if (lines.empty()) return "no line";
  const std::size_t k = random.below(lines.size());
  text.insert(lines[k].end, text.substr(lines[k].begin, lines[k].end - lines[k].begin));
  return "duplicate line " + std::to_string(k + 1);
}

std::string swap_lines(std::string& text, Random& random, const std::vector<SeedScene>&) {
  const auto lines = line_spans(text);
  if (lines.size() < 2) return "one line";
  std::vector<std::string> parts;
  for (const Span& line : lines) parts.push_back(text.substr(line.begin, line.end - line.begin));
  const std::size_t i = random.below(parts.size());
  const std::size_t j = random.below(parts.size());
  std::swap(parts[i], parts[j]);
  text.clear();
  for (const auto& part : parts) text += part;
  return "swap lines " + std::to_string(i + 1) + ", " + std::to_string(j + 1);
}

std::string splice_line(std::string& text, Random& random, const std::vector<SeedScene>& corpus) {
  const SeedScene& donor = corpus[random.below(corpus.size())];
  const auto donor_lines = line_spans(donor.text);
  const auto lines = line_spans(text);
  if (donor_lines.empty()) return "empty donor";
  const Span from = donor_lines[random.below(donor_lines.size())];
  const std::size_t at = lines.empty() ? 0 : lines[random.below(lines.size())].begin;
  text.insert(at, donor.text.substr(from.begin, from.end - from.begin));
  return "splice a line of " + donor.file.filename().string();
}

std::string swap_string(std::string& text, Random& random, const std::vector<SeedScene>& corpus) {
  const auto spans = string_spans(text);
  const SeedScene& donor = corpus[random.below(corpus.size())];
  const auto donor_spans = string_spans(donor.text);
  if (spans.empty() || donor_spans.empty()) return "no string";
  const Span from = donor_spans[random.below(donor_spans.size())];
  const std::string with = donor.text.substr(from.begin, from.end - from.begin);
  return "string " + replace_span(text, spans[random.below(spans.size())], with) + " -> " + with;
}

std::string insert_token(std::string& text, Random& random, const std::vector<SeedScene>&) {
  const std::size_t at = random.below(text.size() + 1);
  const std::string token = kTokens[random.below(kTokens.size())];
  text.insert(at, token);
  return "insert token at " + std::to_string(at);
}

/// A number replaced by nested arrays or inline tables; sometimes thousands of levels deep (a
/// recursive-descent parser must not overflow its stack).
std::string deep_nesting(std::string& text, Random& random, const std::vector<SeedScene>&) {
  const auto spans = number_spans(text);
  if (spans.empty()) return "no number";
  const std::size_t depth = random.one_in(4) ? 1000 + random.below(20000) : 1 + random.below(64);
  const bool tables = random.one_in(2);
  std::string nested;
  for (std::size_t k = 0; k < depth; ++k) nested += tables ? "{a=" : "[";
  nested += "1";
  for (std::size_t k = 0; k < depth; ++k) nested += tables ? "}" : "]";
  replace_span(text, spans[random.below(spans.size())], nested);
  return std::string("nesting ") + (tables ? "tables" : "arrays") + " depth " +
         std::to_string(depth);
}

std::string truncate(std::string& text, Random& random, const std::vector<SeedScene>&) {
  const std::size_t at = random.below(text.size() + 1);
  text.resize(at);
  return "truncate at " + std::to_string(at);
}

// Numbers carry most of the meaning of a scene, so their operators are listed more than once.
constexpr std::array<Operator, 14> kOperators = {
    edge_number, edge_number,  edge_number,    rescale_number, rescale_number,
    flip_byte,   delete_line,  duplicate_line, swap_lines,     splice_line,
    swap_string, insert_token, deep_nesting,   truncate};

}  // namespace

Mutant mutate(const std::vector<SeedScene>& corpus, std::uint64_t seed, std::uint64_t iteration) {
  Random random(seed * 0x100000001b3ULL + iteration);
  Mutant mutant;
  mutant.seed_index = random.below(corpus.size());
  mutant.text = corpus[mutant.seed_index].text;
  const std::size_t count = 1 + random.below(4);
  for (std::size_t k = 0; k < count; ++k) {
    // Truncation and deep nesting only as the last step: after them other edits are mostly noise.
    Operator op = kOperators[random.below(kOperators.size())];
    if ((op == truncate || op == deep_nesting) && k + 1 < count) op = edge_number;
    mutant.recipe += (k ? "; " : "") + op(mutant.text, random, corpus);
  }
  return mutant;
}

}  // namespace catena::fuzz
