// SPDX-License-Identifier: MIT
// What the MoorDyn reader refuses (io/moordyn_deck.hpp; issue 32): each malformed deck is
// InvalidInput naming the line, never a deck read as if it were fine; and the scenes the importer
// writes read back with Catena's own reader whatever the deck's names hold (issue 32, item 3).
// The decks are written here, one small uniform line, and each test changes one thing in it.
#include "catena/io/moordyn_deck.hpp"

#include <gtest/gtest.h>

#include <string>

#include "catena/core/error.hpp"
#include "catena/io/moordyn_import.hpp"
#include "catena/io/scene_reader.hpp"

namespace catena {
namespace {

const std::string kTypes = R"(---------------------- LINE TYPES ----------------------
Name   Diam  MassDen  EA     BA/-zeta  EI   Cd   Ca   CdAx  CaAx
(-)    (m)   (kg/m)   (N)    (N-s/-)   (-)  (-)  (-)  (-)   (-)
chain  0.1   100.0    1e9    0.0       0    1.2  1.0  0.4   0.0
)";
const std::string kPoints = R"(---------------------- POINTS --------------------------
ID  Attachment  X      Y    Z       M    V
(#) (-)         (m)    (m)  (m)     (kg) (m^3)
1   Fixed       0.0    0.0  -100.0  0    0
2   Vessel      300.0  0.0  0.0     0    0
)";
const std::string kLines = R"(---------------------- LINES ---------------------------
ID  LineType  AttachA  AttachB  UnstrLen  NumSegs
(#) (name)    (#)      (#)      (m)       (-)
1   chain     1        2        350.0     20
)";
const std::string kOptions = R"(---------------------- OPTIONS -------------------------
9.81     g
1025     rho
------------------------- need this line ---------------------------
)";

