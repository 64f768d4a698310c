// SPDX-License-Identifier: MIT
#pragma once
// TOML documents as JSON and back, for the tables compiled into the library
// (verification/tolerances.toml and findings.toml). toml11 takes 3.5-5 ms to parse those 15 KB,
// more than fe's whole solve in `catena solve`; so the build converts them to JSON once
// (src/tools/embed_tables.cpp) and the library rebuilds the same TOML document from the JSON,
// which nlohmann_json parses in well under a millisecond. The test
// tests/io/internal/toml_json_test.cpp holds the round trip to the TOML file's own document.

#include <nlohmann/json.hpp>
#include <toml.hpp>

namespace catena::internal {

/// The JSON form of a TOML document: tables are objects, arrays arrays; integers, floats,
/// booleans and strings keep their type. Dates and times have no JSON form: a ParseError.
nlohmann::json json_from_toml(const toml::value& value);

/// The TOML document of json_from_toml's output (equal to the original under toml::value's ==).
toml::value toml_from_json(const nlohmann::json& json);

}  // namespace catena::internal
