// SPDX-License-Identifier: MIT
// The shared fixed point of the drag linearisation (src/solvers/common/dynamic_tension.hpp), run
// through drive_solver() with a model whose fixed point has a closed form: every station responds
// on its own, x_j = A r_j / (1 + i omega c_n(s_j) / k0), tau_j = T1 x_j, with r_j = s_j / L. With
// c_n = a 1/2 rho Cd d V and V = omega |x| the fixed point solves V^2 (1 + beta^2 V^2) = b^2 with
// beta = omega a 1/2 rho Cd d / k0 and b = omega A r: V^2 = (sqrt(1 + 4 beta^2 b^2) - 1) / (2
// beta^2).
#include "solvers/common/dynamic_tension.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>

#include "catena/core/error.hpp"
#include "solvers/common/motion_spectrum.hpp"
#include "solvers/common/solver_driver.hpp"
#include "solvers/common/solver_test_support.hpp"

namespace catena {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kStiffness = 2.0e3;    // k0 [N/m per m of damping... per station]
constexpr double kTensionGain = 5.0e4;  // T1 [N/m]

class LocalNumerics final : public internal::SolverNumerics {
 public:
  explicit LocalNumerics(double length) : length_(length) {}
  bool handles_drag() const override { return true; }
  bool handles_damping() const override { return true; }
  ModalResult modes(Plane, int) override { return {}; }
  internal::ForcedOutcome forced_with_drag(const ForcedRequest& request,
                                           const internal::DragProfile& drag) override {
    ++calls;
    internal::ForcedOutcome out;
    const Vector& s = drag.stations();
    for (double omega : request.omegas_rad_s) {
      ForcedResponse r;
      r.omega_rad_s = omega;
      r.s_m = s;
      const Eigen::Index n = s.size();
      r.u = r.u_imag = r.v = Vector::Zero(n);
      r.w.resize(n), r.w_imag.resize(n), r.tension_n.resize(n), r.tension_imag_n.resize(n);
      for (Eigen::Index j = 0; j < n; ++j) {
        const double c = drag.normal_at(s[j], drag.segment_of(s[j]));
        const std::complex<double> x = request.amplitude_m * (s[j] / length_) /
                                       std::complex<double>(1.0, omega * c / kStiffness);
        r.w[j] = x.real(), r.w_imag[j] = x.imag();
        r.tension_n[j] = kTensionGain * x.real(), r.tension_imag_n[j] = kTensionGain * x.imag();
      }
      r.relative_error_estimate = 1e-12;
      out.responses.push_back(r);
    }
    out.summary.termination = Termination::Converged;
    return out;
  }
  int calls = 0;

