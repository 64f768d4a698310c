#include "solvers/internal/knob_reader.hpp"

#include <cmath>
#include <fmt/format.h>

#include "catena/core/error.hpp"

namespace catena::internal {

std::string KnobReader::key(const std::string& name) const {
  return fmt::format("[solvers.{}].{}", solver_, name);
}

const KnobValue* KnobReader::find(const std::string& name) {
  known_.insert(name);
  const auto it = knobs_.find(name);
  return it == knobs_.end() ? nullptr : &it->second;
}

double KnobReader::get_double(const std::string& name, double fallback) {
  const KnobValue* value = find(name);
  if (!value) return fallback;
  if (const auto* d = std::get_if<double>(value)) return *d;
  if (const auto* i = std::get_if<long>(value)) return static_cast<double>(*i);
  throw InvalidInput(fmt::format("{}: expected a number", key(name)));
}

long KnobReader::get_integer(const std::string& name, long fallback) {
  const KnobValue* value = find(name);
  if (!value) return fallback;
  if (const auto* i = std::get_if<long>(value)) return *i;
  if (const auto* d = std::get_if<double>(value); d && std::floor(*d) == *d && std::abs(*d) < 1e15)
    return static_cast<long>(*d);
  throw InvalidInput(fmt::format("{}: expected an integer", key(name)));
}

bool KnobReader::get_bool(const std::string& name, bool fallback) {
  const KnobValue* value = find(name);
  if (!value) return fallback;
  if (const auto* b = std::get_if<bool>(value)) return *b;
  throw InvalidInput(fmt::format("{}: expected true or false", key(name)));
}

std::string KnobReader::get_string(const std::string& name, const std::string& fallback) {
  const KnobValue* value = find(name);
  if (!value) return fallback;
  if (const auto* s = std::get_if<std::string>(value)) return *s;
  throw InvalidInput(fmt::format("{}: expected a string", key(name)));
}

void KnobReader::reject_unknown() const {
  for (const auto& [name, value] : knobs_) {
    if (!known_.count(name)) {
      std::string known_list;
      for (const auto& k : known_) {
        if (!known_list.empty()) known_list.append(", ");
        known_list.append(k);
      }
      throw InvalidInput(fmt::format("{}: unknown knob for solver '{}' (known: {})", key(name),
                                     solver_, known_list.empty() ? "none" : known_list));
    }
  }
}

}  // namespace catena::internal
