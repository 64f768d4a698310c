// SPDX-License-Identifier: MIT
// `catena solve`'s text for the dynamic tension in waves: the fairlead and anchor rows (regular:
// per period mean, amplitude, phase and max = mean + amplitude; irregular: mean, std, Tz and the
// most probable maximum in the duration) and the fixed point's iterations and residual. Records
// are filled by hand (the solvers on this branch decline the dynamic tension); the expected
// numbers are those records' own, printed with the documented precision.
#include "io/internal/dynamic_tension_text.hpp"

#include <gtest/gtest.h>

#include <string>

namespace catena::internal {
namespace {

DynamicTension regular(double period, bool converged) {
  DynamicTension t;
  t.period_s = period;
  t.fairlead.s_m = 1000.0;
  t.fairlead.mean_n = 812345.0;
  t.fairlead.amplitude_n = 23456.0;
  t.fairlead.phase_deg = -12.5;
  t.anchor.mean_n = 612345.0;
  t.anchor.amplitude_n = 5432.0;
  t.anchor.phase_deg = -40.25;
  t.iterations = 9;
  t.residual = 4.2e-9;
  t.converged = converged;
  if (!converged) t.diagnostic = "no fixed point within 9 iterations";
  return t;
}

TEST(DynamicTensionText, NothingWithoutRecords) {
  EXPECT_EQ(dynamic_tension_text({}, 10800.0, "    "), "");
}

TEST(DynamicTensionText, RegularRowsGiveMeanAmplitudePhaseAndMaxPerPeriod) {
  const std::string text =
      dynamic_tension_text({regular(8.0, true), regular(12.0, false)}, 10800.0, "    ");
  // max = mean + amplitude at each end.
  EXPECT_NE(text.find("835801"), std::string::npos) << text;  // 812345 + 23456
  EXPECT_NE(text.find("617777"), std::string::npos) << text;  // 612345 + 5432
  EXPECT_NE(text.find("-12.50"), std::string::npos) << text;
  EXPECT_NE(text.find("-40.25"), std::string::npos) << text;
  EXPECT_NE(text.find("4.20e-09"), std::string::npos) << text;
  EXPECT_NE(text.find(" 8 "), std::string::npos) << text;
  EXPECT_NE(text.find(" 12 "), std::string::npos) << text;
  EXPECT_NE(text.find("converged"), std::string::npos) << text;
  // The second period did not converge: said, with its diagnostic, never called converged.
  EXPECT_NE(text.find("NOT converged: no fixed point within 9 iterations"), std::string::npos)
      << text;
  // Both periods have a fairlead and an anchor row.
  const auto count = [&](const std::string& word) {
    std::size_t rows = 0;
    for (auto at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) ++rows;
    return rows;
  };
  EXPECT_EQ(count("fairlead"), 2u) << text;
  EXPECT_EQ(count("anchor"), 2u) << text;
}

TEST(DynamicTensionText, IrregularRowsGiveStdTzAndTheMostProbableMaximum) {
  DynamicTension t;
  t.irregular = true;
  t.fairlead.s_m = 1000.0;
  t.fairlead.mean_n = 800000.0;
  t.fairlead.std_n = 12345.0;
  t.fairlead.zero_upcrossing_period_s = 9.75;
  t.fairlead.most_probable_max_n = 851234.0;
  t.anchor.mean_n = 600000.0;
  t.anchor.std_n = 2345.0;
  t.anchor.zero_upcrossing_period_s = 11.5;
  t.anchor.most_probable_max_n = 609876.0;
  t.iterations = 14;
  t.residual = 6.5e-10;
  t.converged = true;
  const std::string text = dynamic_tension_text({t}, 10800.0, "  ");
  for (const char* value : {"12345", "9.75", "851234", "2345", "11.5", "609876", "6.50e-10",
                            "14 iterations", "max in 10800 s [N]", "converged"}) {
    EXPECT_NE(text.find(value), std::string::npos) << value << " in\n" << text;
  }
  EXPECT_EQ(text.find("NOT converged"), std::string::npos) << text;
}

}  // namespace
}  // namespace catena::internal
