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

// The pencil gives the order and the starting poles; the least-squares refinement, which uses
// every sample, reaches the final accuracy. So the pencil's cost is capped: L <= 250 columns
// (12.5 s at 20 Hz; separates poles 1 / (L dt) apart and closer at high SNR), and the rows (the
// windows the Hankel matrix stacks) are thinned evenly to a QR of at most ~2e8 flops, keeping at
// least 2 L of them so that the noise floor stays measurable.
constexpr Index kMaxPencilParameter = 250;
constexpr double kPencilFlopBudget = 2e8;

}  // namespace

PencilPoles matrix_pencil(const std::vector<Vector>& channels,
                          double dt,
                          int max_order,
                          double white_fraction) {
  PencilPoles out;
  const Index n = channels.front().size();
  const auto num_channels = static_cast<Index>(channels.size());
  const Index l = std::max<Index>(2, std::min(n / 3, kMaxPencilParameter));
  out.pencil_parameter = static_cast<int>(l);
  const Index windows = n - l;  // rows per channel
  const auto budget_rows =
      static_cast<Index>(kPencilFlopBudget / (2.0 * static_cast<double>((l + 1) * (l + 1))));
  const Index stride =
      std::max<Index>(1, windows * num_channels / std::max(budget_rows, 2 * (l + 1)));
  const Index rows_per_channel = (windows + stride - 1) / stride;
  const Index rows = rows_per_channel * num_channels;
  Eigen::MatrixXd hankel(rows, l + 1);
  for (Index c = 0; c < num_channels; ++c) {
    for (Index i = 0; i < rows_per_channel; ++i) {
      hankel.row(c * rows_per_channel + i) =
          channels[static_cast<std::size_t>(c)].segment(i * stride, l + 1).transpose();
    }
  }
  // QR first: the SVD then runs on the small triangular factor, with the same singular values and
  // right singular vectors, and without squaring the condition number as a Gram matrix would.
  Eigen::HouseholderQR<Eigen::MatrixXd> qr(hankel);
  const Eigen::MatrixXd r = qr.matrixQR().topRows(l + 1).triangularView<Eigen::Upper>();
  Eigen::BDCSVD<Eigen::MatrixXd> svd(r, Eigen::ComputeThinV);
  const Vector& s = svd.singularValues();
  out.singular_values.assign(s.data(), s.data() + s.size());
  const int cap = max_order > 0 ? max_order : static_cast<int>(l);
  out.order = choose_model_order(out.singular_values, rows, l + 1, cap, white_fraction);
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
