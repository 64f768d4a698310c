// SPDX-License-Identifier: MIT
// Issue 33 end to end: a free decay of Catena's own damped lumped-mass model, integrated in time
// by SUNDIALS ARKODE (tests/verification/free_decay_support.hpp: no eigen solver involved),
// written as MoorDyn v2 writes its main output file, read back by read_time_series and identified
// by identify_modes. Compared with:
//  - fe's damped eigenvalues of the SAME mesh (fe with `elements` = N, no Richardson, no
//    refinement): the identified frequencies and damping ratios must match within the
//    identification's stated uncertainty. The precondition that fe's roots are this mesh's is
//    checked too, against a dense eigen solve (Eigen) of the same first-order matrix.
//  - Catena's continuum (the scene, through `catena check FILE --scene S --channel FAIRTEN1`): on
//    a mesh fine enough that its discretisation error (fe's same-mesh roots against the continuum)
//    is below a tenth of the identification's uncertainty, which sensor noise of 1 % of the range
//    sets; every mode present must "agree", exit 0.
// The scene: a 100 m damped line (normal and tangential drag c_n, c_t, Kelvin-Voigt axial damping
// c_a), written here; the decay is the release of a held fairlead offset.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <complex>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "catena/io/scene_reader.hpp"
#include "catena/io/timeseries_reader.hpp"
#include "catena/solvers/fe_solver.hpp"
#include "catena/statics/dimensionless_groups.hpp"
#include "catena/verification/modal_identification.hpp"
#include "cli/cli_support.hpp"
#include "verification/free_decay_support.hpp"

