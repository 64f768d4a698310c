// What a user would otherwise do (issue 8): the fe solver's in-plane eigenproblem of the mooring
// line, exported as Matrix Market, solved three ways on the same matrices:
//   - Catena's solve (Spectra shift-invert on the banded LDLT, with the inertia proof),
//   - SciPy's eigsh in shift-invert mode (benchmarks/scipy_eigsh.py, run by this driver),
//   - a dense LAPACK-style solve (Eigen's GeneralizedSelfAdjointEigenSolver) where feasible.
// Prints the median wall times, the ratios and the largest eigenvalue difference.
//
//   build/benchmarks/catena_fe_vs_scipy [--python /usr/bin/python3] [--out DIR]
#include <Eigen/Dense>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <string>
#include <vector>

#include "catena/statics/elastic_catenary.hpp"
#include "solvers/internal/fe_eigen.hpp"

namespace {

using namespace catena;
using Clock = std::chrono::steady_clock;

void write_market(const std::filesystem::path& path, const internal::SparseMatrix& matrix) {
  std::ofstream out(path);
  out << "%%MatrixMarket matrix coordinate real general\n";
  out << matrix.rows() << ' ' << matrix.cols() << ' ' << matrix.nonZeros() << '\n';
  out.precision(17);
  for (int k = 0; k < matrix.outerSize(); ++k) {
    for (internal::SparseMatrix::InnerIterator it(matrix, k); it; ++it) {
      out << it.row() + 1 << ' ' << it.col() + 1 << ' ' << it.value() << '\n';
    }
  }
}

template <typename F>
double median_seconds(F&& work, int repeats) {
  std::vector<double> times;
  for (int i = 0; i < repeats; ++i) {
    const auto start = Clock::now();
    work();
    times.push_back(std::chrono::duration<double>(Clock::now() - start).count());
  }
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  std::string python = "/usr/bin/python3";
  std::filesystem::path out = std::filesystem::temp_directory_path() / "catena_fe_vs_scipy";
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string arg = argv[i];
    if (arg == "--python") python = argv[i + 1];
    else if (arg == "--out") out = argv[i + 1];
  }
  std::filesystem::create_directories(out);
  const std::filesystem::path script = std::filesystem::path(CATENA_BENCHMARK_DIR) / "scipy_eigsh.py";

  Problem problem;
  problem.cable = {1000.0, 1000.0, 5e8, 120.0, 80.0};
  problem.supports.b_m = Vec2(900.0, 300.0);
  const StaticSolution statics = solve_statics(problem);
  const int modes = 10;

  std::printf("mooring line, in-plane, %d lowest modes; median wall time of repeated solves\n", modes);
  std::printf("%8s %8s %12s %12s %12s %10s %10s %14s\n", "N", "dofs", "catena [ms]", "scipy [ms]", "dense [ms]",
              "scipy/cat", "dense/cat", "max rel diff");
  for (int N : {250, 500, 1000, 2000, 4000}) {
    const internal::FeChain chain = internal::solve_chain_statics(problem, statics, N, problem.cable.axial_stiffness_n);
    const internal::FeMatrices matrices = internal::assemble_inplane(chain);
    internal::FeEigenSolution ours;
    const double catena_s = median_seconds([&] { ours = internal::solve_lowest_modes(matrices, modes, 1e-10, 1000); }, 15);

    const auto k_path = out / fmt::format("K_{}.mtx", N);
    const auto m_path = out / fmt::format("M_{}.mtx", N);
    const auto w_path = out / fmt::format("scipy_{}.txt", N);
    write_market(k_path, matrices.stiffness);
    write_market(m_path, matrices.mass);
    double scipy_s = -1.0, scipy_diff = -1.0;
    const std::string command = fmt::format("{} {} {} {} {} {} > {} 2>&1", python, script.string(), k_path.string(),
                                            m_path.string(), modes, 15, w_path.string());
    if (std::system(command.c_str()) == 0) {
      std::ifstream result(w_path);
      result >> scipy_s;
      scipy_diff = 0.0;
      for (int i = 0; i < modes; ++i) {
        double lambda = 0.0;
        result >> lambda;
        scipy_diff = std::max(scipy_diff, std::abs(lambda - ours.eigenvalues[i]) / ours.eigenvalues[i]);
      }
    }

    double dense_s = -1.0, dense_diff = -1.0;
    if (matrices.stiffness.rows() <= 4000) {
      const Eigen::MatrixXd K(matrices.stiffness), M(matrices.mass);
      Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> dense;
      dense_s = median_seconds([&] { dense.compute(K, M, Eigen::EigenvaluesOnly); }, N <= 1000 ? 3 : 1);
      dense_diff = 0.0;
      for (int i = 0; i < modes; ++i) {
        dense_diff = std::max(dense_diff, std::abs(dense.eigenvalues()[i] - ours.eigenvalues[i]) / ours.eigenvalues[i]);
      }
    }
    std::printf("%8d %8ld %12.3f %12.3f %12.3f %10.1f %10.1f %7.1e/%7.1e\n", N,
                static_cast<long>(matrices.stiffness.rows()), catena_s * 1e3, scipy_s * 1e3, dense_s * 1e3,
                scipy_s > 0 ? scipy_s / catena_s : -1.0, dense_s > 0 ? dense_s / catena_s : -1.0, scipy_diff,
                dense_diff);
  }
  std::printf("(max rel diff: largest relative eigenvalue difference from Catena's, SciPy / dense)\n");
  return 0;
}