 private:
  double length_;
};

Problem dragged_line() {
  Problem problem = testing::mooring_line(Vec2(900.0, 300.0));
  problem.cable.drag = {0.14, 2.4, 1.15};
  return problem;
}

double half_rho_cd_d(const Problem& p) {
  return 0.5 * p.environment.water_density_kg_per_m3 * p.cable.drag.normal *
         p.cable.drag.diameter_m;
}

TEST(DynamicTension, RegularFixedPointMatchesTheClosedForm) {
  testing::SolvedProblem solved = testing::prepare(dragged_line());
  SolveRequest request = testing::modes_request(0, 0);
  request.points = 11;
  MotionRequest motion;
  motion.amplitude_m = 3.0;
  motion.periods_s = {6.0, 12.0};
  request.motion = motion;
  const SolveContext context{solved.problem, solved.statics, solved.groups, request};
  LocalNumerics numerics(solved.problem.length_m());
  const SolverOutput out = internal::drive_solver("local", context, numerics);
  ASSERT_EQ(out.summary.termination, Termination::Converged) << out.summary.message;
  ASSERT_EQ(out.dynamic_tension.size(), 2u);
  for (const DynamicTension& t : out.dynamic_tension) {
    EXPECT_TRUE(t.converged);
    EXPECT_LE(t.residual, motion.tolerance);
    EXPECT_GT(t.iterations, 1);
    const double omega = 2.0 * kPi / t.period_s;
    const double beta = omega * 8.0 / (3.0 * kPi) * half_rho_cd_d(solved.problem) / kStiffness;
    for (Eigen::Index j = 0; j < t.s_m.size(); ++j) {
      const double b = omega * motion.amplitude_m * t.s_m[j] / solved.problem.length_m();
      const double V =
          std::sqrt((std::sqrt(1.0 + 4.0 * beta * beta * b * b) - 1.0) / (2.0 * beta * beta));
      const double expected = b == 0.0 ? 0.0 : kTensionGain * V / omega;
      EXPECT_NEAR(t.amplitude_n[j], expected, 1e-7 * kTensionGain * motion.amplitude_m) << j;
      EXPECT_NEAR(t.mean_n[j], solved.statics.tension_n(t.s_m[j]), 1e-9 * t.mean_n[j]);
    }
    EXPECT_DOUBLE_EQ(t.fairlead.amplitude_n, t.amplitude_n[t.s_m.size() - 1]);
    EXPECT_EQ(t.anchor.s_m, 0.0);
  }
}

TEST(DynamicTension, AnUnreachedFixedPointIsReportedWithItsResidual) {
  testing::SolvedProblem solved = testing::prepare(dragged_line());
  SolveRequest request = testing::modes_request(0, 0);
  request.points = 11;
  MotionRequest motion;
  motion.amplitude_m = 5.0;
  motion.periods_s = {8.0};
  motion.max_iterations = 2;
  request.motion = motion;
  const SolveContext context{solved.problem, solved.statics, solved.groups, request};
  LocalNumerics numerics(solved.problem.length_m());
  const SolverOutput out = internal::drive_solver("local", context, numerics);
  ASSERT_EQ(out.dynamic_tension.size(), 1u);
  const DynamicTension& t = out.dynamic_tension[0];
  EXPECT_FALSE(t.converged);
  EXPECT_GT(t.residual, motion.tolerance);
  EXPECT_NE(t.diagnostic.find("no fixed point"), std::string::npos) << t.diagnostic;
  EXPECT_NE(out.summary.termination, Termination::Converged);
}

TEST(DynamicTension, IrregularStdIsTheSpectralSumAtTheFixedPoint) {
  testing::SolvedProblem solved = testing::prepare(dragged_line());
  SolveRequest request = testing::modes_request(0, 0);
  request.points = 6;
  MotionRequest motion;
  motion.jonswap = JonswapSpectrum{6.0, 12.0, 3.3};
  motion.rao = RaoTable{{0.2, 0.5, 0.8, 1.2}, {1.0, 0.9, 0.5, 0.1}, {0, 0, 0, 0}, false};
  motion.frequencies = 40;
  request.motion = motion;
  const SolveContext context{solved.problem, solved.statics, solved.groups, request};
  LocalNumerics numerics(solved.problem.length_m());
  const SolverOutput out = internal::drive_solver("local", context, numerics);
  ASSERT_EQ(out.dynamic_tension.size(), 1u);
  const DynamicTension& t = out.dynamic_tension[0];
  ASSERT_TRUE(t.converged) << t.diagnostic;
  // Independently: at station j solve sigma^2 = sum q S w^2 b_j^2 / (1 + (w a h sigma / k0)^2)
  // for sigma by bisection, then the tension std from the same sum.
  const internal::MotionSpectrum spectrum = internal::motion_spectrum(motion);
  const double a = std::sqrt(8.0 / kPi), h = half_rho_cd_d(solved.problem);
  for (Eigen::Index j = 0; j < t.s_m.size(); ++j) {
    const double r = t.s_m[j] / solved.problem.length_m();
    auto sums = [&](double sigma, double* velocity2, double* tension2) {
      *velocity2 = *tension2 = 0.0;
      for (Eigen::Index k = 0; k < spectrum.omega_rad_s.size(); ++k) {
        const double w = spectrum.omega_rad_s[k];
        const double q = spectrum.weight_rad_s[k] * spectrum.density_m2_s_per_rad[k];
        const double g = 1.0 + std::pow(w * a * h * sigma / kStiffness, 2);
        *velocity2 += q * w * w * r * r / g;
        *tension2 += q * kTensionGain * kTensionGain * r * r / g;
      }
    };
    double low = 0.0, high = 100.0, v2 = 0.0, t2 = 0.0;
    for (int i = 0; i < 200; ++i) {
      const double mid = 0.5 * (low + high);
      sums(mid, &v2, &t2);
      (std::sqrt(v2) > mid ? low : high) = mid;
    }
    sums(0.5 * (low + high), &v2, &t2);
    EXPECT_NEAR(t.std_n[j], std::sqrt(t2), 1e-6 * kTensionGain) << j;
  }
  EXPECT_GT(t.fairlead.most_probable_max_n, t.fairlead.mean_n + 3.0 * t.fairlead.std_n);
  EXPECT_GT(t.fairlead.zero_upcrossing_period_s, 2.0 * kPi / 1.2);
  EXPECT_LT(t.fairlead.zero_upcrossing_period_s, 2.0 * kPi / 0.2);
}

TEST(DynamicTension, WithoutDragOneSolveIsTheAnswer) {
  Problem problem = testing::mooring_line(Vec2(900.0, 300.0));
  problem.cable.damping.normal_n_s_per_m2 = 10.0;
  testing::SolvedProblem solved = testing::prepare(problem);
  SolveRequest request = testing::modes_request(0, 0);
  request.points = 5;
  MotionRequest motion;
  motion.amplitude_m = 1.0;
  motion.periods_s = {10.0};
  request.motion = motion;
  const SolveContext context{solved.problem, solved.statics, solved.groups, request};
  LocalNumerics numerics(solved.problem.length_m());
  const SolverOutput out = internal::drive_solver("local", context, numerics);
  ASSERT_EQ(out.dynamic_tension.size(), 1u);
  EXPECT_TRUE(out.dynamic_tension[0].converged);
  EXPECT_EQ(out.dynamic_tension[0].iterations, 1);
  EXPECT_EQ(numerics.calls, 1);
  EXPECT_NEAR(out.dynamic_tension[0].fairlead.amplitude_n, kTensionGain, 1e-9 * kTensionGain);
}

TEST(DynamicTension, SolversWithoutDragDeclineThePart) {
  testing::SolvedProblem solved = testing::prepare(dragged_line());
  SolveRequest request = testing::modes_request(0, 0);
  MotionRequest motion;
  motion.amplitude_m = 1.0;
  motion.periods_s = {10.0};
  request.motion = motion;
  const SolveContext context{solved.problem, solved.statics, solved.groups, request};
  class NoDrag final : public internal::SolverNumerics {
    ModalResult modes(Plane, int) override { return {}; }
  } numerics;
  const SolverOutput out = internal::drive_solver("nodrag", context, numerics);
  EXPECT_TRUE(out.dynamic_tension.empty());
  EXPECT_EQ(out.summary.termination, Termination::NotApplicable) << out.summary.message;
}

TEST(MotionSpectrum, JonswapCarriesTheSignificantWaveHeight) {
  // m0 = Hs^2 / 16 (the normalisation A_gamma is Goda's fit: within ~2 % for gamma = 3.3).
  const JonswapSpectrum sea{6.0, 12.0, 3.3};
  const int n = 20000;
  double m0 = 0.0;
  for (int k = 1; k < n; ++k) m0 += internal::jonswap_density(sea, 0.0005 * k) * 0.0005;
  EXPECT_NEAR(4.0 * std::sqrt(m0), 6.0, 0.02 * 6.0);
  EXPECT_EQ(internal::jonswap_density(sea, 0.0), 0.0);
}

TEST(MotionSpectrum, RaoPerWaveHeightQuadruplesTheMotionSpectrum) {
  MotionRequest motion;
  motion.jonswap = JonswapSpectrum{4.0, 10.0, 2.0};
  motion.rao = RaoTable{{0.3, 1.5}, {0.5, 0.5}, {}, false};
  motion.frequencies = 16;
  const internal::MotionSpectrum amplitude = internal::motion_spectrum(motion);
  motion.rao->per_wave_height = true;
  const internal::MotionSpectrum height = internal::motion_spectrum(motion);
  for (Eigen::Index k = 0; k < amplitude.omega_rad_s.size(); ++k) {
    EXPECT_DOUBLE_EQ(height.density_m2_s_per_rad[k], 4.0 * amplitude.density_m2_s_per_rad[k]);
  }
  EXPECT_NEAR(amplitude.weight_rad_s.sum(), 1.2, 1e-14);
}

TEST(DragProfile, ElementMeansAreExactForThePiecewiseLinearScale) {
  Problem problem = dragged_line();
  Vector stations = Vector::LinSpaced(5, 0.0, 1000.0);
  internal::DragProfile profile(problem, stations, internal::DragLinearisation::Harmonic);
  profile.set_velocity_scales(Vector::LinSpaced(5, 0.0, 4.0), Vector::Constant(5, 2.0));
  const double factor = 8.0 / (3.0 * kPi) * half_rho_cd_d(problem);
  // V_n(s) = s / 250: the mean over [100, 600] is V_n(350) = 1.4.
  EXPECT_NEAR(profile.normal_mean(100.0, 600.0, 0), factor * 1.4, 1e-12 * factor);
  EXPECT_NEAR(profile.normal_at(600.0, 0), factor * 2.4, 1e-12 * factor);
  const double t_factor = 8.0 / (3.0 * kPi) * 0.5 * 1025.0 * 1.15 * kPi * 0.14;
  EXPECT_NEAR(profile.tangential_mean(0.0, 1000.0, 0), 2.0 * t_factor, 1e-12 * t_factor);
}

TEST(MotionRequest, BadInputNamesTheField) {
  auto message = [](const MotionRequest& m) {
    try {
      m.validate();
    } catch (const InvalidInput& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  MotionRequest regular;
  regular.amplitude_m = 1.0;
  regular.periods_s = {10.0, -1.0};
  EXPECT_NE(message(regular).find("request.motion.periods[1]"), std::string::npos);
  MotionRequest irregular;
  irregular.jonswap = JonswapSpectrum{0.0, 10.0, 3.3};
  irregular.rao = RaoTable{{0.2, 0.4}, {1, 1}, {0, 0}, false};
  EXPECT_NE(message(irregular).find("request.motion.jonswap.hs"), std::string::npos);
  irregular.jonswap->hs_m = 2.0;
  irregular.rao->omega_rad_s = {0.4, 0.2};
  EXPECT_NE(message(irregular).find("request.motion.rao.omega[1]"), std::string::npos);
  MotionRequest spectrum;
  spectrum.spectrum = SpectrumTable{{0.1, 0.2}, {1.0, -1.0}};
  EXPECT_NE(message(spectrum).find("request.motion.spectrum.density[1]"), std::string::npos);
}

}  // namespace
}  // namespace catena
