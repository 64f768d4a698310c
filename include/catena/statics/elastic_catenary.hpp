// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Statics of a uniform elastic (or inextensible) cable hanging between two supports
/// (docs/explanation/physics.md): the elastic catenary.
///
/// The internal force at unstretched arc length s is F(s) = (H, V(s)), V(s) = V_A + W0 s, with
/// H >= 0 constant; tension T = |F|, unit tangent t = F/T, in-plane normal n = (-V, H)/T, static
/// strain e = T/EA and r'(s) = (1 + e) t. Closed forms (written here in forms that do not lose
/// digits for taut cables, where H/W0 is large):
///
///     x(s) = H s / EA + (H/W0) [asinh(V(s)/H) - asinh(V_A/H)]
///     z(s) = (V_A s + W0 s^2/2) / EA + (T(s) - T_A) / W0
///
/// EA = inf gives the inextensible catenary; H = 0 is a vertical cable (allowed when it is taut,
/// V > 0 along its whole length).

#include <optional>
#include <string>
#include <vector>

#include "catena/core/types.hpp"
#include "catena/models/cable.hpp"
#include "catena/models/seabed.hpp"

namespace catena {

/// Options of the (H, V_A) Newton solve.
struct StaticsOptions {
  /// Converged when |r(L) - (B - A)| <= relative_tolerance * max(L, |B - A|). In (0, 1e-3].
  double relative_tolerance = 1e-14;
  /// Newton iterations before giving up. >= 1.
  int max_iterations = 200;

  /// Throws InvalidInput naming the field and the constraint.
  void validate() const;
};

/// One piece of a general line's statics: the part of one segment between consecutive joints or
/// point attachments, a closed-form elastic catenary (a straight bar when its weight is zero).
struct StaticPiece {
  /// The segment's section, with length_m = the piece's unstretched length.
  CableProperties section;
  /// Index of the segment in Line::segments.
  std::size_t segment = 0;
  /// Unstretched arc length of the piece's start [m].
  double s_begin_m = 0.0;
  /// Vertical force just after the start (after any point weight there) [N].
  double vertical_begin_n = 0.0;
  /// Offset of the start from support a [m] and stretched length of [0, s_begin] [m].
  Vec2 offset_begin_m = Vec2::Zero();
  double stretched_begin_m = 0.0;
  /// True for a piece resting on the seabed (docs/explanation/physics.md, "Seabed contact"):
  /// straight and horizontal, V = 0, tension set by friction (grounded_tension_begin_n).
  bool grounded = false;
  /// Grounded pieces: the tension at the start before clipping at 0 [N]; the tension along the
  /// piece is max(this + grounded_tension_slope_n_per_m (s - s_begin), 0). On the stretch from an
  /// anchor lying on the seabed: H - C_B (weight resting on the seabed between the start and the
  /// touchdown point). Unused (0) on suspended pieces.
  double grounded_tension_begin_n = 0.0;
  /// Grounded pieces: d(tension)/ds [N/m]: C_B w on the stretch from an anchor lying on the seabed
  /// (friction holds it toward the anchor); 0 on a stretch between two suspended parts, where the
  /// friction is not mobilised and the tension is the suspended parts' H
  /// (docs/explanation/physics.md, "Seabed contact"). Unused (0) on suspended pieces.
  double grounded_tension_slope_n_per_m = 0.0;
  /// Grounded pieces of a slack line (H = 0, docs/explanation/physics.md, "Seabed contact"): the
  /// part of the grounded length that does not fit between the ends' feet. It lies in a heap at
  /// its start, whose shape on the seabed the statics does not define: its offset stays at
  /// offset_begin_m along it, its stretched length grows as ds (zero tension). False elsewhere.
  bool slack_heap = false;
};

/// One stretch of a line resting on the seabed: unstretched arc lengths [m], s_begin < s_end.
struct ContactInterval {
  double s_begin_m = 0.0;
  double s_end_m = 0.0;
};

/// The static state of the cable: the two end-force unknowns plus closed forms at any s.
/// Every function of s takes the unstretched arc length s in [0, L] [m].
///
/// A general line (docs/explanation/physics.md, "General lines") is the same state piecewise: V
/// jumps by the weight of each point attachment, so at a point every function of s gives the value
/// just beyond it (toward b; the `_before_` variants give the value on the side of a).
class StaticSolution {
 public:
  StaticSolution() = default;
  /// The equilibrium with horizontal force `H` [N] and vertical force `V_A` [N] at support `a`.
  StaticSolution(const CableProperties& cable, const Vec2& a_m, double H, double V_A);
  /// The equilibrium of a general line (validated) with forces (H, V_A) at support `a`.
  StaticSolution(const Line& line, const Vec2& a_m, double H, double V_A);
  /// The equilibrium of a line (validated) on `seabed` (docs/explanation/physics.md, "Seabed
  /// contact"): the grounded length L_g = `grounded_length_m` from A rests on the seabed; the rest
  /// is suspended with horizontal force `H` [N], leaving the seabed tangentially (V = 0 at s =
  /// L_g). The grounded pieces come first, cut at joints, points and where the friction tension
  /// reaches 0.
  StaticSolution(
      const Line& line, const Vec2& a_m, const Seabed& seabed, double H, double grounded_length_m);
  /// The equilibrium of a line (validated) on `seabed` given as its pieces in order from A
  /// (offsets relative to `a_m`), with any number of grounded stretches anywhere along it (general
  /// seabed contact: both ends may be above the seabed). `H` is the suspended parts' horizontal
  /// force [N]. The pieces must chain (each starts where the previous ends) and cover [0, L].
  StaticSolution(const Line& line,
                 const Vec2& a_m,
                 const Seabed& seabed,
                 double H,
                 std::vector<StaticPiece> pieces);

