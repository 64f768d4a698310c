// SPDX-License-Identifier: MIT
// What a user sees (issue 17): `fe` on the SI mooring line through the public solve_fe, timed by
// the wall_time_s it reports (everything the solver does: discrete statics of every mesh,
// assembly, eigen solves with the error-estimate mesh, inertia proof, mode matching), against what
// a Python user would write: SciPy's eigsh in shift-invert mode (benchmarks/scipy_eigsh.py) on the
// same matrices as fe's mesh of N elements. Each repeat runs Catena once, in a fresh child process
// (cold memory, as `catena solve` would), then SciPy once (after one untimed warm-up call in its
// own process), alternating; the table holds medians. Rows:
//   - 10 modes in plane and out of plane at N = 1000 without Richardson (N/2 for the estimate);
//   - the default settings (N = 400 with Richardson: 400 and 800) against SciPy at N = 1000;
//   - 1, 6 and 20 modes per plane (N = 1000, no Richardson);
//   - `shooting` at its defaults (rtol 1e-10), 6 and 10 modes per plane, against the same SciPy
//     call: the exact answer against the approximate one;
//   - scaling: N = 1e3 ... 1e6 in plane, 10 modes, no Richardson: wall time, time per element and
//     the child's peak resident set.
//
//   build/catena_fe_vs_scipy [--python /usr/bin/python3] [--work DIR] [--results FILE]
//                            [--repeats R] [--max-elements N] [--tiny] [--help]
// --tiny: small meshes and one repeat, only to keep the driver working (the ctest). --help: the
// options (kUsage below); an unknown option or a bad value exits 2 before anything runs.
#include <fmt/format.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "catena/solvers/fe_solver.hpp"
#include "catena/solvers/shooting_solver.hpp"
#include "catena/statics/dimensionless_groups.hpp"
#include "catena/statics/elastic_catenary.hpp"
#include "solvers/fe/fe_operators.hpp"

