// SPDX-License-Identifier: MIT
// Knobs declared once: reading scene values, ranges, types, defaults and help from one table.
#include "solvers/common/knob_table.hpp"

#include <gtest/gtest.h>

namespace catena::internal {
namespace {

enum class Method { Adams, Bdf };

struct Options {
  int elements = 400;
  double tolerance = 1e-10;
  bool richardson = true;
  Method method = Method::Adams;
  void validate() const;
};

const KnobTable<Options>& knobs() {
  static const KnobTable<Options> table(
      "demo",
      {integer_knob("elements", &Options::elements, Range::closed(2, 1000000), "bar elements"),
       real_knob("tolerance", &Options::tolerance, Range::open_closed(0.0, 1e-2), "relative"),
       flag_knob("richardson", &Options::richardson, "extrapolate"),
       choice_knob("method", &Options::method, {{"adams", Method::Adams}, {"bdf", Method::Bdf}},
                   "")});
  return table;
}
void Options::validate() const { knobs().validate(*this); }

std::string message_of(const SolverKnobs& scene) {
  try {
    knobs().read(scene);
  } catch (const InvalidInput& error) {
    return error.what();
  }
  return "";
}

TEST(KnobTable, ReadsSceneValuesOverDefaults) {
  const Options options = knobs().read({{"elements", 800L}, {"method", std::string("bdf")}});
  EXPECT_EQ(options.elements, 800);
  EXPECT_EQ(options.method, Method::Bdf);
  EXPECT_DOUBLE_EQ(options.tolerance, 1e-10);
  EXPECT_TRUE(options.richardson);
  EXPECT_EQ(knobs().read({{"elements", 1e3}}).elements, 1000);
  // An integer is a valid real (1e-3 written as 0 would not be; 1 is out of range here).
  EXPECT_DOUBLE_EQ(knobs().read({{"tolerance", 0.001}}).tolerance, 1e-3);
  EXPECT_THROW(knobs().read({{"tolerance", 1L}}), InvalidInput);
}

TEST(KnobTable, RejectsNamingTheKnobAndTheReason) {
  EXPECT_EQ(message_of({{"elemnts", 4L}}),
            "[solvers.demo].elemnts: unknown knob for solver 'demo' (known: elements, tolerance, "
            "richardson, method)");
  EXPECT_EQ(message_of({{"elements", 1L}}), "[solvers.demo].elements = 1: must be in [2, 1e+06]");
  EXPECT_EQ(message_of({{"elements", 2.5}}), "[solvers.demo].elements: expected an integer");
  EXPECT_EQ(message_of({{"tolerance", 0.0}}), "[solvers.demo].tolerance = 0: must be in (0, 0.01]");
  EXPECT_EQ(message_of({{"richardson", 1L}}), "[solvers.demo].richardson: expected true or false");
  EXPECT_EQ(message_of({{"method", std::string("rk4")}}),
            "[solvers.demo].method = \"rk4\": must be \"adams\" or \"bdf\"");
}

TEST(KnobTable, IntegersAreRangeCheckedBeforeNarrowingSoNothingWraps) {
  // 4294967304 = 2^32 + 8 would become 8 in a 32-bit int.
  EXPECT_NE(message_of({{"elements", 4294967304L}}).find("must be in"), std::string::npos);
  EXPECT_NE(message_of({{"elements", 1e20}}).find("expected an integer"), std::string::npos);
}

TEST(KnobTable, NonFiniteRealsAreRejected) {
  EXPECT_NE(message_of({{"tolerance", std::nan("")}}).find("must be in"), std::string::npos);
}

TEST(KnobTable, ValidatesTypedOptionsWithTheSameRanges) {
  Options options;
  EXPECT_NO_THROW(options.validate());
  options.elements = 1;
  EXPECT_THROW(options.validate(), InvalidInput);
}

TEST(KnobTable, SpecsCarryTypeDefaultAndValidValues) {
  const std::vector<KnobSpec> specs = knobs().specs();
  ASSERT_EQ(specs.size(), 4u);
  EXPECT_EQ(specs[0].type, "integer");
  EXPECT_EQ(specs[0].default_value, "400");
  EXPECT_EQ(specs[1].default_value, "1e-10");
  EXPECT_EQ(specs[1].valid, "(0, 0.01]");
  EXPECT_EQ(specs[2].default_value, "true");
  EXPECT_EQ(specs[3].default_value, "\"adams\"");
  EXPECT_EQ(specs[3].valid, "\"adams\" or \"bdf\"");
}

TEST(KnobTable, EntryValidatesAndBuildsFromTheSameTable) {
  struct Nothing final : SolverNumerics {
    ModalResult modes(Plane, int) override { return {}; }
  };
  const SolverEntry entry = make_solver_entry(
      "demo solver", knobs(),
      [](const SolveContext&, const Options&) { return std::make_unique<Nothing>(); });
  EXPECT_EQ(entry.name, "demo");
  EXPECT_EQ(entry.knobs.size(), 4u);
  EXPECT_NO_THROW(entry.validate_knobs({{"elements", 10L}}));
  EXPECT_THROW(entry.validate_knobs({{"elements", 0L}}), InvalidInput);
}

}  // namespace
}  // namespace catena::internal