  /// Records the seabed under a solution that does not touch it (L_g = 0; nothing else changes).
  void set_seabed_without_contact(const Seabed& seabed) { seabed_ = seabed; }
  /// True when the problem had a seabed (touching it or not).
  bool has_seabed() const { return seabed_.has_value(); }
  /// The seabed (requires has_seabed()).
  const Seabed& seabed() const { return *seabed_; }
  /// True when some length rests on the seabed (L_g > 0).
  bool has_contact() const { return grounded_length_m_ > 0.0; }
  /// Total unstretched length L_g resting on the seabed [m] (all contact intervals); 0 without
  /// contact. With the anchor on the seabed and one touchdown, the grounded length from A.
  double grounded_length_m() const { return grounded_length_m_; }
  /// The stretches resting on the seabed, in order of s (merged across piece cuts); empty without
  /// contact.
  std::vector<ContactInterval> contact_intervals() const;
  /// Unstretched length lying in a heap on the seabed [m]: the part of a slack line's (H = 0)
  /// grounded length that does not fit in the span (StaticPiece::slack_heap); 0 otherwise.
  double slack_length_m() const;
  /// True when s lies on a stretch resting on the seabed (at a cut: the piece toward B).
  bool grounded_at(double s) const { return is_line() && piece_at(s).grounded; }
  /// True when end A rests on the seabed (the first piece is grounded).
  bool anchor_grounded() const { return !pieces_.empty() && pieces_.front().grounded; }
  /// Horizontal force on end A [N]: with A on the seabed, H reduced by the seabed friction along
  /// the grounded part, max(H - C_B (grounded weight), 0); H otherwise.
  double anchor_horizontal_force_n() const;

  /// The uniform cable. For a general line only length_m (the total) is meaningful: use
  /// segment_at() for the section at s.
  const CableProperties& cable() const { return cable_; }
  /// True for a general line (built from a Line).
  bool is_line() const { return !pieces_.empty(); }
  /// The line (one segment for a uniform cable).
  Line line() const { return is_line() ? line_ : line_of_cable(cable_); }
  /// Pieces of a general line in order from a (empty for a uniform cable).
  const std::vector<StaticPiece>& pieces() const { return pieces_; }
  /// The section at s (at a joint: the segment toward b).
  LineSegment segment_at(double s) const;
  /// V on the side of a of s [N]: V(s) minus the weight of a point attachment at s.
  double vertical_force_before_n(double s) const;
  /// Arc length of the lowest point of the line [m].
  double lowest_point_s_m() const;
  /// H: horizontal component of the tension, constant along the cable [N]. With seabed contact:
  /// that of the suspended part (the fairlead's); on the grounded part it is tension_n(s).
  double horizontal_force_n() const { return H_; }
  /// V_A: vertical component of the tension at s = 0 (along t, i.e. toward b) [N]; 0 with seabed
  /// contact (the seabed carries the grounded weight).
  double vertical_force_a_n() const { return V_A_; }