namespace {

using namespace catena;
namespace fs = std::filesystem;

struct Options {
  std::string python = "/usr/bin/python3";
  fs::path work = fs::temp_directory_path() / "catena_fe_vs_scipy";
  fs::path results = fs::path(CATENA_BENCHMARK_DIR) / "results" / "fe-vs-scipy.txt";
  int repeats = 5;
  int max_elements = 1000000;
  bool tiny = false;
};

// The SI mooring line of verification/scenes/physical/mooring-line-900m.toml.
struct Scene {
  Problem problem;
  StaticSolution statics;
  DimensionlessGroups groups;
  Scene() {
    problem.cable = {1000.0, 1000.0, 5e8, 120.0, 80.0};
    problem.supports.b_m = Vec2(900.0, 300.0);
    statics = solve_statics(problem);
    groups = compute_dimensionless_groups(problem, statics);
  }
};

// One fe run as a user asks for it (or, with `shooting`, one shooting run at its defaults).
struct FeCase {
  int elements = 1000;
  bool richardson = false;
  Plane plane = Plane::InPlane;
  int modes = 10;
  bool shooting = false;
};

// What one Catena run reports: wall_time_s, frequencies, the child's peak resident set.
struct CatenaRun {
  double wall_s = -1.0;
  double peak_rss_mb = -1.0;
  std::vector<double> omegas;
};

CatenaRun run_in_process(const Scene& scene, const FeCase& fe) {
  SolveRequest request;
  request.inplane_modes = fe.plane == Plane::InPlane ? fe.modes : 0;
  request.outofplane_modes = fe.plane == Plane::OutOfPlane ? fe.modes : 0;
  FeSolverOptions options;
  options.elements = fe.elements;
  options.richardson = fe.richardson;
  const SolverOutput output =
      fe.shooting ? solve_shooting(scene.problem, scene.statics, scene.groups, request)
                  : solve_fe(scene.problem, scene.statics, scene.groups, request, options);
  CatenaRun run;
  run.wall_s = output.summary.wall_time_s;
  const auto& result = fe.plane == Plane::InPlane ? output.inplane : output.outofplane;
  if (result)
    for (const Mode& mode : result->modes) run.omegas.push_back(mode.omega_rad_s);
  return run;
}

// The run in a forked child (fresh pages, its own peak RSS); results come back through a pipe.
CatenaRun run_in_child(const Scene& scene, const FeCase& fe) {
  int fds[2];
  if (pipe(fds) != 0) return {};
  const pid_t pid = fork();
  if (pid == 0) {
    close(fds[0]);
    const CatenaRun run = run_in_process(scene, fe);
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    std::string text = fmt::format("{:.17g} {:.17g}", run.wall_s, usage.ru_maxrss / 1024.0);
    for (double omega : run.omegas) text += fmt::format(" {:.17g}", omega);
    if (write(fds[1], text.data(), text.size()) < 0) _exit(1);
    _exit(0);
  }
  close(fds[1]);
  std::string text;
  char buffer[4096];
  for (ssize_t got; (got = read(fds[0], buffer, sizeof buffer)) > 0;)
    text.append(buffer, static_cast<std::size_t>(got));
  close(fds[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  CatenaRun run;
  std::istringstream in(text);
  in >> run.wall_s >> run.peak_rss_mb;
  for (double omega; in >> omega;) run.omegas.push_back(omega);
  return run;
}

void write_market(const fs::path& path, const internal::SparseMatrix& matrix) {
  std::ofstream out(path);
  out << "%%MatrixMarket matrix coordinate real general\n";
  out << matrix.rows() << ' ' << matrix.cols() << ' ' << matrix.nonZeros() << '\n';
  out.precision(17);
  for (int k = 0; k < matrix.outerSize(); ++k)
    for (internal::SparseMatrix::InnerIterator it(matrix, k); it; ++it)
      out << it.row() + 1 << ' ' << it.col() + 1 << ' ' << it.value() << '\n';
}

// fe's matrices of the mesh of `elements` elements, exported for SciPy; returns (K, M) paths.
std::pair<fs::path, fs::path> export_matrices(const Options& options,
                                              const Scene& scene,
                                              int elements,
                                              Plane plane) {
  const Problem& problem = scene.problem;
  const internal::FeChain chain = internal::solve_chain_statics(problem, scene.statics, elements,
                                                                problem.cable.axial_stiffness_n);
  const internal::FeMatrices matrices = internal::assemble(plane, chain);
  const std::string tag = fmt::format("{}_{}", plane == Plane::InPlane ? "in" : "out", elements);
  const fs::path k_path = options.work / ("K_" + tag + ".mtx"),
                 m_path = options.work / ("M_" + tag + ".mtx");
  write_market(k_path, matrices.stiffness);
  write_market(m_path, matrices.mass);
  return {k_path, m_path};
}

// One timed eigsh call (after one warm-up) on the exported matrices: seconds and omegas
// (-1 and none when Python or SciPy is missing).
std::pair<double, std::vector<double>> run_scipy(const Options& options,
                                                 const std::pair<fs::path, fs::path>& km,
                                                 int modes) {
  const fs::path script = fs::path(CATENA_BENCHMARK_DIR) / "scipy_eigsh.py";
  const fs::path output = options.work / "scipy.txt";
  const std::string command =
      fmt::format("{} {} {} {} {} 1 1 > {} 2>&1", options.python, script.string(),
                  km.first.string(), km.second.string(), modes, output.string());
  if (std::system(command.c_str()) != 0) return {-1.0, {}};
  std::ifstream in(output);
  double seconds = -1.0;
  in >> seconds;
  std::vector<double> omegas;
  for (double lambda; in >> lambda;) omegas.push_back(std::sqrt(std::max(0.0, lambda)));
  return {seconds, omegas};
}

double median(std::vector<double> values) {
  if (values.empty()) return -1.0;
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

double max_relative_difference(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.empty() || a.size() != b.size()) return -1.0;
  double worst = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i)
    worst = std::max(worst, std::abs(a[i] - b[i]) / std::abs(b[i]));
  return worst;
}

// One row of the comparison: `repeats` alternations of Catena (case `fe`) and SciPy on the
// matrices of the mesh `scipy_elements`.
std::string comparison_row(const Options& options,
                           const Scene& scene,
                           const std::string& label,
                           const FeCase& fe,
                           int scipy_elements) {
  const auto km = export_matrices(options, scene, scipy_elements, fe.plane);
  std::vector<double> catena_s, scipy_s;
  CatenaRun last;
  std::vector<double> scipy_omegas;
  for (int r = 0; r < options.repeats; ++r) {
    last = run_in_child(scene, fe);
    catena_s.push_back(last.wall_s);
    auto [seconds, omegas] = run_scipy(options, km, fe.modes);
    if (seconds >= 0.0) scipy_s.push_back(seconds);
    scipy_omegas = omegas;
  }
  const double c = median(catena_s), s = median(scipy_s);
  return fmt::format("{:<40} {:>8} {:>10.3f} {:>10.3f} {:>9.2f} {:>12.1e}\n", label, fe.modes,
                     1e3 * c, 1e3 * s, s > 0.0 ? s / c : -1.0,
                     max_relative_difference(last.omegas, scipy_omegas));
}

}  // namespace

namespace {

constexpr const char* kUsage =
    R"(catena_fe_vs_scipy: fe (and shooting) on the SI mooring line against SciPy's eigsh
(shift-invert) on the same matrices; Catena in a fresh process per run, medians (issue 17).
Takes about a minute on 2 cores, most of it the N = 1e6 scaling row.

