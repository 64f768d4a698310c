// SPDX-License-Identifier: MIT
// The fe chain's stiffness and mass matrices: see fe_operators.hpp and
// docs/explanation/methods/fe.md.
#include "solvers/fe/fe_operators.hpp"

#include <algorithm>
#include <cassert>
#include <vector>

namespace catena::internal {
namespace {

// Builds the compressed-column block-tridiagonal matrix of the free nodes 1..N-1 directly (no
// triplets: at N = 1e6 the triplet list and its sort cost more than everything but the Lanczos
// iterations, mostly in first-touch page faults). `element[j]` is the P x P block of element j
// (nodes j, j+1); the block of free nodes (a, b) is sum of element blocks on the diagonal and
// minus the shared element's block off it. With `diagonal_only`, only the diagonal blocks
// `node[i]` are stored (the lumped mass).
// Filled in place: Eigen 3.4's SparseMatrix has no move assignment, and a copy of a large matrix
// costs mostly first-touch page faults.
template <int P>
void fill_block_tridiagonal(
    SparseMatrix& matrix,
    const std::vector<Eigen::Matrix<double, P, P>>& element,
    const std::vector<Eigen::Matrix<double, P, P>>& node,
    int elements,
    bool diagonal_only,
    const std::vector<Eigen::Matrix<double, P, P>>* node_stiffness = nullptr) {
  const int free_nodes = elements - 1;
  const Eigen::Index n = static_cast<Eigen::Index>(P) * free_nodes;
  const Eigen::Index nonzeros = diagonal_only ? P * n : 3 * P * n - 2 * P * P;
  matrix.resize(n, n);
  matrix.resizeNonZeros(nonzeros);
  auto* outer = matrix.outerIndexPtr();
  auto* inner = matrix.innerIndexPtr();
  double* values = matrix.valuePtr();
  Eigen::Index at = 0;
  for (int i = 1; i <= free_nodes; ++i) {  // free node i, unknowns P (i - 1) ..
    for (int c = 0; c < P; ++c) {
      outer[P * (i - 1) + c] = static_cast<int>(at);
      auto put = [&](int node_j, const Eigen::Matrix<double, P, P>& block, double sign) {
        for (int r = 0; r < P; ++r) {
          inner[at] = P * (node_j - 1) + r;
          values[at] = sign * block(r, c);
          ++at;
        }
      };
      if (diagonal_only) {
        put(i, node[static_cast<std::size_t>(i)], 1.0);
        continue;
      }
      const auto& left = element[static_cast<std::size_t>(i) - 1];  // nodes i-1, i
      const auto& right = element[static_cast<std::size_t>(i)];     // nodes i, i+1
      if (i > 1) put(i - 1, left, -1.0);
      Eigen::Matrix<double, P, P> diagonal = left + right;
      if (node_stiffness) diagonal += (*node_stiffness)[static_cast<std::size_t>(i)];
      put(i, diagonal, 1.0);
      if (i < free_nodes) put(i + 1, right, -1.0);
    }
  }
  outer[n] = static_cast<int>(at);
  assert(at == nonzeros);
}

// True when the elements on both sides of node i have the same length and section: the node then
// carries l0 times the line density, as on a uniform cable.
bool same_section(const FeChain& chain, int i) {
  return chain.element_length_m[i - 1] == chain.element_length_m[i] &&
         chain.tangential_mass_kg_per_m[i - 1] == chain.tangential_mass_kg_per_m[i] &&
         chain.normal_mass_kg_per_m[i - 1] == chain.normal_mass_kg_per_m[i];
}

// Node i's lumped share of a density: half of each neighbouring element's [kg].
double half_sum(const FeChain& chain, const Vector& density, int i) {
  return 0.5 *
         (chain.element_length_m[i - 1] * density[i - 1] + chain.element_length_m[i] * density[i]);
}

// A point attachment at node i, with or without inertia: a massless buoy's weight kinks the line
// as much as a clump's (until 2026-12 only a point with inertia counted, and a buoy given by its
// volume alone left fe first order: docs/explanation/methods/fe.md, "Lines").
bool has_point(const FeChain& chain, int i) {
  const FeNodeInertia& point = chain.node_inertia[static_cast<std::size_t>(i)];
  return point.attached || point.tangential_kg > 0.0 || point.normal_kg > 0.0 ||
         point.outofplane_kg > 0.0;
}

// True when elements j and k lie in the same mesh piece (FeChain::piece_first_element).
bool same_piece(const FeChain& chain, int j, int k) {
  const std::vector<int>& first = chain.piece_first_element;
  auto piece = [&first](int e) { return std::upper_bound(first.begin(), first.end(), e); };
  return piece(j) == piece(k);
}

// The frame of node i's half cell on the side of element j (j = i toward b, j = i - 1 toward a),
// at a node where the line kinks or changes section. An interior node of a piece takes the bisector
// of its two elements' directions, which differs from the line's tangent at the node by O(h^2);
// the half cell takes the bisector that node would have if the piece went on beyond it: of t_j and
// the direction of the force 2 F_j - F_k of the element before it (the element force is linear in
// s within a piece; k is j's neighbour away from the node). In t_j alone (the element's own frame)
// the half cell's mass differs from the piece's interior scheme by O(h^2) on one node, an O(h^3)
// error in the frequencies that Richardson's even expansion leaves (third order after it, where the
// line's m and M differ). Falls back to t_j where the piece has one element on that side, or where
// `alike` says that element k is lumped differently from j (the drag of a profile that varies
// element by element is lumped in the element frames at every node, so that is the scheme to
// continue).
Vec2 half_cell_tangent(const FeChain& chain,
                       int i,
                       int j,
                       bool (*alike)(const FeChain&, int, int) = nullptr) {
  const Vec2& t = chain.direction[static_cast<std::size_t>(j)];
  const int k = j == i ? j + 1 : j - 1;
  if (k < 0 || k >= chain.elements || !same_piece(chain, j, k)) return t;
  if (alike && !alike(chain, j, k)) return t;
  const Vec2 before = 2.0 * chain.tension_n[j] * t -
                      chain.tension_n[k] * chain.direction[static_cast<std::size_t>(k)];
  if (!(before.norm() > 0.0)) return t;
  const Vec2 sum = t + before.normalized();
  return sum.norm() > 1.0 ? Vec2(sum.normalized()) : t;
}

// In-plane lumped mass of the half of element j on node i, in the half cell's frame
// (half_cell_tangent: m along it, M across it) [kg].
Eigen::Matrix2d half_element_mass(const FeChain& chain, int i, int j) {
  const Vec2 t = half_cell_tangent(chain, i, j);
  const Eigen::Matrix2d ttT = t * t.transpose();
  const double M = chain.normal_mass_kg_per_m[j];
  return 0.5 * chain.element_length_m[j] *
         (chain.tangential_mass_kg_per_m[j] * ttT + M * (Eigen::Matrix2d::Identity() - ttT));
}

// The seabed foundation out of plane, lumped as inplane_foundation (fe_operators.hpp): node i
// carries k_t times half of each grounded neighbour's l0. Empty without contact.
std::vector<Eigen::Matrix<double, 1, 1>> outofplane_foundation(const FeChain& chain) {
  if (!chain.has_contact()) return {};
  std::vector<Eigen::Matrix<double, 1, 1>> node(static_cast<std::size_t>(chain.elements) + 1);
  for (int i = 0; i <= chain.elements; ++i)
    node[static_cast<std::size_t>(i)](0, 0) =
        chain.foundation_tangential_n_per_m2 * chain.grounded_share_m(i);
  return node;
}

}  // namespace

std::vector<Eigen::Matrix2d> inplane_foundation(const FeChain& chain) {
  if (!chain.has_contact()) return {};
  std::vector<Eigen::Matrix2d> node(static_cast<std::size_t>(chain.elements) + 1,
                                    Eigen::Matrix2d::Zero());
  for (int i = 1; i < chain.elements; ++i) {
    const double share = chain.grounded_share_m(i);
    node[static_cast<std::size_t>(i)].diagonal() << chain.foundation_tangential_n_per_m2 * share,
        chain.foundation_vertical_n_per_m2 * share;
  }
  return node;
}

FeMatrices assemble_inplane(const FeChain& chain) {
  const int N = chain.elements;
  FeMatrices out;
  out.dofs_per_node = 2;
  std::vector<Eigen::Matrix2d> element(static_cast<std::size_t>(N)),
      node(static_cast<std::size_t>(N) + 1);
  for (int j = 0; j < N; ++j) {
    const Vec2& t = chain.direction[static_cast<std::size_t>(j)];
    const Eigen::Matrix2d ttT = t * t.transpose();
    element[static_cast<std::size_t>(j)] =
        (chain.axial_stiffness_n[j] / chain.element_length_m[j]) * ttT +
        (chain.tension_n[j] / chain.stretched_length_m[j]) * (Eigen::Matrix2d::Identity() - ttT);
  }
  for (int i = 1; i < N; ++i) {
    // The node tangent bisects the two element directions; the mass is m along it and M across.
    const Vec2 t = (chain.direction[static_cast<std::size_t>(i) - 1] +
                    chain.direction[static_cast<std::size_t>(i)])
                       .normalized();
    const Vec2 nrm(-t.y(), t.x());
    const Eigen::Matrix2d ttT = t * t.transpose(), nnT = nrm * nrm.transpose();
    if (same_section(chain, i) && !has_point(chain, i)) {
      // The uniform cable's expression, kept term for term so its results stay bit-identical.
      node[static_cast<std::size_t>(i)] =
          chain.element_length_m[i] * (chain.tangential_mass_kg_per_m[i] * t * t.transpose() +
                                       chain.normal_mass_kg_per_m[i] * nrm * nrm.transpose());
    } else {
      // A joint or a point: each half cell keeps the frame of its own side (half_cell_tangent).
      // At a point weight the static line has a kink (an O(1) angle between the elements); lumped
      // in the bisector frame, the half elements' masses would be off by O(1) on one node, an O(h)
      // error in every frequency that Richardson's h^2 model cannot remove
      // (docs/explanation/methods/fe.md, "Lines").
      node[static_cast<std::size_t>(i)] =
          half_element_mass(chain, i, i - 1) + half_element_mass(chain, i, i);
    }
    const FeNodeInertia& point = chain.node_inertia[static_cast<std::size_t>(i)];
    if (point.tangential_kg > 0.0 || point.normal_kg > 0.0)
      node[static_cast<std::size_t>(i)] += point.tangential_kg * ttT + point.normal_kg * nnT;
  }
  const std::vector<Eigen::Matrix2d> foundation = inplane_foundation(chain);
  fill_block_tridiagonal<2>(out.stiffness, element, node, N, false,
                            foundation.empty() ? nullptr : &foundation);
  fill_block_tridiagonal<2>(out.mass, element, node, N, true);
  // Columns 0-1: node a's (x, z); columns 2-3: node b's.
  const Eigen::Index n = out.stiffness.rows();
  std::vector<Eigen::Triplet<double>> b_entries;
  for (int r = 0; r < 2; ++r) {
    for (int c = 0; c < 2; ++c) {
      b_entries.emplace_back(r, c, -element.front()(r, c));
      b_entries.emplace_back(n - 2 + r, 2 + c, -element.back()(r, c));
    }
  }
  out.boundary_coupling.resize(n, 4);
  out.boundary_coupling.setFromTriplets(b_entries.begin(), b_entries.end());
  return out;
}

FeMatrices assemble_outofplane(const FeChain& chain) {
  const int N = chain.elements;
  FeMatrices out;
  out.dofs_per_node = 1;
  using Block = Eigen::Matrix<double, 1, 1>;
  std::vector<Block> element(static_cast<std::size_t>(N)), node(static_cast<std::size_t>(N) + 1);
  // Only the string part T/l resists motion normal to the plane.
  for (int j = 0; j < N; ++j)
    element[static_cast<std::size_t>(j)](0, 0) = chain.tension_n[j] / chain.stretched_length_m[j];
  for (int i = 1; i < N; ++i) {
    node[static_cast<std::size_t>(i)](0, 0) =
        (same_section(chain, i) ? chain.element_length_m[i] * chain.normal_mass_kg_per_m[i]
                                : half_sum(chain, chain.normal_mass_kg_per_m, i)) +
        chain.node_inertia[static_cast<std::size_t>(i)].outofplane_kg;
  }
  const std::vector<Block> foundation = outofplane_foundation(chain);
  fill_block_tridiagonal<1>(out.stiffness, element, node, N, false,
                            foundation.empty() ? nullptr : &foundation);
  fill_block_tridiagonal<1>(out.mass, element, node, N, true);
  const Eigen::Index n = out.stiffness.rows();
  const std::vector<Eigen::Triplet<double>> b_entries = {
      {0, 0, -element.front()(0, 0)}, {static_cast<int>(n) - 1, 1, -element.back()(0, 0)}};
  out.boundary_coupling.resize(n, 2);
  out.boundary_coupling.setFromTriplets(b_entries.begin(), b_entries.end());
  return out;
}

FeMatrices assemble(Plane plane, const FeChain& chain) {
  return plane == Plane::InPlane ? assemble_inplane(chain) : assemble_outofplane(chain);
}

namespace {

// True when elements j and k have the same length and drag (lumped alike: inplane_node_damping).
bool same_drag(const FeChain& chain, int j, int k) {
  return chain.element_length_m[j] == chain.element_length_m[k] &&
         chain.tangential_damping_n_s_per_m2[j] == chain.tangential_damping_n_s_per_m2[k] &&
         chain.normal_damping_n_s_per_m2[j] == chain.normal_damping_n_s_per_m2[k];
}

// In-plane drag of the half of element j on node i, in the half cell's frame [N s/m]: the
// bisector its side's interior nodes would give it where they lump the drag in the bisector frame
// (uniform drag), else the element's own frame (a drag profile that varies element by element).
Eigen::Matrix2d half_element_drag(const FeChain& chain, int i, int j) {
  const Vec2 t = half_cell_tangent(chain, i, j, &same_drag);
  const Eigen::Matrix2d ttT = t * t.transpose();
  return 0.5 * chain.element_length_m[j] *
         (chain.tangential_damping_n_s_per_m2[j] * ttT +
          chain.normal_damping_n_s_per_m2[j] * (Eigen::Matrix2d::Identity() - ttT));
}

bool same_damping(const FeChain& chain, int i) {
  return chain.element_length_m[i - 1] == chain.element_length_m[i] &&
         chain.tangential_damping_n_s_per_m2[i - 1] == chain.tangential_damping_n_s_per_m2[i] &&
         chain.normal_damping_n_s_per_m2[i - 1] == chain.normal_damping_n_s_per_m2[i];
}

// The in-plane node drag (the mass's lumping, assemble_inplane) plus the seabed dashpot on z.
std::vector<Eigen::Matrix2d> inplane_node_damping(const FeChain& chain) {
  const int N = chain.elements;
  std::vector<Eigen::Matrix2d> node(static_cast<std::size_t>(N) + 1, Eigen::Matrix2d::Zero());
  for (int i = 1; i < N; ++i) {
    const auto k = static_cast<std::size_t>(i);
    if (same_damping(chain, i) && !has_point(chain, i)) {
      // As the mass (assemble_inplane): at a point the line kinks, and drag with c_t != c_n
      // lumped in the bisector frame would be off by O(1) on that node.
      const Vec2 t = (chain.direction[k - 1] + chain.direction[k]).normalized();
      const Vec2 nrm(-t.y(), t.x());
      node[k] =
          chain.element_length_m[i] * (chain.tangential_damping_n_s_per_m2[i] * t * t.transpose() +
                                       chain.normal_damping_n_s_per_m2[i] * nrm * nrm.transpose());
    } else {
      node[k] = half_element_drag(chain, i, i - 1) + half_element_drag(chain, i, i);
    }
    if (chain.has_contact())
      node[k](1, 1) += chain.foundation_damping_n_s_per_m2 * chain.grounded_share_m(i);
  }
  return node;
}

}  // namespace

FeDampingMatrix assemble_damping(Plane plane, const FeChain& chain) {
  const int N = chain.elements;
  FeDampingMatrix out;
  std::vector<Eigen::Triplet<double>> b_entries;
  if (plane == Plane::InPlane) {
    std::vector<Eigen::Matrix2d> element(static_cast<std::size_t>(N));
    for (int j = 0; j < N; ++j) {
      const Vec2& t = chain.direction[static_cast<std::size_t>(j)];
      element[static_cast<std::size_t>(j)] =
          (chain.axial_damping_n_s[j] / chain.element_length_m[j]) * (t * t.transpose());
    }
    const std::vector<Eigen::Matrix2d> node = inplane_node_damping(chain);
    fill_block_tridiagonal<2>(out.damping, element, node, N, false, &node);
    const Eigen::Index n = out.damping.rows();
    for (int r = 0; r < 2; ++r) {
      for (int c = 0; c < 2; ++c) {
        b_entries.emplace_back(r, c, -element.front()(r, c));
        b_entries.emplace_back(n - 2 + r, 2 + c, -element.back()(r, c));
      }
    }
    out.boundary_coupling.resize(n, 4);
  } else {
    using Block = Eigen::Matrix<double, 1, 1>;
    std::vector<Block> element(static_cast<std::size_t>(N), Block::Zero()),
        node(static_cast<std::size_t>(N) + 1, Block::Zero());
    for (int i = 1; i < N; ++i)
      node[static_cast<std::size_t>(i)](0, 0) =
          same_damping(chain, i) ? chain.element_length_m[i] * chain.normal_damping_n_s_per_m2[i]
                                 : half_sum(chain, chain.normal_damping_n_s_per_m2, i);
    fill_block_tridiagonal<1>(out.damping, element, node, N, false, &node);
    out.boundary_coupling.resize(out.damping.rows(), 2);
  }
  out.boundary_coupling.setFromTriplets(b_entries.begin(), b_entries.end());
  return out;
}

int fe_unknowns(Plane plane, int elements) {
  return (plane == Plane::InPlane ? 2 : 1) * (elements - 1);
}

}  // namespace catena::internal
