// `catena solvers`: the solvers, what they assume, and their knobs.
#include <fmt/format.h>

#include "catena/solvers/solver_registry.hpp"
#include "cli/commands.hpp"

namespace catena::cli {

void add_solvers_command(CLI::App& app, std::function<int()>& run) {
  CLI::App* command = app.add_subcommand(
      "solvers", "List the solvers, their methods and the knobs a scene may set in [solvers.<name>].");
  command->callback([&run] {
    run = [] {
      for (const auto& entry : solver_registry()) {
        fmt::print("{}: {}\n", entry.name, entry.description);
        for (const auto& knob : entry.knobs) fmt::print("    {:<14} {}\n", knob.name, knob.description);
      }
      return 0;
    };
  });
}

}  // namespace catena::cli
