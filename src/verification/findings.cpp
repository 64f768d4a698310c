// SPDX-License-Identifier: MIT
#include "catena/verification/findings.hpp"

namespace catena {

const Finding* FindingsTable::find(const std::string& scene,
                                   const std::string& quantity,
                                   int mode,
                                   const std::string& solver) const {
  for (const auto& f : findings_) {
    if (f.scene == scene && f.quantity == quantity && f.mode == mode && f.solver == solver)
      return &f;
  }
  return nullptr;
}

}  // namespace catena