namespace catena {
namespace {

namespace fs = std::filesystem;

// A 100 m line between (0, 0) and (90, 40): sag about 7 m, first in-plane modes 0.2-1 Hz. Damping
// in all three coefficients (ratios of a few per cent), so that every one enters the comparison.
constexpr const char* kScene = R"(name = "free-decay-100m"
description = "100 m damped line for the free-decay end-to-end test"
[cable]
length = 100.0
weight = 150.0
EA = 2.0e7
mass = 20.0
added_mass = 10.0
damping_normal = 1.0
damping_tangential = 0.5
axial_damping = 1.5e5
a = [0.0, 0.0]
b = [90.0, 40.0]
[request]
inplane_modes = 6
outofplane_modes = 0
)";

// Mesh of the same-mesh comparison ("a few tens of elements").
constexpr int kElements = 30;
// 20 Hz, as a MoorDyn run's dtOut = 0.05 s would write, for 60 s (tens of periods of each mode).
constexpr double kSampleInterval = 0.05;
constexpr double kDuration = 60.0;
// ARKODE's relative tolerance: its global error on the frequencies is far below what the record's
// 8 printed digits let the identification resolve.
constexpr double kRtol = 1e-11;
// The held fairlead offset released at t = 0: 2 cm across the top element, in plane. Across it,
// so that the release does not stretch the top element (an offset along it of d would change its
// tension by EA d / l0 at once: 1 cm gives 60 kN here, more than its 26 kN). 2 cm is small
// against the line's non-linear scale (its sag, ~7 m), which the linear model does not need but a
// MoorDyn run would.
constexpr double kOffset = 0.02;
Vec2 release_offset(const test::LumpedModel& model) {
  const Vec2& t = model.chain.direction.back();
  return kOffset * Vec2(-t.y(), t.x());
}

fs::path temp_dir() {
  const fs::path dir = fs::temp_directory_path() / "catena_free_decay_test";
  fs::create_directories(dir);
  return dir;
}

struct Scenario {
  Problem problem;
  StaticSolution statics;
  DimensionlessGroups groups;
};

Scenario scenario() {
  Scenario s;
  s.problem = parse_scene_text(kScene, "free-decay-100m.toml").front().problem;
  s.statics = solve_statics(s.problem);
  s.groups = compute_dimensionless_groups(s.problem, s.statics);
  return s;
}

// fe's damped in-plane modes on exactly `elements` elements: no Richardson, no refinement.
std::vector<Mode> fe_same_mesh(const Scenario& s, int elements, int modes) {
  FeSolverOptions options;
  options.elements = elements;
  options.richardson = false;
  options.tolerance = 0.0;
  options.max_elements = elements;
  SolveRequest request;
  request.inplane_modes = modes;
  request.outofplane_modes = 0;
  const SolverOutput out = solve_fe(s.problem, s.statics, s.groups, request, options);
  EXPECT_TRUE(out.inplane.has_value());
  return out.inplane ? out.inplane->modes : std::vector<Mode>{};
}

// The underdamped eigenvalues (Im > 0, ascending) of the first-order matrix [0 I; -M^-1 K,
// -M^-1 C] of the same model, by Eigen's dense solver.
std::vector<std::complex<double>> dense_roots(const test::LumpedModel& model) {
  const Eigen::MatrixXd M(model.matrices.mass), K(model.matrices.stiffness),
      C(model.damping.damping);
  const Eigen::Index n = M.rows();
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  A.topRightCorner(n, n).setIdentity();
  const Eigen::MatrixXd Minv = M.inverse();
  A.bottomLeftCorner(n, n) = -Minv * K;
  A.bottomRightCorner(n, n) = -Minv * C;
  const Eigen::VectorXcd all = Eigen::EigenSolver<Eigen::MatrixXd>(A, false).eigenvalues();
  std::vector<std::complex<double>> roots;
  for (const auto& r : all) {
    if (r.imag() > 0.0) roots.push_back(r);
  }
  std::sort(roots.begin(), roots.end(), [](auto a, auto b) { return a.imag() < b.imag(); });
  return roots;
}

// The decay of an `elements` mesh, written to `name` in MoorDyn's format, with optional noise.
fs::path write_decay(
    const Scenario& s, int elements, const std::string& name, double noise, double rtol = kRtol) {
  const test::LumpedModel model = test::lumped_model(s.problem, s.statics, elements);
  const Vector x0 = test::released_offset(model, release_offset(model));
  test::DecayRecord record =
      test::integrate_decay(model, x0, s.problem.supports.a_m, {elements / 3, elements / 2},
                            kDuration, kSampleInterval, rtol);
  if (noise > 0.0) test::add_noise(record, noise, 33);
  const fs::path file = temp_dir() / name;
  test::write_moordyn_output(file, record);
  return file;
}

// The fe mode nearest in damped frequency.
const Mode& nearest(const std::vector<Mode>& modes, double frequency_hz) {
  return *std::min_element(modes.begin(), modes.end(), [&](const Mode& a, const Mode& b) {
    return std::abs(a.frequency_hz - frequency_hz) < std::abs(b.frequency_hz - frequency_hz);
  });
}

TEST(FreeDecayEndToEnd, FeRootsOnTheMeshAreTheDenseEigenvaluesOfTheSameMatrices) {
  // The precondition of the same-mesh comparison: fe without Richardson returns this mesh's roots.
  const Scenario s = scenario();
  const std::vector<Mode> fe = fe_same_mesh(s, kElements, 6);
  const auto roots = dense_roots(test::lumped_model(s.problem, s.statics, kElements));
  ASSERT_GE(fe.size(), 4u);
  for (std::size_t k = 0; k < fe.size(); ++k) {
    const std::complex<double> lambda(-fe[k].decay_rate_1_s, fe[k].omega_rad_s);
    // Dense QR on a 116 x 116 nonsymmetric matrix: backward stable, ~1e-13 on these roots.
    EXPECT_LT(std::abs(lambda - roots[k]) / std::abs(roots[k]), 1e-9)
        << "mode " << k + 1 << ": fe " << lambda << ", dense " << roots[k];
  }
}

TEST(FreeDecayEndToEnd, IntegratedDecayIsTheExactSolutionOfTheModel) {
  // The generator's check: the sampled positions against y(t) = V exp(Lambda t) V^-1 y0 of the
  // first-order system (Eigen's dense eigendecomposition; the roots are simple here).
  const Scenario s = scenario();
  const test::LumpedModel model = test::lumped_model(s.problem, s.statics, kElements);
  const Vector x0 = test::released_offset(model, release_offset(model));
  const int node = kElements / 3;
  const test::DecayRecord record = test::integrate_decay(model, x0, s.problem.supports.a_m, {node},
                                                         kDuration, kSampleInterval, kRtol);
  const Eigen::MatrixXd M(model.matrices.mass), K(model.matrices.stiffness),
      C(model.damping.damping);
  const Eigen::Index n = M.rows();
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  A.topRightCorner(n, n).setIdentity();
  A.bottomLeftCorner(n, n) = -M.inverse() * K;
  A.bottomRightCorner(n, n) = -M.inverse() * C;
  const Eigen::EigenSolver<Eigen::MatrixXd> eigen(A);
  const Eigen::MatrixXcd V = eigen.eigenvectors();
  Eigen::VectorXcd y0 = Eigen::VectorXcd::Zero(2 * n);
  y0.head(n) = x0.cast<std::complex<double>>();
  const Eigen::VectorXcd c = V.partialPivLu().solve(y0);
  const double scale = x0.cwiseAbs().maxCoeff();
  const Vec2 static_position = s.problem.supports.a_m + model.chain.node_offset_m[node];
  double worst = 0.0;
  for (Eigen::Index k = 0; k < record.time_s.size(); k += 100) {
    const Eigen::VectorXcd e = (eigen.eigenvalues() * record.time_s[k]).array().exp();
    const Eigen::VectorXd y = (V * (c.array() * e.array()).matrix()).real();
    worst =
        std::max({worst, std::abs(record.columns[1][k] - static_position.x() - y[2 * (node - 1)]),
                  std::abs(record.columns[2][k] - static_position.y() - y[2 * (node - 1) + 1])});
  }
  std::printf("  largest difference from the exact solution: %.2e of the offset\n", worst / scale);
  // The record's own rounding is far coarser: MoorDyn's 8 digits of a tension of ~26 kN are ~1e-3
  // N, ~5e-6 of its dynamic range here. The integration must stay well below that: 1e-7 of the
  // offset (measured: 2e-8 at rtol 1e-11 over the 60 s, ~50 periods of the highest mode).
  EXPECT_LT(worst / scale, 1e-7);
}

TEST(FreeDecayEndToEnd, TheRecordReadsBackAsAMoorDynFileWithItsChannelsAndUnits) {
  const Scenario s = scenario();
  const fs::path file = write_decay(s, kElements, "decay-readback.out", 0.0);
  const TimeSeries series = read_time_series(file);
  EXPECT_EQ(series.format, "moordyn");
  EXPECT_EQ(series.names,
            (std::vector<std::string>{"FAIRTEN1", "L1N10PX", "L1N10PZ", "L1N15PX", "L1N15PZ"}));
  EXPECT_EQ(series.units, (std::vector<std::string>{"N", "m", "m", "m", "m"}));
  ASSERT_EQ(series.time_s.size(), std::llround(kDuration / kSampleInterval) + 1);
  EXPECT_EQ(series.time_s[1], kSampleInterval);
  // The fairlead tension starts at the released state's: the static tension of the top element
  // plus what the held offset's displacement of its lower node stretches it by.
  const Vector& tension = series.channel("FAIRTEN1");
  EXPECT_GT(tension.maxCoeff() - tension.minCoeff(), 1.0);  // it rings [N]
}

TEST(FreeDecayEndToEnd, SameMeshDecayMatchesFesDampedRootsWithinTheIdentificationUncertainty) {
  const Scenario s = scenario();
  const TimeSeries series = read_time_series(write_decay(s, kElements, "decay-30.out", 0.0));
  // From the first sample after the release: at t = 0 the fairlead has just moved back.
  const Eigen::Index n = series.time_s.size() - 1;
  // The identification as `catena check` runs it (its default band, up to 0.8 Nyquist), against
  // fe's lowest 14 roots: the modes found below half a spacing above fe's highest are compared.
  const Identification id =
      identify_modes(series.time_s.tail(n), {Vector(series.channel("FAIRTEN1").tail(n))});
  const std::vector<Mode> fe = fe_same_mesh(s, kElements, 14);
  ASSERT_GE(fe.size(), 6u);
  const double top = 1.5 * fe.back().frequency_hz - 0.5 * fe[fe.size() - 2].frequency_hz;
  int compared = 0;
  std::vector<int> matched;
  for (const IdentifiedMode& mode : id.modes) {
    if (!mode.identifiable || mode.frequency_hz > top) continue;
    const Mode& reference = nearest(fe, mode.frequency_hz);
    EXPECT_EQ(std::count(matched.begin(), matched.end(), reference.index), 0)
        << "two identified modes near fe's mode " << reference.index;
    matched.push_back(reference.index);
    const double df = mode.frequency_hz - reference.frequency_hz;
    const double dz = mode.damping_ratio - reference.damping_ratio;
    std::printf(
        "  mode %d: f %.9f Hz, fe %.9f, rel. error %.1e, U %.1e; zeta %.6f, fe %.6f, error %.1e, "
        "U %.1e\n",
        reference.index, mode.frequency_hz, reference.frequency_hz, df / reference.frequency_hz,
        mode.frequency_uncertainty_hz / reference.frequency_hz, mode.damping_ratio,
        reference.damping_ratio, dz, mode.damping_ratio_uncertainty);
    EXPECT_LE(std::abs(df), mode.frequency_uncertainty_hz) << "mode " << reference.index;
    EXPECT_LE(std::abs(dz), mode.damping_ratio_uncertainty) << "mode " << reference.index;
    ++compared;
  }
  EXPECT_GE(compared, 3) << "modes identified: " << id.modes.size();
}

// The CLI run: N = 300, whose discretisation error (fe's same-mesh roots against Catena's
// continuum: 4.5e-5, 7.5e-5, 1.6e-4 relative on in-plane modes 1-3, more above) must be negligible
// against the identification's uncertainty. Sensor noise of 0.5 % of each channel's range sets that
// uncertainty (a noise-free record's 8 digits resolve the lumped model's own frequencies to ~1e-6
// and show its discretisation error as a disagreement, as a single coarse MoorDyn run would), and
// the band is modes 1-3 (--max-frequency half-way to mode 4): each must stand out of the noise in
// the fairlead tension for a verdict (at 1 % noise, mode 3 decays below it within a period and is
// not identifiable). The integration need only be far below the noise: rtol 1e-6.
constexpr int kFineElements = 300;
constexpr double kNoise = 5e-3;
constexpr double kFineRtol = 1e-6;
constexpr double kBandHz = 0.59;
// "Negligible": below a tenth of the uncertainty, so that the verdict is the identification's.
constexpr double kNegligible = 0.1;

TEST(FreeDecayEndToEnd, CatenaCheckAgreesOnAFineMeshDecayThroughTheCommandLine) {
  const Scenario s = scenario();
  const fs::path file = write_decay(s, kFineElements, "decay-fine.out", kNoise, kFineRtol);
  const fs::path scene = temp_dir() / "free-decay-100m.toml";
  std::ofstream(scene) << kScene;
  const fs::path json = temp_dir() / "check-fine.json";
  fs::remove(json);
  const testing::CliRun run = testing::run_cli(
      "check " + file.string() + " --scene " + scene.string() + " --channel FAIRTEN1 --window " +
      fmt::format("{}: --max-frequency {}", kSampleInterval, kBandHz) + " --json " + json.string());
  std::printf("%s", run.output.c_str());
  EXPECT_EQ(run.exit_code, 0) << run.output;
  std::ifstream in(json);
  ASSERT_TRUE(in.good()) << json;
  const nlohmann::json document = nlohmann::json::parse(in);
  const std::vector<Mode> fine = fe_same_mesh(s, kFineElements, 8);
  int agreeing = 0;
  for (const auto& mode : document.at("modes")) {
    if (mode.at("verdict") != "agrees") continue;
    ++agreeing;
    const int index = mode.at("mode").get<int>();
    ASSERT_LE(index, static_cast<int>(fine.size()));
    const Mode& lumped = fine[static_cast<std::size_t>(index - 1)];
    // The precondition: this mesh's own roots are within a tenth of the uncertainty of Catena's.
    const double f = mode.at("catena_frequency_hz").get<double>();
    const double zeta = mode.at("catena_damping_ratio").get<double>();
    EXPECT_LE(std::abs(lumped.frequency_hz - f),
              kNegligible * mode.at("frequency_uncertainty_hz").get<double>())
        << "mode " << index;
    EXPECT_LE(std::abs(lumped.damping_ratio - zeta),
              kNegligible * mode.at("damping_ratio_uncertainty").get<double>())
        << "mode " << index;
  }
  EXPECT_GE(agreeing, 2) << run.output;
}

}  // namespace
}  // namespace catena