  --python PATH        Python 3 with numpy and scipy (default /usr/bin/python3)
  --work DIR           scratch directory for the matrices handed to SciPy (default: the
                       system's temporary directory / catena_fe_vs_scipy)
  --results FILE       the table is written here, replacing the file (default
                       benchmarks/results/fe-vs-scipy.txt in the source tree)
  --repeats R          runs per row, R >= 1; the table holds medians (default 5)
  --max-elements N     largest mesh of the scaling table, N >= 1000 (default 1000000)
  --tiny               small meshes and one repeat: only keeps the driver working (the ctest)
  --help               this text
)";

// Exit 2 with the reason and the usage (bad command line); never a half-run benchmark.
[[noreturn]] void usage_error(const std::string& reason) {
  std::fprintf(stderr, "catena_fe_vs_scipy: %s\n\n%s", reason.c_str(), kUsage);
  std::exit(2);
}

int positive_integer(const std::string& option, const char* text, int smallest) {
  char* end = nullptr;
  const long value = std::strtol(text, &end, 10);
  if (end == text || *end != '\0' || value < smallest || value > 100000000)
    usage_error(fmt::format("{} wants an integer >= {}, got '{}'", option, smallest, text));
  return static_cast<int>(value);
}

Options parse(int argc, char** argv) {
  Options options;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool valued = arg == "--python" || arg == "--work" || arg == "--results" ||
                        arg == "--repeats" || arg == "--max-elements";
    if (valued && i + 1 >= argc) usage_error(arg + " needs a value");
    if (arg == "--help" || arg == "-h") {
      std::fputs(kUsage, stdout);
      std::exit(0);
    } else if (arg == "--tiny") {
      options.tiny = true;
    } else if (arg == "--python") {
      options.python = argv[++i];
    } else if (arg == "--work") {
      options.work = argv[++i];
    } else if (arg == "--results") {
      options.results = argv[++i];
    } else if (arg == "--repeats") {
      options.repeats = positive_integer(arg, argv[++i], 1);
    } else if (arg == "--max-elements") {
      options.max_elements = positive_integer(arg, argv[++i], 1000);
    } else {
      usage_error("unknown option '" + arg + "'");
    }
  }
  if (options.tiny) {
    options.repeats = 1;
    options.max_elements = 80;
  }
  return options;
}

std::string machine_line() {
  std::ifstream load("/proc/loadavg");
  std::string one, five;
  load >> one >> five;
  const std::time_t now = std::time(nullptr);
  char date[32];
  std::strftime(date, sizeof date, "%Y-%m-%d %H:%M", std::localtime(&now));
  return fmt::format("# {}, {} hardware threads, load average {} (1 min) {} (5 min) at the start\n",
                     date, sysconf(_SC_NPROCESSORS_ONLN), one, five);
}

std::string comparison_table(const Options& options, const Scene& scene) {
  const int N = options.tiny ? 40 : 1000, N_default = options.tiny ? 20 : 400;
  std::string out = fmt::format(
      "mooring line (L = 1000 m, EA = 5e8 N); Catena: solve_fe's (solve_shooting's) wall_time_s, "
      "in a fresh process; SciPy: eigsh\n"
      "shift-invert (sigma = 0, tol 1e-10) on the matrices of fe's mesh of N = {} elements; "
      "medians of {}\n"
      "alternating runs. diff: largest relative difference of the frequencies (Catena's are "
      "extrapolated in\n"
      "the Richardson row, so there it is Catena's accuracy gain over the N = {} mesh)\n",
      N, options.repeats, N);
  out += fmt::format("{:<40} {:>8} {:>10} {:>10} {:>9} {:>12}\n", "case", "modes", "catena ms",
                     "scipy ms", "scipy/cat", "diff");
  for (Plane plane : {Plane::InPlane, Plane::OutOfPlane}) {
    const std::string name = plane == Plane::InPlane ? "in-plane" : "out-of-plane";
    out += comparison_row(options, scene, fmt::format("{}, N = {}, no Richardson", name, N),
                          {N, false, plane, 10}, N);
  }
  out += comparison_row(options, scene,
                        fmt::format("in-plane, default (N = {} + Richardson)", N_default),
                        {N_default, true, Plane::InPlane, 10}, N);
  for (Plane plane : {Plane::InPlane, Plane::OutOfPlane})
    for (int modes : {1, 6, 20})
      out += comparison_row(options, scene,
                            fmt::format("{}, N = {}, no Richardson",
                                        plane == Plane::InPlane ? "in-plane" : "out-of-plane", N),
                            {N, false, plane, modes}, N);
  for (Plane plane : {Plane::InPlane, Plane::OutOfPlane})
    for (int modes : {6, 10})
      out += comparison_row(options, scene,
                            fmt::format("{}, shooting (rtol 1e-10)",
                                        plane == Plane::InPlane ? "in-plane" : "out-of-plane"),
                            {N, false, plane, modes, true}, N);
  return out;
}

std::string scaling_table(const Options& options, const Scene& scene) {
  std::string out =
      "\nscaling: in-plane, 10 modes, no Richardson (meshes N/2 and N), one fresh process per "
      "run;\n"
      "median of the repeats up to N = 1e4, one run above\n";
  out += fmt::format("{:>10} {:>12} {:>14} {:>14}\n", "N", "wall [s]", "us / element",
                     "peak RSS [MB]");
  for (int N = options.tiny ? 40 : 1000; N <= options.max_elements; N *= options.tiny ? 2 : 10) {
    std::vector<double> seconds;
    double rss = 0.0;
    const int repeats = N <= 10000 ? options.repeats : 1;
    for (int r = 0; r < repeats; ++r) {
      const CatenaRun run = run_in_child(scene, {N, false, Plane::InPlane, 10});
      seconds.push_back(run.wall_s);
      rss = std::max(rss, run.peak_rss_mb);
    }
    const double wall = median(seconds);
    out += fmt::format("{:>10} {:>12.4f} {:>14.2f} {:>14.1f}\n", N, wall, 1e6 * wall / N, rss);
    std::fputs(out.c_str() + out.rfind('\n', out.size() - 2) + 1, stdout);
    std::fflush(stdout);
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  const Options options = parse(argc, argv);
  fs::create_directories(options.work);
  const Scene scene;
  std::string table = machine_line();
  table += comparison_table(options, scene);
  std::fputs(table.c_str(), stdout);
  std::fflush(stdout);
  table += scaling_table(options, scene);
  if (!options.results.parent_path().empty()) fs::create_directories(options.results.parent_path());
  std::ofstream(options.results) << table;
  std::printf("wrote %s\n", options.results.string().c_str());
  return 0;
}
