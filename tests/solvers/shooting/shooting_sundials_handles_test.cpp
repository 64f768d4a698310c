// SPDX-License-Identifier: MIT
// SUNDIALS never prints: CVODE's error messages used to reach stderr under `catena --quiet` (and
// inside Python); CvodeMemory keeps them instead.
#include "solvers/shooting/shooting_sundials_handles.hpp"

#include <gtest/gtest.h>

#include <string>

namespace catena::internal {
namespace {

TEST(CvodeMemory, KeepsCvodesErrorMessagesOffStderr) {
  SundialsContext context;
  ASSERT_TRUE(context.ok());
  CvodeMemory cvode(CV_BDF, context.get());
  ASSERT_TRUE(cvode.ok());
  SerialVector y(2, context.get());
  ASSERT_TRUE(y.ok());
  ::testing::internal::CaptureStderr();
  // A call before CVodeInit: an error CVODE reports through its handler.
  const int flag = CVodeReInit(cvode.get(), 0.0, y.get());
  const std::string printed = ::testing::internal::GetCapturedStderr();
  EXPECT_LT(flag, 0);
  EXPECT_EQ(printed, "");
  EXPECT_NE(cvode.last_message().find("CVodeReInit"), std::string::npos) << cvode.last_message();
}

}  // namespace
}  // namespace catena::internal
