// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Reading a MoorDyn input file (v1 and v2 layouts; docs/how-to/moordyn-import.md) into plain data,
/// for `catena import moordyn`. The file is a sequence of sections introduced by header lines that
/// start with "---" and name the section (case-insensitive, any text around it): LINE TYPES or
/// LINE DICTIONARY, POINTS (or POINT LIST, POINT PROPERTIES, CONNECTION PROPERTIES, NODE
/// PROPERTIES), LINES (or LINE LIST, LINE PROPERTIES), OPTIONS (or SOLVER OPTIONS); ROD TYPES,
/// RODS, BODIES, FAILURE, SYROPE IC and OUTPUTS are recognised and only recorded. Each table
/// section has a column-name row and a units row (in parentheses) before its data rows; columns
/// are found by name, case-insensitive, so v1 (Can, NodeAnch/NodeFair) and v2 (Ca,
/// AttachA/AttachB) layouts both read. Lines before the first header are free text; lines
/// starting with '#' or '!' are comments; reading stops at the closing "need this line" header.

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace catena {

struct MoorDynLineType {
  std::string name;
  double diameter_m = 0.0;                     ///< volume-equivalent diameter
  double mass_kg_per_m = 0.0;                  ///< in air
  std::optional<double> axial_stiffness_n;     ///< absent when EA is not a number (a curve, Syrope)
  std::string axial_stiffness_text;            ///< EA as written
  double normal_added_mass_coefficient = 0.0;  ///< Can (v1) or Ca (v2)
  int file_line = 0;
  double normal_drag_coefficient = 0.0;            ///< Cdn (v1) or Cd (v2)
  double tangential_drag_coefficient = 0.0;        ///< Cdt (v1) or CdAx (v2), on pi Diam
  double tangential_added_mass_coefficient = 0.0;  ///< Cat (v1) or CaAx (v2)
  /// BA as written: > 0 the Kelvin-Voigt coefficient [N s]; < 0 minus a damping ratio (MoorDyn
  /// converts it per line with the line's segment length); absent when not a number (a curve, or
  /// a viscoelastic "BA|BA_D" pair).
  std::optional<double> axial_damping;
  std::string axial_damping_text;
  /// EI as written (v2); empty when the table has no EI column (v1).
  std::string bending_stiffness_text;
  /// Columns Catena does not read (e.g. Cl, dF, cF), as (name as written, value).
  std::vector<std::pair<std::string, std::string>> other_columns;
};

/// How a point is held (MoorDyn's type or attachment column).
enum class MoorDynPointKind {
  Fixed,    ///< Fixed, Fix, Anchor
  Coupled,  ///< Vessel, Ves, Coupled, Cpld, Fairlead
  Free,     ///< Free, Connect, Con, Point
  Body,     ///< Body<n>
  Other     ///< anything else (e.g. Turbine<n> of a FAST.Farm deck)
};

struct MoorDynPoint {
  int id = 0;
  std::string attachment;  ///< as written
  MoorDynPointKind kind = MoorDynPointKind::Fixed;
  double x_m = 0.0, y_m = 0.0, z_m = 0.0;
  double mass_kg = 0.0;
  double volume_m3 = 0.0;
  double added_mass_coefficient = 0.0;
  int file_line = 0;
  /// Columns Catena does not read (CdA, v1's FX FY FZ), as (name as written, value).
  std::vector<std::pair<std::string, std::string>> other_columns;
};

struct MoorDynLine {
  int id = 0;
  std::string type;
  std::string end_a;  ///< as written: a point number, or e.g. "R1A" (a rod end)
  std::string end_b;
  double length_m = 0.0;
  int segments = 0;
  int file_line = 0;
  /// Columns Catena does not read (Outputs/Flags), as (name as written, value).
  std::vector<std::pair<std::string, std::string>> other_columns;
};

/// One row of OPTIONS, as written.
struct MoorDynOption {
  std::string name;  ///< as written, e.g. "WtrDpth"
  std::string value;
  int file_line = 0;
};

struct MoorDynDeck {
  std::string file;
  std::vector<MoorDynLineType> types;
  std::vector<MoorDynPoint> points;
  std::vector<MoorDynLine> lines;
  /// Options by lower-case name, values as written (the last row of a name).
  std::map<std::string, std::string> options;
  /// Every OPTIONS row in file order (for the import summary: what became of each).
  std::vector<MoorDynOption> option_rows;
  /// The channels of the OUTPUTS section, as written.
  std::vector<std::string> outputs;
  /// Data rows of the ROD TYPES, RODS, BODIES and SYROPE IC sections.
  int rod_type_rows = 0;
  int rod_rows = 0;
  int body_rows = 0;
  int syrope_rows = 0;
  bool has_rods = false;
  bool has_bodies = false;
  /// Lines named in a FAILURE section.
  std::vector<int> failing_lines;

  /// Gravity [m/s^2], water density [kg/m^3], depth [m] (absent when silent or not a number,
  /// e.g. MoorDyn-F's "DEFAULT" or a bathymetry file), bottom stiffness [Pa/m] and damping
  /// [Pa s/m]: from the options (g/gravity, rho/rhow/wtrdnsty, wtrdpth/depth, kbot/kb, cbot/cb),
  /// else MoorDyn-C's defaults 9.80665, 1025, none, 3e6, 3e5.
  double gravity() const;
  double water_density() const;
  std::optional<double> water_depth() const;
  double bottom_stiffness() const;
  double bottom_damping() const;
  /// The bathymetry file MoorDyn would read instead of a flat seabed (MoorDyn-C's SeafloorFile,
  /// or MoorDyn-F's WtrDpth given as a file name); empty when none.
  std::string bathymetry_file() const;
};

/// Reads a deck. InvalidInput naming the file and line for: a byte that is not text (a binary
/// file), an empty deck, an unknown section or a header of dashes only, a missing or empty LINE
/// TYPES or LINES section (a truncated deck), a table without the columns it needs, a value that
/// is not a decimal number (hexadecimal, NaN and infinities included), a negative diameter, mass
/// or volume, a non-positive UnstrLen, an ID or NumSegs that is not an integer, a line type,
/// point or line defined twice, or an option Catena uses that is not a number (g <= 0, negative
/// density or seabed coefficients); ParseError when the file cannot be read.
MoorDynDeck read_moordyn_deck(const std::filesystem::path& path);

/// The same, from the deck's text; `file` names it in messages.
MoorDynDeck parse_moordyn_deck_text(const std::string& text, const std::string& file);

}  // namespace catena
