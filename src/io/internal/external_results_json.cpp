// SPDX-License-Identifier: MIT
#include "io/internal/external_results_json.hpp"

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "catena/core/error.hpp"
#include "catena/io/external_results_reader.hpp"
#include "catena/io/file_access.hpp"
#include "io/internal/json_strict.hpp"

namespace catena::internal {
namespace {

using nlohmann::json;

// One array: std::begin({"results"}) and std::end({"results"}) would be two different lists (the
// end of one is not reachable from the other: reading past it crashed on an unknown key).
const char* const kDocumentKeys[] = {"results"};
const char* const kItemKeys[] = {"plane",        "mode",        "resolution",
                                 "frequency_hz", "omega_rad_s", "shape"};
const char* const kShapeKeys[] = {"s_m", "u", "w", "v", "tension_n"};

double number_of(const json& value, const std::string& where) {
  if (!value.is_number())
    throw InvalidInput(fmt::format("{}: {} is not a number", where, value.dump()));
  return value.get<double>();
}

double number_at(const json& item, const std::string& key, const std::string& where) {
  return number_of(item.at(key), where + "." + key);
}

void reject_unknown_keys(const json& object,
                         const char* const* begin,
                         const char* const* end,
                         const std::string& where) {
  for (const auto& [key, value] : object.items()) {
    if (std::find(begin, end, key) == end)
      throw InvalidInput(fmt::format("{}: unknown key '{}'", where, key));
  }
}

Vector numbers_at(const json& shape, const std::string& key, const std::string& where) {
  if (!shape.contains(key)) return {};
  const json& array = shape.at(key);
  if (!array.is_array()) throw InvalidInput(fmt::format("{}.{}: not an array", where, key));
  Vector out(static_cast<Index>(array.size()));
  for (std::size_t i = 0; i < array.size(); ++i) {
    out[static_cast<Index>(i)] = number_of(array[i], fmt::format("{}.{}[{}]", where, key, i));
  }
  return out;
}

ExternalShape read_shape(const json& shape, const std::string& where) {
  if (!shape.is_object()) throw InvalidInput(fmt::format("{}: not an object", where));
  reject_unknown_keys(shape, std::begin(kShapeKeys), std::end(kShapeKeys), where);
  if (!shape.contains("s_m")) throw InvalidInput(fmt::format("{}: missing 's_m'", where));
  return {numbers_at(shape, "s_m", where), numbers_at(shape, "u", where),
          numbers_at(shape, "w", where), numbers_at(shape, "v", where),
          numbers_at(shape, "tension_n", where)};
}

ExternalMode read_item(const json& item, const std::string& where) {
  if (!item.is_object()) throw InvalidInput(fmt::format("{}: not an object", where));
  reject_unknown_keys(item, std::begin(kItemKeys), std::end(kItemKeys), where);
  for (const char* key : {"plane", "mode"}) {
    if (!item.contains(key)) throw InvalidInput(fmt::format("{}: missing '{}'", where, key));
  }
  const bool hz = item.contains("frequency_hz");
  if (hz == item.contains("omega_rad_s")) {
    throw InvalidInput(
        fmt::format("{}: give exactly one of 'frequency_hz' and 'omega_rad_s'", where));
  }
  ExternalMode mode;
  mode.origin = where;
  const json& plane = item.at("plane");
  const auto parsed = plane.is_string() ? parse_plane(plane.get<std::string>()) : std::nullopt;
  if (!parsed) {
    throw InvalidInput(
        fmt::format("{}.plane: {} is not a plane (in-plane, inplane, out-of-plane, outofplane)",
                    where, plane.dump()));
  }
  mode.plane = *parsed;
  mode.mode = mode_number(number_at(item, "mode", where), where + ".mode");
  if (item.contains("resolution")) mode.resolution = number_at(item, "resolution", where);
  const double value = number_at(item, hz ? "frequency_hz" : "omega_rad_s", where);
  mode.omega_rad_s = hz ? 2.0 * kPi * value : value;
  if (item.contains("shape")) mode.shape = read_shape(item.at("shape"), where + ".shape");
  return mode;
}

}  // namespace

std::vector<ExternalMode> read_external_results_json(const std::filesystem::path& path) {
  return parse_results_json_text(read_input_file(path, "results JSON", 64 * kMaxInputFileBytes),
                                 path_text(path));
}

std::vector<ExternalMode> parse_results_json_text(const std::string& text,
                                                  const std::string& file) {
  // A results file is 4 levels deep ({"results": [{"shape": {"u": [...]}}]}).
  constexpr int kMaxDepth = 32;
  const json document = parse_json_strict(text, file, kMaxDepth);
  const json* list = &document;
  if (document.is_object()) {
    reject_unknown_keys(document, std::begin(kDocumentKeys), std::end(kDocumentKeys), file);
    if (!document.contains("results"))
      throw InvalidInput(fmt::format("{}: missing 'results'", file));
    list = &document.at("results");
  }
  if (!list->is_array() || list->empty())
    throw InvalidInput(fmt::format("{}: 'results' must be a non-empty array", file));
  std::vector<ExternalMode> modes;
  for (std::size_t i = 0; i < list->size(); ++i) {
    modes.push_back(read_item(list->at(i), fmt::format("{}: results[{}]", file, i)));
  }
  return modes;
}

}  // namespace catena::internal
