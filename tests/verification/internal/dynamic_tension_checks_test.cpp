// SPDX-License-Identifier: MIT
// The dynamic-tension checks on hand-made results (docs/reference/verdicts.md, "Dynamic tension"):
// for each check a passing case and a failing one. The pair check holds two solvers' amplitude
// (regular) or standard deviation (irregular) at the fairlead, the anchor and along the line to the
// rules of verification/tolerances.toml; the fixed-point check fails a claimed convergence beyond
// the request's tolerance and warns on a declared non-convergence; drag-consistency recomputes the
// linearised drag from the reported motion (c_n = 8/(3 pi) 1/2 rho Cd d omega |x| for an
// out-of-plane motion, the model's definition); drag-anchor compares a drag-free fixed point with
// the same solver's damped forced response; the estimate check holds each solver's estimate to the
// actual difference; the mutation of one solver's tension by 1e-3 is caught. No solver is run.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>

#include "catena/io/findings_reader.hpp"
#include "catena/io/tolerance_reader.hpp"
#include "catena/verification/mutation.hpp"
#include "verification/internal/checks.hpp"

namespace catena {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kStations = 11;

// A suspended 76 mm studless chain, 1000 m, anchor 200 m below the fairlead: MoorPy/MoorDyn chain
// values (d = 1.8 x 0.076 m, Cd 2.4, CdAx 1.15), or linear damping only when `drag` is false.
SceneResult chain_result(bool drag, bool out_of_plane = false) {
  SceneResult result;
  result.scene.name = "dynamic-tension-test";
  result.scene.file = "verification/scenes/drag/dynamic-tension-test.toml";
  Problem& p = result.scene.problem;
  p.cable.length_m = 1000.0;
  p.cable.weight_n_per_m = 1074.0;
  p.cable.axial_stiffness_n = 5.8e8;
  p.cable.mass_kg_per_m = 126.0;
  p.cable.added_mass_kg_per_m = 15.07;
  if (drag) {
    p.cable.drag = MorisonDrag{1.8 * 0.076, 2.4, 1.15};
  } else {
    p.cable.damping.normal_n_s_per_m2 = 50.0;
    p.cable.damping.tangential_n_s_per_m2 = 5.0;
  }
  p.supports.a_m = Vec2(0.0, -200.0);
  p.supports.b_m = Vec2(950.0, 0.0);
  result.statics = solve_statics(p);
  result.groups = compute_dimensionless_groups(p, *result.statics);
  result.request.inplane_modes = 0;
  result.request.points = kStations;
  MotionRequest motion;
  motion.direction = out_of_plane ? ForcingDirection::OutOfPlane : ForcingDirection::GivenVector;
  motion.amplitude_m = 2.0;
  motion.periods_s = {10.0};
  result.request.motion = motion;
  return result;
}

// The 8/(3 pi) 1/2 rho Cd d factor of the chain (normal) and 8/(3 pi) 1/2 rho CdAx pi d
// (tangential) [kg/m^2].
double normal_factor() { return 8.0 / (3.0 * kPi) * 0.5 * 1025.0 * 2.4 * 1.8 * 0.076; }
double tangential_factor() { return 8.0 / (3.0 * kPi) * 0.5 * 1025.0 * 1.15 * kPi * 1.8 * 0.076; }

// A regular dynamic tension rising linearly from `anchor` to `fairlead` [N], with the motion and
// the linearised drag of an out-of-plane motion |v(s)| = 2 s / L consistent with each other.
DynamicTension regular(double period, double fairlead, double anchor) {
  DynamicTension t;
  t.period_s = period;
  t.omega_rad_s = 2.0 * kPi / period;
  t.s_m = Vector::LinSpaced(kStations, 0.0, 1000.0);
  t.mean_n = Vector::Constant(kStations, 3e5);
  t.amplitude_n = Vector::LinSpaced(kStations, anchor, fairlead);
  t.phase_deg = Vector::Zero(kStations);
  t.motion_m = Vector::LinSpaced(kStations, 0.0, 2.0);
  t.normal_damping_n_s_per_m2 = normal_factor() * t.omega_rad_s * t.motion_m;
  t.tangential_damping_n_s_per_m2 = Vector::Zero(kStations);
  t.fairlead = {1000.0, 3e5, fairlead, 0.0, -1.0, -1.0, -1.0};
  t.anchor = {0.0, 3e5, anchor, 0.0, -1.0, -1.0, -1.0};
  t.iterations = 14;
  t.residual = 3e-10;
  t.converged = true;
  t.relative_error_estimate = 2e-5;
  return t;
}

DynamicTension irregular(double fairlead_std, double anchor_std) {
  DynamicTension t = regular(0.0, 0.0, 0.0);
  t.irregular = true;
  t.period_s = t.omega_rad_s = 0.0;
  t.amplitude_n = t.phase_deg = Vector();
  t.std_n = Vector::LinSpaced(kStations, anchor_std, fairlead_std);
  t.fairlead.amplitude_n = t.anchor.amplitude_n = -1.0;
  t.fairlead.std_n = fairlead_std;
  t.anchor.std_n = anchor_std;
  return t;
}

SolverOutput output_with(const std::string& solver, std::vector<DynamicTension> tensions) {
  SolverOutput out;
  out.solver = solver;
  out.summary.solver = solver;
  out.summary.termination = Termination::Converged;
  out.dynamic_tension = std::move(tensions);
  return out;
}

std::vector<CheckResult> run_checks(const SceneResult& result) {
  static const ToleranceTable tolerances = builtin_tolerance_table();
  static const FindingsTable findings = builtin_findings_table();
  return internal::run_checks(result, tolerances, findings);
}

const CheckResult* find(const std::vector<CheckResult>& checks,
                        const std::string& kind,
                        const std::string& plane,
                        const std::string& compare = "") {
  for (const auto& c : checks) {
    if (c.check == kind && c.plane == plane && (compare.empty() || c.compare == compare)) return &c;
  }
  return nullptr;
}

std::optional<Verdict> verdict_of(const std::vector<CheckResult>& checks,
                                  const std::string& kind,
                                  const std::string& plane,
                                  const std::string& compare = "") {
  const CheckResult* check = find(checks, kind, plane, compare);
  return check ? std::optional(check->verdict) : std::nullopt;
}

TEST(DynamicTensionChecks, AgreeingSolversPassAtBothEndsAndAlongTheLine) {
  SceneResult r = chain_result(true);
  r.outputs = {output_with("fe", {regular(10.0, 2.0e5 * (1 + 3e-6), 5.0e4 * (1 - 2e-6))}),
               output_with("shooting", {regular(10.0, 2.0e5, 5.0e4)})};
  const auto checks = run_checks(r);
  for (const char* place : {"fairlead", "anchor", "stations"}) {
    const CheckResult* c = find(checks, "dynamic-tension", place);
    ASSERT_NE(c, nullptr) << place;
    EXPECT_EQ(c->verdict, Verdict::Pass) << place << ": " << c->detail;
    EXPECT_EQ(c->tolerance, 1e-4) << "fe's rule in verification/tolerances.toml";
    EXPECT_EQ(c->compare, "fe vs shooting");
  }
  EXPECT_NEAR(find(checks, "dynamic-tension", "fairlead")->measured, 3e-6 / (1 + 3e-6), 1e-15);
  EXPECT_NEAR(find(checks, "dynamic-tension", "anchor")->measured, 2e-6, 1e-15);
}

TEST(DynamicTensionChecks, AFairleadAmplitude1e3OffFails) {
  SceneResult r = chain_result(true);
  r.outputs = {output_with("fe", {regular(10.0, 2.0e5 * (1 + 1e-3), 5.0e4)}),
               output_with("shooting", {regular(10.0, 2.0e5, 5.0e4)})};
  const auto checks = run_checks(r);
  EXPECT_EQ(verdict_of(checks, "dynamic-tension", "fairlead"), Verdict::Fail);
  EXPECT_EQ(verdict_of(checks, "dynamic-tension", "anchor"), Verdict::Pass);
  // Along the line the max-norm sees the fairlead's difference (relative to the largest value).
  EXPECT_EQ(verdict_of(checks, "dynamic-tension", "stations"), Verdict::Fail);
}

TEST(DynamicTensionChecks, IrregularMotionComparesTheStandardDeviation) {
  SceneResult r = chain_result(true);
  r.request.motion->periods_s.clear();
  r.request.motion->amplitude_m = 0.0;
  r.request.motion->jonswap = JonswapSpectrum{6.0, 12.0, 3.3};
  r.outputs = {output_with("fe", {irregular(8.0e4, 2.0e4)}),
               output_with("shooting", {irregular(8.0e4 * (1 + 1e-7), 2.0e4)})};
  auto checks = run_checks(r);
  EXPECT_EQ(verdict_of(checks, "dynamic-tension", "fairlead"), Verdict::Pass);
  EXPECT_NE(find(checks, "dynamic-tension", "fairlead")->detail.find("sigma_T"), std::string::npos);
  r.outputs[1].dynamic_tension[0].anchor.std_n *= 1.01;
  checks = run_checks(r);
  EXPECT_EQ(verdict_of(checks, "dynamic-tension", "anchor"), Verdict::Fail);
}

TEST(DynamicTensionChecks, AnUnconvergedFixedPointIsAWarnNeverAFail) {
  SceneResult r = chain_result(true);
  DynamicTension stuck = regular(10.0, 2.0e5 * (1 + 1e-3), 5.0e4);
  stuck.converged = false;
  stuck.residual = 3e-3;
  stuck.diagnostic = "no fixed point: residual 0.003 > tolerance 1e-08 (stopped)";
  r.outputs = {output_with("fe", {stuck}), output_with("shooting", {regular(10.0, 2.0e5, 5.0e4)})};
  const auto checks = run_checks(r);
  EXPECT_EQ(verdict_of(checks, "dynamic-tension", "fairlead"), Verdict::Warn);
  const CheckResult* fp = find(checks, "fixed-point", "dynamic", "fe");
  ASSERT_NE(fp, nullptr);
  EXPECT_EQ(fp->verdict, Verdict::Warn);
  EXPECT_EQ(fp->measured, 3e-3);
  EXPECT_NE(fp->detail.find("not converged"), std::string::npos) << fp->detail;
  EXPECT_EQ(verdict_of(checks, "fixed-point", "dynamic", "shooting"), Verdict::Pass);
}

TEST(DynamicTensionChecks, ConvergedBeyondTheRequestsToleranceFails) {
  SceneResult r = chain_result(true);
  DynamicTension claimed = regular(10.0, 2.0e5, 5.0e4);
  claimed.residual = 1e-6;  // the request's tolerance is 1e-8
  r.outputs = {output_with("fe", {claimed})};
  const auto checks = run_checks(r);
  const CheckResult* fp = find(checks, "fixed-point", "dynamic", "fe");
  ASSERT_NE(fp, nullptr);
  EXPECT_EQ(fp->verdict, Verdict::Fail);
  EXPECT_EQ(fp->tolerance, 1e-8);
  EXPECT_NE(fp->detail.find("claimed converged"), std::string::npos) << fp->detail;
}

TEST(DynamicTensionChecks, TheReportedDragMustBeTheOneOfTheReportedMotion) {
  SceneResult r = chain_result(true, true);
  r.outputs = {output_with("fe", {regular(10.0, 2.0e5, 5.0e4)})};
  auto checks = run_checks(r);
  const CheckResult* c = find(checks, "drag-consistency", "dynamic");
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(c->verdict, Verdict::Pass) << c->detail;
  EXPECT_LT(c->measured, 1e-14);
  // A drag computed from a motion 1e-6 away, with a residual that claims 3e-10.
  r.outputs[0].dynamic_tension[0].normal_damping_n_s_per_m2 *= 1.0 + 1e-6;
  checks = run_checks(r);
  c = find(checks, "drag-consistency", "dynamic");
  EXPECT_EQ(c->verdict, Verdict::Fail);
  EXPECT_NEAR(c->measured, 1e-6, 1e-9);
}

TEST(DynamicTensionChecks, InPlaneDragConsistencyUsesBothComponents) {
  SceneResult r = chain_result(true);
  DynamicTension t = regular(10.0, 2.0e5, 5.0e4);
  // |w| = 0.8 |x|, |u| = 0.6 |x|: c_n from |w|, c_t from |u|.
  t.normal_damping_n_s_per_m2 = normal_factor() * t.omega_rad_s * 0.8 * t.motion_m;
  t.tangential_damping_n_s_per_m2 = tangential_factor() * t.omega_rad_s * 0.6 * t.motion_m;
  r.outputs = {output_with("fe", {t})};
  EXPECT_EQ(verdict_of(run_checks(r), "drag-consistency", "dynamic"), Verdict::Pass);
  r.outputs[0].dynamic_tension[0].tangential_damping_n_s_per_m2 *= 1.1;
  EXPECT_EQ(verdict_of(run_checks(r), "drag-consistency", "dynamic"), Verdict::Fail);
}

// Linear damping only: the forced response at omega = 2 pi / 10 s, amplitude 0.5 m, whose |tau|
// per metre must be the fixed point's amplitude per metre (2 m).
ForcedResponse forced_at(double omega, double scale) {
  ForcedResponse f;
  f.omega_rad_s = omega;
  f.s_m = Vector::LinSpaced(kStations, 0.0, 1000.0);
  f.tension_n = 0.25 * Vector::LinSpaced(kStations, 5.0e4, 2.0e5) * 0.6 * scale;
  f.tension_imag_n = 0.25 * Vector::LinSpaced(kStations, 5.0e4, 2.0e5) * 0.8 * scale;
  f.max_abs_tension_n = 0.25 * 2.0e5 * scale;
  f.relative_error_estimate = 1e-9;
  return f;
}

SceneResult anchor_scene(double forced_scale) {
  SceneResult r = chain_result(false);
  ForcedRequest forced;
  forced.end = CableEnd::B;
  forced.direction = ForcingDirection::GivenVector;
  forced.amplitude_m = 0.5;
  forced.omegas_rad_s = {0.3, 2.0 * kPi / 10.0};
  r.request.forced = forced;
  DynamicTension t = regular(10.0, 2.0e5, 5.0e4);
  t.iterations = 1;
  t.residual = 0.0;
  t.normal_damping_n_s_per_m2 = t.tangential_damping_n_s_per_m2 = Vector::Zero(kStations);
  SolverOutput out = output_with("shooting", {t});
  out.forced = {forced_at(0.3, 0.7), forced_at(2.0 * kPi / 10.0, forced_scale)};
  r.outputs = {out};
  return r;
}

TEST(DynamicTensionChecks, WithoutDragTheFixedPointIsTheDampedForcedResponse) {
  auto checks = run_checks(anchor_scene(1.0));
  const CheckResult* c = find(checks, "drag-anchor", "dynamic");
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(c->verdict, Verdict::Pass) << c->detail;
  EXPECT_LT(c->measured, 1e-15);
  EXPECT_EQ(c->tolerance, 2e-8);
  EXPECT_EQ(find(checks, "drag-consistency", "dynamic"), nullptr) << "no drag to recompute";
  checks = run_checks(anchor_scene(1.0 + 1e-6));
  EXPECT_EQ(verdict_of(checks, "drag-anchor", "dynamic"), Verdict::Fail);
}

TEST(DynamicTensionChecks, NoAnchorWithoutAForcedResponseAtTheSameFrequencyAndDirection) {
  SceneResult r = anchor_scene(1.0);
  r.request.forced->omegas_rad_s[1] *= 1.0 + 1e-6;
  EXPECT_EQ(find(run_checks(r), "drag-anchor", "dynamic"), nullptr);
  r = anchor_scene(1.0);
  r.request.forced->vector = Vec2(0.0, 1.0);
  EXPECT_EQ(find(run_checks(r), "drag-anchor", "dynamic"), nullptr);
}

TEST(DynamicTensionChecks, EachEstimateIsHeldToTheActualDifference) {
  SceneResult r = chain_result(true);
  DynamicTension fe = regular(10.0, 2.0e5 * (1 + 5e-5), 5.0e4);
  DynamicTension shooting = regular(10.0, 2.0e5, 5.0e4);
  shooting.relative_error_estimate = 1e-8;
  fe.relative_error_estimate = 1e-4;
  r.outputs = {output_with("fe", {fe}), output_with("shooting", {shooting})};
  auto checks = run_checks(r);
  EXPECT_EQ(verdict_of(checks, "dynamic-tension", "fairlead"), Verdict::Pass);
  EXPECT_EQ(verdict_of(checks, "estimate", "fairlead", "fe vs shooting"), Verdict::Pass);
  // An estimate of 1e-6 for a value 5e-5 off the reference is not an upper bound.
  r.outputs[0].dynamic_tension[0].relative_error_estimate = 1e-6;
  checks = run_checks(r);
  EXPECT_EQ(verdict_of(checks, "dynamic-tension", "fairlead"), Verdict::Pass);
  const CheckResult* c = find(checks, "estimate", "fairlead", "fe vs shooting");
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(c->verdict, Verdict::Fail);
  EXPECT_NE(c->detail.find("not an upper bound"), std::string::npos);
}

TEST(DynamicTensionChecks, BitIdenticalTensionsOverTheExcitationsAreAnIdentityFailure) {
  SceneResult r = chain_result(true);
  r.request.motion->periods_s = {8.0, 10.0};
  r.outputs = {output_with("fe", {regular(8.0, 1.5e5, 4e4), regular(10.0, 2e5, 5e4)}),
               output_with("shooting", {regular(8.0, 1.5e5, 4e4), regular(10.0, 2e5, 5e4)})};
  const auto checks = run_checks(r);
  EXPECT_EQ(verdict_of(checks, "identity", "fairlead"), Verdict::Fail);
  r.outputs[1].dynamic_tension[0].fairlead.amplitude_n *= 1 + 1e-12;
  EXPECT_FALSE(verdict_of(run_checks(r), "identity", "fairlead").has_value());
}

TEST(DynamicTensionChecks, AMutationOfOneSolversTensionIsCaught) {
  SceneResult r = chain_result(true);
  r.outputs = {output_with("fe", {regular(10.0, 2.0e5 * (1 + 3e-6), 5.0e4)}),
               output_with("shooting", {regular(10.0, 2.0e5, 5.0e4 * (1 + 1e-9))})};
  SceneRunOptions options;
  options.tolerances = builtin_tolerance_table();
  options.findings = builtin_findings_table();
  int made = 0;
  for (const MutationOutcome& o : mutate_scene(r, options)) {
    if (o.quantity != MutatedQuantity::DynamicTension) continue;
    ++made;
    EXPECT_TRUE(o.caught) << o.solver;
    EXPECT_TRUE(o.exact_witness);
    EXPECT_EQ(o.size, kDynamicTensionMutation);
    EXPECT_EQ(o.caught_by.rfind("dynamic-tension", 0), 0u) << o.caught_by;
  }
  EXPECT_EQ(made, 2);
  EXPECT_EQ(to_string(MutatedQuantity::DynamicTension), "dynamic-tension");
}

}  // namespace
}  // namespace catena