// The deck's text: a title (line 1), then line types (2-5), points (6-10), lines (11-14) and
// options (15-18).
std::string deck(const std::string& types = kTypes,
                 const std::string& points = kPoints,
                 const std::string& lines = kLines,
                 const std::string& options = kOptions) {
  return "A deck written for Catena's tests\n" + types + points + lines + options;
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

// The message of the InvalidInput that reading `text` throws ("" when it reads).
std::string refusal(const std::string& text) {
  try {
    parse_moordyn_deck_text(text, "deck.txt");
  } catch (const InvalidInput& error) {
    return error.what();
  }
  return "";
}

TEST(MoorDynDeck, TheBaseDeckReads) {
  const MoorDynDeck d = parse_moordyn_deck_text(deck(), "deck.txt");
  ASSERT_EQ(d.types.size(), 1u);
  ASSERT_EQ(d.points.size(), 2u);
  ASSERT_EQ(d.lines.size(), 1u);
  EXPECT_EQ(d.gravity(), 9.81);
}

TEST(MoorDynDeck, RefusesADashesOnlyHeader) {
  EXPECT_NE(refusal(replaced(deck(), "---------------------- POINTS ---",
                             "-------------------------------"))
                .find("deck.txt:6: a section header of dashes only"),
            std::string::npos);
}

TEST(MoorDynDeck, RefusesBinaryGarbage) {
  EXPECT_NE(refusal(replaced(deck(), "(-)         (m)", std::string("(-)  \x01\x00 (m)", 11)))
                .find("deck.txt:8: byte 0x01"),
            std::string::npos);
  const std::string garbage(
      "\x7F"
      "ELF\x02\x01\x01\x00\x00\x00",
      10);
  EXPECT_NE(refusal(garbage).find("deck.txt:1: byte 0x7F"), std::string::npos);
}

TEST(MoorDynDeck, RefusesEmptyAndTruncatedDecks) {
  EXPECT_NE(refusal("").find("deck.txt: empty deck"), std::string::npos);
  // Cut after the LINES header: the section has no rows.
  const std::string cut = deck().substr(0, deck().find("ID  LineType"));
  EXPECT_NE(refusal(cut).find("deck.txt:11: the LINES section has no data rows"),
            std::string::npos);
  // Cut before the LINES section: it is missing (the last line read is named).
  EXPECT_NE(refusal(deck(kTypes, kPoints, "", "")).find("deck.txt:10: no LINES section"),
            std::string::npos);
  EXPECT_NE(refusal(deck("", kPoints, kLines)).find("no LINE TYPES section"), std::string::npos);
}

TEST(MoorDynDeck, RefusesDuplicateIds) {
  EXPECT_NE(
      refusal(deck(kTypes + "chain  0.2   50.0    1e9    0.0       0    1.2  1.0  0.4   0.0\n"))
          .find("deck.txt:6: line type 'chain' is defined twice (first at line 5)"),
      std::string::npos);
  EXPECT_NE(refusal(deck(kTypes, kPoints + "1   Fixed  10.0  0.0  -100.0  0  0\n"))
                .find("deck.txt:11: point 1 is defined twice (first at line 9)"),
            std::string::npos);
  EXPECT_NE(
      refusal(deck(kTypes, kPoints, kLines + "1   chain     1        2        350.0     20\n"))
          .find("deck.txt:15: line 1 is defined twice (first at line 14)"),
      std::string::npos);
  EXPECT_NE(refusal(deck(kTypes, kPoints, kLines + kLines)).find("deck.txt:15: a second"),
            std::string::npos);
}

TEST(MoorDynDeck, RefusesNegativeMassDiameterAndVolume) {
  EXPECT_NE(refusal(replaced(deck(), "0.1   100.0", "0.1   -100.0"))
                .find("deck.txt:5: 'MassDen' = -100.0 is negative"),
            std::string::npos);
  EXPECT_NE(refusal(replaced(deck(), "0.1   100.0", "-0.1   100.0"))
                .find("deck.txt:5: 'Diam' = -0.1 is negative"),
            std::string::npos);
  EXPECT_NE(refusal(replaced(deck(), "0.0     0    0\n", "0.0     -5    0\n"))
                .find("deck.txt:10: 'Mass' = -5 is negative"),
            std::string::npos);
  EXPECT_NE(refusal(replaced(deck(), "350.0", "-350.0")).find("deck.txt:14: 'UnstrLen'"),
            std::string::npos);
}

TEST(MoorDynDeck, RefusesNonPositiveGravity) {
  EXPECT_NE(refusal(replaced(deck(), "9.81     g", "-9.81     g"))
                .find("deck.txt:16: option g = -9.81: gravity must not be negative"),
            std::string::npos);
  // g = 0 (decks of MoorDyn's own tests) reads; the line is then not converted, with the reason.
  const MoorDynDeck weightless =
      parse_moordyn_deck_text(replaced(deck(), "9.81     g", "0     g"), "deck.txt");
  const auto scenes = convert_moordyn_deck(weightless, "stem");
  ASSERT_EQ(scenes.size(), 1u);
  EXPECT_TRUE(scenes[0].toml.empty());
  EXPECT_NE(scenes[0].reason.find("g = 0"), std::string::npos);
  EXPECT_NE(refusal(replaced(deck(), "1025     rho", "-1025     rho")).find("deck.txt:17:"),
            std::string::npos);
}

TEST(MoorDynDeck, RefusesHexadecimalNanAndInfiniteNumbers) {
  // strtod reads all of these; MoorDyn's decks are decimal.
  EXPECT_NE(refusal(replaced(deck(), "350.0", "0x1p3"))
                .find("deck.txt:14: 'UnstrLen': '0x1p3' is a hexadecimal number"),
            std::string::npos);
  EXPECT_NE(refusal(replaced(deck(), "1e9 ", "0x3B9ACA00 ")).find("deck.txt:5: 'EA'"),
            std::string::npos);
  EXPECT_NE(refusal(replaced(deck(), "9.81     g", "0x9.cp0     g")).find("deck.txt:16:"),
            std::string::npos);
  EXPECT_NE(refusal(replaced(deck(), "300.0  0.0  0.0", "nan  0.0  0.0"))
                .find("deck.txt:10: 'X': 'nan' is not a finite number"),
            std::string::npos);
  EXPECT_NE(refusal(replaced(deck(), "1e9 ", "inf ")).find("deck.txt:5: 'EA': 'inf'"),
            std::string::npos);
  EXPECT_NE(refusal(replaced(deck(), "1   Fixed", "1e12   Fixed")).find("deck.txt:9: 'ID'"),
            std::string::npos);
}

// The scene the importer writes for `text`, read back by Catena's scene reader.
std::vector<Scene> imported_and_read(const std::string& text, const std::string& file) {
  const MoorDynDeck d = parse_moordyn_deck_text(text, file);
  const auto scenes = convert_moordyn_deck(d, "stem\"with\\quote");
  EXPECT_EQ(scenes.size(), 1u);
  EXPECT_FALSE(scenes.at(0).toml.empty());
  return parse_scene_text(scenes.at(0).toml, "imported.toml");
}

TEST(MoorDynImport, WritesNamesWithQuotesBackslashesAndInvalidUtf8AsValidToml) {
  const std::string name = "ch\"a\\in\xFF";
  const std::string text =
      replaced(replaced(deck(), "chain  0.1", name + "  0.1"), "1   chain", "1   " + name);
  const std::vector<Scene> scenes = imported_and_read(text, "my \"deck\" \\ file.txt");
  ASSERT_EQ(scenes.size(), 1u);
  EXPECT_EQ(scenes[0].name, "stem\"with\\quote-line-1");
  // The invalid byte is spelled out; the rest is kept as written.
  EXPECT_NE(scenes[0].description.find("my \"deck\" \\ file.txt"), std::string::npos)
      << scenes[0].description;
}

// Found by the MoorDyn fuzz target: a deck value beyond the scene format's ranges (here a
// negative CdAx, the scene's drag_tangential) gave a scene file that Catena's own reader refuses.
// The line is now listed as not converted, with the reader's reason, and no scene is written.
TEST(MoorDynImport, AValueTheSceneReaderRefusesLeavesTheLineNotConverted) {
  const MoorDynDeck d =
      parse_moordyn_deck_text(replaced(deck(), "1.0  0.4", "1.0  -0.4"), "deck.txt");
  const auto scenes = convert_moordyn_deck(d, "stem");
  ASSERT_EQ(scenes.size(), 1u);
  EXPECT_TRUE(scenes[0].toml.empty());
  EXPECT_NE(scenes[0].reason.find("the scene would not read"), std::string::npos)
      << scenes[0].reason;
  EXPECT_NE(scenes[0].reason.find("drag_tangential"), std::string::npos) << scenes[0].reason;
}

}  // namespace
}  // namespace catena
