// SPDX-License-Identifier: MIT
#include "verification/internal/identification_pencil.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>

#include "verification/internal/identification_order.hpp"

namespace catena::internal {

namespace {

constexpr double kPencilFlopBudget = 2e9;  // QR of the stacked Hankel matrix, ~1 s on this machine

int pencil_parameter(Index samples, Index channels) {
  const double budget_columns =
      std::sqrt(kPencilFlopBudget / (2.0 * static_cast<double>(channels * samples)));
  return static_cast<int>(
      std::max<Index>(2, std::min<Index>(samples / 3, static_cast<Index>(budget_columns) - 1)));
}

}  // namespace

PencilPoles matrix_pencil(const std::vector<Vector>& channels, double dt, int max_order) {
  PencilPoles out;
  const Index n = channels.front().size();
  const int l = pencil_parameter(n, static_cast<Index>(channels.size()));
  out.pencil_parameter = l;
  const Index rows_per_channel = n - l;
  const Index rows = rows_per_channel * static_cast<Index>(channels.size());
  Eigen::MatrixXd hankel(rows, l + 1);
  for (std::size_t c = 0; c < channels.size(); ++c) {
    for (Index i = 0; i < rows_per_channel; ++i) {
      hankel.row(static_cast<Index>(c) * rows_per_channel + i) =
          channels[c].segment(i, l + 1).transpose();
    }
  }
  // QR first: the SVD then runs on the small triangular factor, with the same singular values and
  // right singular vectors, and without squaring the condition number as a Gram matrix would.
  Eigen::HouseholderQR<Eigen::MatrixXd> qr(hankel);
  const Eigen::MatrixXd r = qr.matrixQR().topRows(l + 1).triangularView<Eigen::Upper>();
  Eigen::BDCSVD<Eigen::MatrixXd> svd(r, Eigen::ComputeThinV);
  const Vector& s = svd.singularValues();
  out.singular_values.assign(s.data(), s.data() + s.size());
  const int cap = max_order > 0 ? max_order : l;
  out.order = choose_model_order(out.singular_values, rows, l + 1, cap);
  if (out.order == 0) return out;
  // Hua & Sarkar's pencil on the signal subspace: the poles z are the eigenvalues of
  // V1^+ V2, V1 and V2 the signal right singular vectors without their last and first row.
  const Eigen::MatrixXd v = svd.matrixV().leftCols(out.order);
  const Eigen::MatrixXd shifted = v.topRows(l).colPivHouseholderQr().solve(v.bottomRows(l));
  Eigen::EigenSolver<Eigen::MatrixXd> eigen(shifted, false);
  for (Index k = 0; k < eigen.eigenvalues().size(); ++k) {
    out.poles_1_s.push_back(std::log(eigen.eigenvalues()[k]) / dt);
  }
  return out;
}

}  // namespace catena::internal
