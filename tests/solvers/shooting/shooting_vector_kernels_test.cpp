// SPDX-License-Identifier: MIT
// The compiled vector kernels of a shot's N_Vectors (src/solvers/shooting/shooting_vector_kernels)
// against SUNDIALS' own serial operations on the same data: every kernel ERKStep calls gives the
// serial result to the last bit (same sums in the same order), a linear combination may write over
// any of its inputs, and the clones ERKStep makes inherit the kernels.
#include "solvers/shooting/shooting_vector_kernels.hpp"

#include <gtest/gtest.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>

#include <array>
#include <cmath>
#include <vector>

namespace catena::internal {
namespace {

constexpr sunindextype kLength = 17;  // the largest shot state (in plane, with the slope)

// A context and vectors: `plain` with SUNDIALS' serial operations, `compiled` with the kernels.
class VectorKernels : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_EQ(SUNContext_Create(nullptr, &context_), 0);
    for (int k = 0; k < 4; ++k) {
      plain_[k] = N_VNew_Serial(kLength, context_);
      compiled_[k] = N_VNew_Serial(kLength, context_);
      use_compiled_kernels(compiled_[k]);
      for (sunindextype i = 0; i < kLength; ++i) {
        // Values of mixed sign and magnitude, none zero (the inverse and the quotient).
        const double value = std::sin(1.0 + 3.7 * static_cast<double>(i + 5 * k)) *
                             std::pow(10.0, static_cast<double>((i % 7) - 3));
        NV_Ith_S(plain_[k], i) = value;
        NV_Ith_S(compiled_[k], i) = value;
      }
    }
  }
  void TearDown() override {
    for (int k = 0; k < 4; ++k) {
      N_VDestroy(plain_[k]);
      N_VDestroy(compiled_[k]);
    }
    SUNContext_Free(&context_);
  }

  // Every element of plain_[k] equals compiled_[k]'s, bit for bit.
  void expect_same(int k) const {
    for (sunindextype i = 0; i < kLength; ++i) {
      EXPECT_EQ(NV_Ith_S(plain_[k], i), NV_Ith_S(compiled_[k], i))
          << "vector " << k << " [" << i << "]";
    }
  }

  SUNContext context_ = nullptr;
  std::array<N_Vector, 4> plain_{};
  std::array<N_Vector, 4> compiled_{};
};

TEST_F(VectorKernels, ElementwiseOperationsMatchTheSerialOnes) {
  N_VLinearSum(0.3, plain_[0], -1.7, plain_[1], plain_[2]);
  N_VLinearSum(0.3, compiled_[0], -1.7, compiled_[1], compiled_[2]);
  expect_same(2);
  N_VScale(2.5, plain_[2], plain_[3]);
  N_VScale(2.5, compiled_[2], compiled_[3]);
  expect_same(3);
  N_VProd(plain_[0], plain_[1], plain_[3]);
  N_VProd(compiled_[0], compiled_[1], compiled_[3]);
  expect_same(3);
  N_VDiv(plain_[0], plain_[1], plain_[3]);
  N_VDiv(compiled_[0], compiled_[1], compiled_[3]);
  expect_same(3);
  N_VAbs(plain_[2], plain_[3]);
  N_VAbs(compiled_[2], compiled_[3]);
  expect_same(3);
  N_VInv(plain_[3], plain_[3]);
  N_VInv(compiled_[3], compiled_[3]);
  expect_same(3);
  N_VAddConst(plain_[3], 1e-12, plain_[3]);
  N_VAddConst(compiled_[3], 1e-12, compiled_[3]);
  expect_same(3);
  N_VConst(-4.0, plain_[2]);
  N_VConst(-4.0, compiled_[2]);
  expect_same(2);
}

TEST_F(VectorKernels, NormsMatchTheSerialOnes) {
  N_VAbs(plain_[1], plain_[1]);
  N_VAbs(compiled_[1], compiled_[1]);
  EXPECT_EQ(N_VWrmsNorm(plain_[0], plain_[1]), N_VWrmsNorm(compiled_[0], compiled_[1]));
  EXPECT_EQ(N_VMaxNorm(plain_[0]), N_VMaxNorm(compiled_[0]));
  EXPECT_EQ(N_VMin(plain_[0]), N_VMin(compiled_[0]));
}

TEST_F(VectorKernels, LinearCombinationMatchesTheSerialOneAndMayOverwriteAnInput) {
  std::array<double, 4> c = {1.0, 0.25, -3.0, 1e-3};
  // Into a fresh vector, then into its first input with c0 = 1 and c0 != 1 (ERKStep's cases).
  for (int aliased : {-1, 0}) {
    for (double c0 : {1.0, 0.7}) {
      c[0] = c0;
      const int out = aliased < 0 ? 3 : aliased;
      std::array<N_Vector, 3> xp = {plain_[0], plain_[1], plain_[2]};
      std::array<N_Vector, 3> xc = {compiled_[0], compiled_[1], compiled_[2]};
      N_VLinearCombination(3, c.data(), xp.data(), plain_[out]);
      N_VLinearCombination(3, c.data(), xc.data(), compiled_[out]);
      expect_same(out);
    }
  }
  // The output is a later input: element by element, each input is read before it is written.
  std::vector<double> expected(kLength);
  for (sunindextype i = 0; i < kLength; ++i) {
    expected[static_cast<std::size_t>(i)] =
        c[0] * NV_Ith_S(compiled_[0], i) + c[1] * NV_Ith_S(compiled_[1], i);
  }
  std::array<N_Vector, 2> xc = {compiled_[0], compiled_[1]};
  N_VLinearCombination(2, c.data(), xc.data(), compiled_[1]);
  for (sunindextype i = 0; i < kLength; ++i) {
    EXPECT_EQ(NV_Ith_S(compiled_[1], i), expected[static_cast<std::size_t>(i)]) << i;
  }
}

TEST_F(VectorKernels, ClonesInheritTheKernels) {
  N_Vector clone = N_VClone(compiled_[0]);
  ASSERT_NE(clone, nullptr);
  EXPECT_EQ(clone->ops->nvlinearcombination, compiled_[0]->ops->nvlinearcombination);
  EXPECT_NE(clone->ops->nvlinearcombination, plain_[0]->ops->nvlinearcombination);
  EXPECT_EQ(clone->ops->nvwrmsnorm, compiled_[0]->ops->nvwrmsnorm);
  N_VDestroy(clone);
}

}  // namespace
}  // namespace catena::internal