  /// V(s) = V_A + W0 s [N] (piecewise on a general line).
  double vertical_force_n(double s) const;
  /// T(s) = sqrt(H^2 + V^2) [N].
  double tension_n(double s) const;
  /// e(s) = T/EA (0 when inextensible) [-].
  double strain(double s) const;
  /// Angle of the tangent above the horizontal [rad]: atan2(V, H), that of tangent() where the
  /// tension is zero.
  double angle_rad(double s) const;
  /// Unit tangent t = (H, V)/T; (1, 0) on the seabed. Where the tension is zero on a suspended
  /// piece (the foot of a slack line's vertical part, H = V = 0): the direction the piece leaves
  /// in, (0, +-1) by the sign of its weight.
  Vec2 tangent(double s) const;
  /// Unit in-plane normal n = (-V, H)/T (t rotated +90 degrees).
  Vec2 normal(double s) const;
  /// r(s) - r(0): offset from support a along the cable [m].
  Vec2 offset_m(double s) const;
  /// r(s): absolute position [m].
  Vec2 position_m(double s) const { return a_m_ + offset_m(s); }
  /// Stretched length of [0, s] [m].
  double stretched_length_m(double s) const;

  /// Newton iterations used by solve_statics (0 when built directly); with seabed contact, the
  /// steps of the bisection on H (each a bisection on L_g).
  int iterations = 0;
  /// |r(L) - (B - A)| at the solution [m].
  double closure_error_m = 0.0;
  /// False when solve_statics stopped without closing the chord to its tolerance: a numerical
  /// outcome, reported here and never thrown. The forces are then the last Newton iterate and must
  /// not be used for dynamics.
  bool converged = true;
  /// Why solve_statics stopped when !converged (closure error, tolerance, iterations, forces);
  /// empty when converged.
  std::string message;
  /// One line: "H = ... N, V_A = ... N, T_A = ..., T_B = ..., 5 Newton iterations, closure 1e-16
  /// m".
  std::string brief_report() const;

 private:
  /// The piece containing s (at a break: the one toward b).
  const StaticPiece& piece_at(double s) const;

  CableProperties cable_;
  Line line_;
  std::vector<StaticPiece> pieces_;
  Vec2 a_m_ = Vec2::Zero();
  double H_ = 0.0;
  double V_A_ = 0.0;
  std::optional<Seabed> seabed_;
  double grounded_length_m_ = 0.0;
};

/// Offset r(L) - r(0) of a cable with end forces (H, V_A): the closure function of the Newton
/// solve. Also used by problem builders. `H` >= 0 [N]; H = 0 requires V > 0 on (0, L].
Vec2 catenary_end_offset(const CableProperties& cable, double H, double V_A);

/// Solves the statics: finds (H, V_A) with r(L) = B - A by Newton's method on the 2x2 system with
/// its analytic Jacobian, from a robust initial guess (parabolic sag for slack cables, a straight
/// taut estimate otherwise), with a backtracking line search that keeps H > 0.
/// A vertical chord (B - A along z) is solved in the one unknown V_A with H = 0.
/// When the problem has prescribed_forces, they are the solution (no Newton; the closure error
/// against support b is checked and reported).
///
/// Errors, in two kinds (docs/contributing/architecture.md, "Errors"):
/// - bad input throws InvalidInput before any iteration: an invalid problem or options, no
///   equilibrium (an inextensible cable shorter than the chord, a vertical chord that leaves the
///   cable slack), prescribed forces that miss support b;
/// - a Newton iteration that does not close the chord is a numerical outcome: the result is
///   returned with `converged == false` and `message` saying why (closure error, tolerance,
///   iterations). Callers check `converged` before using the solution.
/// A general line (Problem::is_uniform() false) is solved by solve_line_statics
/// (catena/statics/line_statics.hpp), a problem with a seabed by solve_seabed_statics
/// (catena/statics/seabed_statics.hpp).
StaticSolution solve_statics(const Problem& problem, const StaticsOptions& options = {});

}  // namespace catena
