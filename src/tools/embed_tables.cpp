// SPDX-License-Identifier: MIT
// Build tool: converts the reviewed TOML tables compiled into the library into JSON, once, at
// build time, and writes them as C++ string constants (src/io/internal/toml_json.hpp says why).
//
//   catena_embed_tables OUTPUT.hpp NAME=FILE.toml [NAME=FILE.toml ...]
//
// A TOML syntax error stops the build with toml11's message naming the file and line. The header
// is written to a temporary file and renamed, never left half-written.
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <toml.hpp>

#include "io/internal/toml_json.hpp"

namespace {

// The raw string's delimiter; a table containing it could not be embedded as it is.
constexpr const char* kDelimiter = "catena_json";

std::string constant(const std::string& name, const std::string& path) {
  const std::string json = catena::internal::json_from_toml(toml::parse(path)).dump();
  if (json.find(std::string(")") + kDelimiter) != std::string::npos)
    throw std::runtime_error(path + ": contains the raw-string delimiter )" + kDelimiter);
  return "// From " + std::filesystem::path(path).filename().string() + ".\n" +
         "inline constexpr const char* " + name + " = R\"" + kDelimiter + "(" + json + ")" +
         kDelimiter + "\";\n";
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s OUTPUT.hpp NAME=FILE.toml [NAME=FILE.toml ...]\n", argv[0]);
    return 2;
  }
  try {
    std::string text =
        "// Generated at build time by src/tools/embed_tables.cpp: do not edit.\n#pragma once\n"
        "namespace catena::internal {\n";
    for (int i = 2; i < argc; ++i) {
      const std::string argument = argv[i];
      const auto equals = argument.find('=');
      if (equals == std::string::npos)
        throw std::runtime_error("expected NAME=FILE.toml, got " + argument);
      text += constant(argument.substr(0, equals), argument.substr(equals + 1));
    }
    text += "}  // namespace catena::internal\n";
    const std::filesystem::path output = argv[1], partial = output.string() + ".partial";
    std::ofstream out(partial, std::ios::binary);
    out << text;
    out.close();
    if (!out) throw std::runtime_error("cannot write " + partial.string());
    std::filesystem::rename(partial, output);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "catena_embed_tables: %s\n", e.what());
    return 1;
  }
  return 0;
}
