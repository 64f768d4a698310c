// SPDX-License-Identifier: MIT
// `catena report`: the comparison report (Markdown, self-contained HTML, CSV, figures) from the
// results JSON that `catena verify` wrote.
#include <fmt/format.h>

#include <filesystem>

#include "catena/core/error.hpp"
#include "catena/io/file_access.hpp"
#include "catena/io/report.hpp"
#include "cli/commands.hpp"

namespace catena::cli {
namespace {

struct ReportArguments {
  std::string from = "build/report/report.json";
  std::string out = "build/report";
  std::string data;
  std::string tools;
  // Debian's interpreter, where python3-matplotlib installs (a python3 earlier on PATH, e.g.
  // pyenv's, may not have it).
  std::string python = std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
  bool no_figures = false;
};

}  // namespace

void add_report_command(CLI::App& app, std::function<int()>& run) {
  auto arguments = std::make_shared<ReportArguments>();
  CLI::App* command = app.add_subcommand(
      "report",
      "Write the comparison report from a results JSON of `catena verify`: report.md,\n"
      "report.html (self-contained, figures embedded), data/*.csv and figures/*.png.\n"
      "Figures need python3 with matplotlib; without them the report says so. The validity\n"
      "maps (figures/validity-map-*.png) are drawn from the `catena sweep` outputs found in\n"
      "OUT/validity/<map>/points.csv (`make verify` writes them; see\n"
      "docs/explanation/validity-maps.md).");
  command->add_option("--from", arguments->from, "Results JSON written by `catena verify`")
      ->capture_default_str()
      ->check(non_empty_path());
  command
      ->add_option("--out", arguments->out,
                   std::string("Output directory. For each file written in it:") + kOutputPathHelp)
      ->capture_default_str()
      ->check(non_empty_path());
  command->add_option(
      "--data", arguments->data,
      "Data dir: figures.py, reference/published, benchmarks (default: share/catena next to\n"
      "the executable, else the build tree's)");
  command->add_option("--tools", arguments->tools,
                      "Directory of figures.py (default: the data dir)");
  command->add_option("--python", arguments->python, "Python interpreter for the figures")
      ->capture_default_str();
  command->add_flag("--no-figures", arguments->no_figures, "Skip the figures");
  command->callback([arguments, &run] {
    run = [arguments] {
      for (const char* name : {"report.md", "report.html"}) {
        check_not_an_input(std::filesystem::path(arguments->out) / name, {arguments->from},
                           "--out");
      }
      ReportOptions options;
      options.out_dir = arguments->out;
      options.data_dir = arguments->data;
      options.tools_dir = arguments->tools;
      options.python = arguments->python;
      options.figures = !arguments->no_figures;
      const ReportFiles files = write_report(arguments->from, options);
      fmt::print("wrote {} and {} ({} figures{}; {} source-discrepancy rows); data in {}\n",
                 files.markdown.string(), files.html.string(), files.figures,
                 files.figures_note.empty() ? "" : "; " + files.figures_note,
                 files.discrepancy_rows, files.data_dir.string());
      return 0;
    };
  });
}

}  // namespace catena::cli
