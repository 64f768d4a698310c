// SPDX-License-Identifier: MIT
// What the MoorDyn importer says about a deck (io/moordyn_notes.hpp, io/moordyn_import.hpp), on
// decks written for these tests (not copies of published decks): the seabed written under every
// line, the statics solved with it (or its refusal, and where the line would hang without it,
// against an independent catenary), and a note for everything else the deck holds.
#include "catena/io/moordyn_notes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "catena/core/types.hpp"
#include "catena/io/moordyn_deck.hpp"
#include "catena/io/moordyn_import.hpp"

namespace catena {
namespace {

namespace fs = std::filesystem;

MoorDynDeck deck_from(const std::string& name, const std::string& text) {
  const fs::path dir = fs::temp_directory_path() / "catena_moordyn_notes_test";
  fs::create_directories(dir);
  const fs::path path = dir / name;
  std::ofstream(path) << text;
  return read_moordyn_deck(path);
}

// One uniform, nearly inextensible line (EA = 1e20 N) whose two ends are above the seabed at
// z = -300 m: A at (0, 0, -250), B at (400, 0, -20), 600 m long. Hanging freely it would sag far
// below the seabed (to z = -331.9 m), so it rests on it between two suspended parts.
std::string w_deck(const std::string& options) {
  return R"(W-shaped line written for Catena's tests: both ends above the seabed
---------------------- LINE TYPES ----------------------------------------
Name   Diam  MassDen  EA     BA/-zeta  EI     Cd   Ca   CdAx  CaAx  Cl
(-)    (m)   (kg/m)   (N)    (N-s/-)   (N-m^2) (-) (-)  (-)   (-)   (-)
chain  0.1   100.0    1e20   0.0       2.5e3  1.2  1.0  0.4   0.0   0.8
---------------------- POINTS --------------------------------------------
ID  Attachment  X      Y    Z       M    V    CdA  CA
(#) (-)         (m)    (m)  (m)     (kg) (m^3) (m^2) (-)
1   Fixed       0.0    0.0  -250.0  0    0    0    0
2   Vessel      400.0  0.0  -20.0   0    0    1.5  0
---------------------- LINES ---------------------------------------------
ID  LineType  AttachA  AttachB  UnstrLen  NumSegs  Outputs
(#) (name)    (#)      (#)      (m)       (-)      (-)
1   chain     1        2        600.0     40       pt
---------------------- OPTIONS -------------------------------------------
)" + options +
         R"(---------------------- OUTPUTS -------------------------------------------
FairTen1
AnchTen1
------------------------- need this line ---------------------------------
)";
}

const std::string kOptions = R"(0.001    dtM
300      WtrDpth
2.0e6    kBot
1.0e5    cBot
60.0     TmaxIC
4.0      CdScaleIC
0.01     threshIC
0.5      FrictionCoefficient
200      FricDamp
0.3      MU_KT
0        WaveKin
1        Currents
7        Mystery
)";

// The lowest point of an inextensible catenary of length L between (0, 0) and (X, h), solved
// here independently of Catena: sqrt(L^2 - h^2) = 2 a sinh(X / 2a) for the parameter a (by
// bisection), then the vertex x0 = X/2 - a asinh(h / (2 a sinh(X / 2a))) and its depth
// a (1 - cosh(x0 / a)) below A.
double catenary_lowest_z(double X, double h, double L) {
  const double target = std::sqrt(L * L - h * h);
  double lo = 1e-3, hi = 1e6;  // 2 a sinh(X / 2a) decreases in a towards X
  for (int i = 0; i < 200; ++i) {
    const double a = 0.5 * (lo + hi);
    (2.0 * a * std::sinh(X / (2.0 * a)) > target ? lo : hi) = a;
  }
  const double a = 0.5 * (lo + hi);
  const double x0 = X / 2.0 - a * std::asinh(h / (2.0 * a * std::sinh(X / (2.0 * a))));
  return a * (1.0 - std::cosh(x0 / a));
}

// Replaces the one occurrence of `from` in `text`.
void replace_once(std::string& text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  ASSERT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
}

bool has_note(const std::vector<MoorDynNote>& notes,
              const std::string& item,
              const std::string& fate) {
  return std::any_of(notes.begin(), notes.end(), [&](const MoorDynNote& note) {
    return note.item == item && note.fate == fate;
  });
}

TEST(MoorDynImport, LineWithBothEndsAboveTheSeabedGetsTheSeabed) {
  const MoorDynDeck deck = deck_from("w.dat", w_deck(kOptions));
  const auto scenes = convert_moordyn_deck(deck, "w");
  ASSERT_EQ(scenes.size(), 1u);
  const ImportedScene& scene = scenes.front();
  ASSERT_TRUE(scene.reason.empty()) << scene.reason;
  // [seabed] at -WtrDpth with kBot Diam and cBot Diam, friction 0, though end A is above it.
  const std::string& text = scene.toml;
  EXPECT_NE(text.find("\n[seabed]"), std::string::npos) << text;
  EXPECT_NE(text.find("\nz = -300.0\nfriction = 0.0\nstiffness = 200000.0\ndamping = 10000.0\n"),
            std::string::npos)
      << text;
  EXPECT_EQ(scene.tables, "[cable] + [seabed]");
  // Whether the statics solves a line with both ends above the seabed depends on the seabed model
  // on main; either way it must not leave the line below the seabed unsaid.
  if (scene.statics_solved) {
    EXPECT_EQ(scene.statics.rfind("grounded ", 0), 0u) << scene.statics;
    for (const auto& note : scene.notes)
      EXPECT_EQ(note.find("passes below the seabed"), std::string::npos) << note;
  } else {
    EXPECT_EQ(scene.statics, "refused (see the notes)");
    EXPECT_TRUE(std::any_of(scene.notes.begin(), scene.notes.end(),
                            [](const auto& n) { return n.rfind("Statics refused: ", 0) == 0; }));
    // Without the seabed the line would hang to the catenary's vertex, far below z = -300.
    const double lowest = -250.0 + catenary_lowest_z(400.0, 230.0, 600.0);
    ASSERT_LT(lowest, -300.0);
    const auto note = std::find_if(scene.notes.begin(), scene.notes.end(), [](const auto& n) {
      return n.rfind("Without the seabed the line would hang down to z = ", 0) == 0;
    });
    ASSERT_NE(note, scene.notes.end());
    const double printed = std::stod(note->substr(note->find("z = ") + 4));
    EXPECT_NEAR(printed, lowest, 1e-5 * std::abs(lowest)) << *note;  // 6 digits printed
    EXPECT_NE(note->find("below the deck's water depth"), std::string::npos) << *note;
  }
  // The line's own notes say what its type loses: EI = 2.5e3 N m^2.
  EXPECT_NE(std::find(scene.notes.begin(), scene.notes.end(),
                      "Line 1 (type chain): EI = 2.5e3 N m^2 dropped: Catena's lines have no "
                      "bending stiffness."),
            scene.notes.end());
  // The scene's header carries the notes; no stale "Needs" promise.
  for (const auto& note : scene.notes) EXPECT_NE(text.find("# " + note), std::string::npos);
  EXPECT_EQ(text.find("Needs:"), std::string::npos) << text;
  EXPECT_EQ(text.find("once its readers"), std::string::npos) << text;
}

TEST(MoorDynImport, LineOnTheSeabedIsSolvedWithItAndReportsItsContact) {
  // The same line anchored on the seabed at -300 m: today's seabed statics solves it.
  std::string text = w_deck(kOptions);
  replace_once(text, "0.0    0.0  -250.0", "0.0    0.0  -300.0");
  const auto scenes = convert_moordyn_deck(deck_from("on.dat", text), "on");
  ASSERT_EQ(scenes.size(), 1u);
  ASSERT_TRUE(scenes[0].statics_solved) << scenes[0].toml;
  EXPECT_EQ(scenes[0].statics.rfind("grounded ", 0), 0u) << scenes[0].statics;
  EXPECT_NE(scenes[0].statics.find(" of 600 m"), std::string::npos) << scenes[0].statics;
  EXPECT_NE(scenes[0].toml.find("# Statics with the seabed: H = "), std::string::npos);
}

TEST(MoorDynNotes, EveryOptionAndColumnIsReportedWithItsFate) {
  const auto notes = moordyn_deck_notes(deck_from("notes.dat", w_deck(kOptions)));
  EXPECT_TRUE(has_note(notes, "option WtrDpth = 300", "used"));
  EXPECT_TRUE(has_note(notes, "option kBot = 2.0e6", "used"));
  EXPECT_TRUE(has_note(notes, "option cBot = 1.0e5", "used"));
  for (const char* item :
       {"option dtM = 0.001", "option TmaxIC = 60.0", "option CdScaleIC = 4.0",
        "option threshIC = 0.01", "option FrictionCoefficient = 0.5", "option FricDamp = 200",
        "option MU_KT = 0.3", "option Currents = 1", "option Mystery = 7"}) {
    EXPECT_TRUE(has_note(notes, item, "ignored")) << item;
  }
  EXPECT_TRUE(has_note(notes, "option WaveKin = 0", "none"));
  EXPECT_TRUE(has_note(notes, "g (not given)", "default"));
  EXPECT_TRUE(has_note(notes, "rho (not given)", "default"));
  EXPECT_TRUE(has_note(notes, "type chain: EI = 2.5e3", "dropped"));
  EXPECT_TRUE(has_note(notes, "type chain: Cl = 0.8", "ignored"));
  EXPECT_TRUE(has_note(notes, "point 2: CdA = 1.5", "dropped"));
  EXPECT_TRUE(has_note(notes, "line output flags (1: pt)", "ignored"));
  EXPECT_TRUE(has_note(notes, "output channels: 2 (FairTen1, AnchTen1)", "ignored"));
  EXPECT_TRUE(has_note(notes, "seabed", "used"));
  // Friction: MoorDyn's is a damper that holds nothing at rest; the seabed is written with 0.
  const auto friction = std::find_if(notes.begin(), notes.end(), [](const MoorDynNote& n) {
    return n.item == "option FrictionCoefficient = 0.5";
  });
  ASSERT_NE(friction, notes.end());
  EXPECT_NE(friction->detail.find("zero at rest"), std::string::npos) << friction->detail;
}

TEST(MoorDynNotes, FreePointPositionsAreReportedAsNotUsed) {
  // Two lines in series through a free point: its position is MoorDyn's initial guess.
  std::string text = w_deck(kOptions);
  replace_once(text, "2   Vessel", "3   Vessel");
  text.insert(text.find("3   Vessel"), "2   Free        200.0  0.0  -280.0  0    0    0    0\n");
  replace_once(text, "1   chain     1        2        600.0",
               "1   chain     1        2        300.0");
  text.insert(text.find("---------------------- OPTIONS"),
              "2   chain     2        3        300.0     20       -\n");
  const MoorDynDeck deck = deck_from("free.dat", text);
  EXPECT_TRUE(has_note(moordyn_deck_notes(deck), "point 2 (Free) at (200, 0, -280) m", "not used"));
  const auto scenes = convert_moordyn_deck(deck, "free");
  ASSERT_EQ(scenes.size(), 1u);
  EXPECT_EQ(scenes[0].lines, (std::vector<int>{1, 2}));
  EXPECT_NE(scenes[0].toml.find("point 2 (Free) at (200, 0, -280) m: not used - "),
            std::string::npos);
}

TEST(MoorDynSeabed, DepthFromTheOptionsOrMoorDynCsRule) {
  std::string text = w_deck(kOptions);
  EXPECT_EQ(moordyn_seabed(deck_from("depth.dat", text)).z_m, -300.0);
  // A point below WtrDpth: MoorDyn-C lowers the seabed to it.
  replace_once(text, "300      WtrDpth", "200      WtrDpth");
  const MoorDynSeabed lowered = moordyn_seabed(deck_from("lowered.dat", text));
  EXPECT_EQ(lowered.z_m, -250.0);
  EXPECT_NE(lowered.source.find("lowers the seabed"), std::string::npos) << lowered.source;
  // MoorDyn-F's DEFAULT (OpenFAST's depth, not in the deck): the deepest point, said so.
  replace_once(text, "200      WtrDpth", "DEFAULT  WtrDpth");
  const MoorDynDeck defaulted = deck_from("default.dat", text);
  EXPECT_EQ(moordyn_seabed(defaulted).z_m, -250.0);
  EXPECT_TRUE(has_note(moordyn_deck_notes(defaulted), "option WtrDpth = DEFAULT", "not used"));
  // A bathymetry file: Catena's seabed is flat; no [seabed], and the line is compared with the
  // deepest point of the deck instead.
  replace_once(text, "DEFAULT  WtrDpth", "bathy.txt WtrDpth");
  const MoorDynDeck bathymetry = deck_from("bathymetry.dat", text);
  EXPECT_FALSE(moordyn_seabed(bathymetry).z_m.has_value());
  const auto scenes = convert_moordyn_deck(bathymetry, "bathymetry");
  ASSERT_EQ(scenes.size(), 1u);
  EXPECT_EQ(scenes[0].toml.find("\n[seabed]"), std::string::npos);
  EXPECT_EQ(scenes[0].tables, "[cable]");
  ASSERT_TRUE(scenes[0].statics_solved) << scenes[0].statics;
  const bool below = std::any_of(scenes[0].notes.begin(), scenes[0].notes.end(), [](const auto& n) {
    return n.find("below the deepest point of the deck (-250 m)") != std::string::npos;
  });
  EXPECT_TRUE(below);
}

// ---- What makes a MoorDyn free decay non-linear (io/internal/moordyn_free_decay_notes.hpp) ----

// The note of `scene` that starts with `prefix`, or "" when none does.
std::string note_starting(const ImportedScene& scene, const std::string& prefix) {
  for (const auto& note : scene.notes) {
    if (note.rfind(prefix, 0) == 0) return note;
  }
  return "";
}

// The number printed right after `marker` in `text` (NaN when the marker is absent).
double number_after(const std::string& text, const std::string& marker) {
  const auto at = text.find(marker);
  if (at == std::string::npos) return std::nan("");
  return std::stod(text.substr(at + marker.size()));
}

// The submerged weight per metre of w_deck's chain with MoorDyn-C's defaults g = 9.80665 m/s^2 and
// rho_w = 1025 kg/m^3 (kOptions gives neither) [N/m].
const double kChainWeight = (100.0 - 1025.0 * kPi / 4.0 * 0.1 * 0.1) * 9.80665;

// The inextensible catenary between (0, 0) and (X, h) of length L, solved here as in
// catenary_lowest_z: its parameter a = H / w [m], and the extremes the notes report: the largest
// distance from the chord (by 1e5 samples of z(x) = a (cosh((x - x0)/a) - cosh(x0/a))), and the
// lowest and largest tension a w and (a + h - z_vertex) w (T = w (a + z - z_vertex) on a catenary).
struct CatenaryExtremes {
  double a = 0.0, sag = 0.0, lowest_z = 0.0, tension_ratio = 0.0, vertex_s = 0.0;
};
CatenaryExtremes catenary_extremes(double X, double h, double L) {
  const double target = std::sqrt(L * L - h * h);
  double lo = 1e-3, hi = 1e6;
  for (int i = 0; i < 200; ++i) {
    const double a = 0.5 * (lo + hi);
    (2.0 * a * std::sinh(X / (2.0 * a)) > target ? lo : hi) = a;
  }
  CatenaryExtremes out;
  out.a = 0.5 * (lo + hi);
  const double a = out.a;
  const double x0 = X / 2.0 - a * std::asinh(h / (2.0 * a * std::sinh(X / (2.0 * a))));
  for (int i = 0; i <= 100000; ++i) {
    const double x = X * i / 100000.0;
    const double z = a * (std::cosh((x - x0) / a) - std::cosh(x0 / a));
    out.sag = std::max(out.sag, std::abs(X * z - h * x) / std::hypot(X, h));
  }
  out.lowest_z = a * (1.0 - std::cosh(x0 / a));
  out.vertex_s = a * std::sinh(x0 / a);
  out.tension_ratio = a / (a + h - out.lowest_z);
  return out;
}

// w_deck's line with both ends moved and its length changed, over a seabed 1000 m deep (off it).
std::string suspended_deck(const std::string& a_z,
                           const std::string& b,
                           const std::string& length) {
  std::string text = w_deck(kOptions);
  replace_once(text, "300      WtrDpth", "1000     WtrDpth");
  replace_once(text, "0.0    0.0  -250.0", "0.0    0.0  " + a_z);
  replace_once(text, "400.0  0.0  -20.0", b);
  replace_once(text, "600.0     40", length + "     40");
  return text;
}

TEST(MoorDynFreeDecayNotes, QuadraticDragIsNamedWithTheDampingRatioItAddsPerMetre) {
  const auto scenes = convert_moordyn_deck(deck_from("drag.dat", w_deck(kOptions)), "drag");
  ASSERT_EQ(scenes.size(), 1u);
  const std::string note =
      note_starting(scenes[0], "Free decay: line 1 (type chain) has quadratic");
  ASSERT_FALSE(note.empty());
  // Independently: the energy 1/2 rho_w Cd Diam |v| v dissipates over one cycle of v = w a cos(w t)
  // (trapezoidal sum), as a linear damper c that dissipates as much (c = E / int v^2 dt), and its
  // damping ratio c / (2 w M) with M = MassDen + Ca rho_w pi/4 Diam^2, at a = 1 m.
  const double rho = 1025.0, omega = 0.7, a = 1.0, period = 2.0 * kPi / omega;
  const double M = 100.0 + 1.0 * rho * kPi / 4.0 * 0.01;
  double dissipated = 0.0, squared = 0.0;
  constexpr int kSteps = 20000;
  for (int i = 0; i < kSteps; ++i) {
    const double v = omega * a * std::cos(omega * period * i / kSteps);
    dissipated += 0.5 * rho * 1.2 * 0.1 * std::abs(v) * v * v * period / kSteps;
    squared += v * v * period / kSteps;
  }
  const double zeta_per_metre = dissipated / squared / (2.0 * omega * M);
  EXPECT_NEAR(number_after(note, "at most a damping ratio of "), zeta_per_metre,
              2e-3 * zeta_per_metre)  // 3 digits printed
      << note;
  EXPECT_NE(note.find("set Cd = CdAx = 0"), std::string::npos) << note;
  // Along the line: CdAx = 0.4 on pi Diam, mass MassDen (CaAx = 0).
  const double tangential = zeta_per_metre * (0.4 * kPi / 1.2) * (M / 100.0);
  EXPECT_NEAR(number_after(note, "and "), tangential, 2e-3 * tangential) << note;
  // Without drag, no such note.
  std::string text = w_deck(kOptions);
  replace_once(text, "1.2  1.0  0.4", "0.0  1.0  0.0");
  const auto no_drag = convert_moordyn_deck(deck_from("nodrag.dat", text), "nodrag");
  ASSERT_EQ(no_drag.size(), 1u);
  for (const auto& n : no_drag[0].notes) EXPECT_EQ(n.find("quadratic drag"), std::string::npos);
}

TEST(MoorDynFreeDecayNotes, AmplitudeScaleTensionAndClearanceOfASuspendedLine) {
  // A at (0, -250), B at (400, -20), 600 m, EA = 1e20 N (inextensible to 1e-16), seabed at -1000.
  const auto scenes = convert_moordyn_deck(
      deck_from("suspended.dat", suspended_deck("-250.0", "400.0  0.0  -20.0", "600.0")), "s");
  ASSERT_EQ(scenes.size(), 1u);
  ASSERT_TRUE(scenes[0].statics_solved) << scenes[0].statics;
  const CatenaryExtremes c = catenary_extremes(400.0, 230.0, 600.0);
  // l = sqrt(d^2 + L^2 H/EA) = d here (L sqrt(H/EA) ~ 1e-6 m); 4 digits printed.
  const std::string scale = note_starting(scenes[0], "Free decay: small means");
  EXPECT_NEAR(number_after(scale, "sqrt(d^2 + L^2 H/EA) = "), c.sag, 1e-3 * c.sag) << scale;
  EXPECT_NEAR(number_after(scale, "a <= "), 0.01 * c.sag, 1e-5 * c.sag) << scale;
  // The lowest tension is H = a w at the vertex, 31 % of the fairlead's: not nearly slack.
  const std::string tension = note_starting(scenes[0], "Free decay: lowest static tension");
  ASSERT_FALSE(tension.empty());
  EXPECT_NEAR(number_after(tension, "lowest static tension "), c.a * kChainWeight,
              1e-3 * c.a * kChainWeight)
      << tension;
  // At the vertex, s = a sinh(x0 / a) from A, within the notes' sampling (L / 2000).
  EXPECT_NEAR(number_after(tension, "N at s = "), c.vertex_s, 0.3) << tension;
  EXPECT_NEAR(number_after(tension, " m ("), 100.0 * c.tension_ratio, 0.2 * c.tension_ratio)
      << tension;
  // Clearance: the vertex 668 m above the seabed.
  const std::string clear = note_starting(scenes[0], "Free decay: the line is off the seabed");
  const double clearance = -250.0 + c.lowest_z + 1000.0;
  EXPECT_NEAR(number_after(clear, "its lowest point "), clearance, 1e-3 * clearance) << clear;
}

TEST(MoorDynFreeDecayNotes, ADeepUIsNearlySlack) {
  // A at (0, -250), B at (200, -150), 800 m: a = 30.7 m, lowest tension 6.8 % of the largest.
  const auto scenes = convert_moordyn_deck(
      deck_from("deep-u.dat", suspended_deck("-250.0", "200.0  0.0  -150.0", "800.0")), "u");
  ASSERT_EQ(scenes.size(), 1u);
  ASSERT_TRUE(scenes[0].statics_solved) << scenes[0].statics;
  const CatenaryExtremes c = catenary_extremes(200.0, 100.0, 800.0);
  ASSERT_LT(c.tension_ratio, 0.1);
  const std::string tension = note_starting(scenes[0], "Free decay: nearly slack: lowest static");
  ASSERT_FALSE(tension.empty()) << scenes[0].toml;
  EXPECT_NEAR(number_after(tension, "tension "), c.a * kChainWeight, 1e-3 * c.a * kChainWeight)
      << tension;
  EXPECT_NE(tension.find("slackens the line"), std::string::npos) << tension;
}

TEST(MoorDynFreeDecayNotes, SeabedContactNamesTheTouchdownsAndTheStaticPenetration) {
  // w_deck's line rests on the seabed between two suspended parts: two touchdown points; MoorDyn's
  // grounded node sits w / (kBot Diam) below the seabed (kBot = 2e6 Pa/m, Diam = 0.1 m).
  const auto scenes = convert_moordyn_deck(deck_from("contact.dat", w_deck(kOptions)), "c");
  ASSERT_EQ(scenes.size(), 1u);
  if (!scenes[0].statics_solved) GTEST_SKIP() << "the seabed statics refuses this line";
  const auto note = std::find_if(scenes[0].notes.begin(), scenes[0].notes.end(), [](const auto& n) {
    return n.find("rest on the seabed (touchdown at s = ") != std::string::npos;
  });
  ASSERT_NE(note, scenes[0].notes.end()) << scenes[0].toml;
  const double penetration_mm = 1e3 * kChainWeight / (2.0e6 * 0.1);
  EXPECT_NEAR(number_after(*note, "static penetration, w / (kBot Diam) = "), penetration_mm,
              2e-3 * penetration_mm)
      << *note;
  EXPECT_EQ(std::count(note->begin(), note->end(), '='), 3) << *note;  // two touchdowns + w/(..)
  EXPECT_NE(note->find("one-sided"), std::string::npos) << *note;
}

TEST(MoorDynFreeDecayNotes, AnAnchorOnTheSeabedWithTheLineRisingFromItIsNotContact) {
  // A on the seabed at -300 m, B at (400, -20), 500 m: the catenary's vertex lies beyond A, so the
  // line rises from the anchor at atan(sinh(-x0 / a)) above the horizontal.
  std::string text = w_deck(kOptions);
  replace_once(text, "0.0    0.0  -250.0", "0.0    0.0  -300.0");
  replace_once(text, "600.0     40", "500.0     40");
  const auto scenes = convert_moordyn_deck(deck_from("rising.dat", text), "r");
  ASSERT_EQ(scenes.size(), 1u);
  ASSERT_TRUE(scenes[0].statics_solved) << scenes[0].statics;
  const std::string note = note_starting(scenes[0], "Free decay: the line touches the seabed only");
  ASSERT_FALSE(note.empty()) << scenes[0].toml;
  const double X = 400.0, h = 280.0, L = 500.0;
  const CatenaryExtremes c = catenary_extremes(X, h, L);
  const double x0 = X / 2.0 - c.a * std::asinh(h / (2.0 * c.a * std::sinh(X / (2.0 * c.a))));
  ASSERT_LT(x0, 0.0);
  const double angle = std::atan(std::sinh(-x0 / c.a)) * 180.0 / kPi;
  EXPECT_NEAR(number_after(note, "rises from it at "), angle, 2e-3 * angle) << note;
}

}  // namespace
}  // namespace catena
