// SPDX-License-Identifier: MIT
// The plane a time-series channel sees, from its name (docs/how-to/check-time-series.md,
// "Channels and planes"). In the linear theory about the static state in the x-z plane, the
// dynamic tension and the x and z motions belong to the in-plane modes, the y motion to the
// out-of-plane modes: the two planes decouple (docs/explanation/physics.md).
#include <algorithm>
#include <cctype>
#include <string>

#include "catena/verification/timeseries_check.hpp"
#include "core/internal/ascii_lower.hpp"

namespace catena {
namespace {

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// The quantity letters after the last digit: "l1n5px" -> "px", "seg3te" -> "te", "fairten1" ->
// "" (the digits end the name; its letters before them say what it is).
std::string quantity_suffix(const std::string& key) {
  const auto last_digit = key.find_last_of("0123456789");
  return last_digit == std::string::npos ? key : key.substr(last_digit + 1);
}

}  // namespace

std::optional<Plane> channel_plane(const std::string& name) {
  const std::string key = internal::ascii_lower(name);
  // Tensions: MoorDyn's FAIRTEN<k>, ANCHTEN<k>, L<k>N<j>TEN / T / TENA / TENB, a line file's
  // Seg<j>Te, v1's Fair<k>Ten, and the strains Seg<j>St / dSt, which follow the tension.
  if (key.rfind("fairten", 0) == 0 || key.rfind("anchten", 0) == 0) return Plane::InPlane;
  const std::string suffix = quantity_suffix(key);
  for (const char* tension : {"ten", "te", "t", "tena", "tenb", "ta", "tb", "st", "dst"}) {
    if (suffix == tension && suffix.size() < key.size()) return Plane::InPlane;
  }
  // Motions and forces along an axis: p (position), v (velocity), a (acceleration), u (wave
  // velocity), d (drag), f (force), b (seabed force), then x, y or z.
  if (suffix.size() == 2 && std::string("pvaudfb").find(suffix[0]) != std::string::npos &&
      suffix.size() < key.size()) {
    if (suffix[1] == 'x' || suffix[1] == 'z') return Plane::InPlane;
    if (suffix[1] == 'y') return Plane::OutOfPlane;
  }
  // Plain CSV names spelled out: "tension", "fairlead_tension_n", "x_m", "z", "y".
  if (key.find("tension") != std::string::npos) return Plane::InPlane;
  for (const char* in : {"x", "z", "x_m", "z_m"})
    if (key == in || ends_with(key, std::string("_") + in)) return Plane::InPlane;
  for (const char* out : {"y", "y_m"})
    if (key == out || ends_with(key, std::string("_") + out)) return Plane::OutOfPlane;
  return std::nullopt;
}

}  // namespace catena
