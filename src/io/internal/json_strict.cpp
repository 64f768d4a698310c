// SPDX-License-Identifier: MIT
#include "io/internal/json_strict.hpp"

#include <fmt/format.h>

#include <set>
#include <vector>

#include "catena/core/error.hpp"
#include "catena/io/file_access.hpp"

namespace catena::internal {

nlohmann::json parse_json_strict(const std::string& text, const std::string& file, int max_depth) {
  using nlohmann::json;
  // The keys seen so far in each open object (an array holds no keys: an empty set).
  std::vector<std::set<std::string>> keys;
  const auto callback = [&](int depth, json::parse_event_t event, json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start:
      case json::parse_event_t::array_start:
        // Checked before the level is built: the parser itself is iterative, but copying and
        // walking the tree later are not.
        if (depth >= max_depth)
          throw InvalidInput(fmt::format(
              "{}: nested deeper than {} levels (not a file Catena reads)", file, max_depth));
        keys.emplace_back();
        break;
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        if (!keys.empty()) keys.pop_back();
        break;
      case json::parse_event_t::key:
        if (!keys.empty() && !keys.back().insert(parsed.get<std::string>()).second)
          throw InvalidInput(
              fmt::format("{}: key '{}' given twice in one object (which one is meant?)", file,
                          path_text(std::filesystem::path(parsed.get<std::string>()))));
        break;
      case json::parse_event_t::value:
        break;
    }
    return true;
  };
  try {
    return json::parse(text, callback, true);
  } catch (const json::parse_error& error) {
    throw InvalidInput(
        fmt::format("{}: not valid JSON at byte {} (NaN is not JSON either)", file, error.byte));
  } catch (const json::out_of_range&) {
    // nlohmann's only out_of_range while parsing: a number literal beyond double's range (1e400).
    throw InvalidInput(fmt::format("{}: a number beyond the range of double (over 1.8e308)", file));
  }
}

}  // namespace catena::internal
