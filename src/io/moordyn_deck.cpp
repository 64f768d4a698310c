// SPDX-License-Identifier: MIT
// MoorDyn decks (v1 and v2 layouts) read into plain data (docs/how-to/moordyn-import.md). Written
// from MoorDyn's documented input format, not from its code.
#include "catena/io/moordyn_deck.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "catena/core/error.hpp"
#include "catena/io/file_access.hpp"

namespace catena {
namespace {

enum class Section {
  Preamble,
  LineTypes,
  RodTypes,
  Bodies,
  Rods,
  Points,
  Lines,
  Failure,
  SyropeIc,
  Options,
  Outputs,
  End
};

// Checked in this order against the upper-cased header text (MoorDyn, too, looks for the name
// anywhere in the header line).
const std::pair<const char*, Section> kSectionNames[] = {{"LINE DICTIONARY", Section::LineTypes},
                                                         {"LINE TYPES", Section::LineTypes},
                                                         {"ROD DICTIONARY", Section::RodTypes},
                                                         {"ROD TYPES", Section::RodTypes},
                                                         {"BODIES", Section::Bodies},
                                                         {"BODY LIST", Section::Bodies},
                                                         {"BODY PROPERTIES", Section::Bodies},
                                                         {"RODS", Section::Rods},
                                                         {"ROD LIST", Section::Rods},
                                                         {"ROD PROPERTIES", Section::Rods},
                                                         {"POINTS", Section::Points},
                                                         {"POINT LIST", Section::Points},
                                                         {"POINT PROPERTIES", Section::Points},
                                                         {"CONNECTION PROPERTIES", Section::Points},
                                                         {"NODE PROPERTIES", Section::Points},
                                                         {"LINES", Section::Lines},
                                                         {"LINE LIST", Section::Lines},
                                                         {"LINE PROPERTIES", Section::Lines},
                                                         {"FAILURE", Section::Failure},
                                                         {"SYROPE IC", Section::SyropeIc},
                                                         {"OPTIONS", Section::Options},
                                                         {"OUTPUT", Section::Outputs},
                                                         {"NEED THIS LINE", Section::End},
                                                         {"MOORDYN", Section::Preamble}};

// The options Catena uses, by their MoorDyn names (lower case).
const std::vector<std::string> kGravityNames = {"g", "gravity"};
const std::vector<std::string> kDensityNames = {"rho", "rhow", "wtrdnsty"};
const std::vector<std::string> kDepthNames = {"wtrdpth", "depth", "waterdepth"};
const std::vector<std::string> kBottomStiffnessNames = {"kbot", "kb"};
const std::vector<std::string> kBottomDampingNames = {"cbot", "cb"};

std::string upper(std::string text) {
  for (char& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return text;
}
std::string lower(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

std::vector<std::string> tokens(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> out;
  for (std::string token; in >> token;) out.push_back(token);
  return out;
}

// MoorDyn's numbers are decimal. strtod also reads hexadecimal ("0x1p3"), "nan" and "inf": those
// are not numbers here (a value that is one is refused by name, see special_number).
std::optional<double> number(const std::string& text) {
  if (text.find_first_not_of("0123456789+-.eE") != std::string::npos) return std::nullopt;
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value))
    return std::nullopt;
  return value;
}

// Why `text` looks like a number but is not one Catena reads ("" when it does not look like one):
// hexadecimal floats, NaN and infinities, which strtod (and so MoorDyn's atof) would accept.
std::string special_number(const std::string& text) {
  std::string t = lower(text);
  if (!t.empty() && (t[0] == '+' || t[0] == '-')) t.erase(0, 1);
  if (t.rfind("0x", 0) == 0) return "a hexadecimal number (write it in decimal)";
  if (t.rfind("nan", 0) == 0 || t.rfind("inf", 0) == 0) return "not a finite number";
  if (!t.empty() && (std::isdigit(static_cast<unsigned char>(t[0])) || t[0] == '.') &&
      !number(text))
    return "not a number";
  return "";
}

// A table section: its column names (lower case) and data rows with their file lines.
struct Table {
  std::vector<std::string> columns;
  std::vector<std::string> names;  // the column names as written
  bool units_seen = false;
  std::vector<std::pair<int, std::vector<std::string>>> rows;
  int header_line = 0;
  int section_line = 0;  // the "---" line that opened it (0: the deck has no such section)
};

struct Reader {
  std::string file;
  std::map<Section, Table> tables;
  MoorDynDeck deck;

  [[noreturn]] void fail(int line, const std::string& why) const {
    throw InvalidInput(fmt::format("{}:{}: {}", file, line, why));
  }
  // The column's index: the first of `names` present, else `fallback` (-1: required, fail).
  std::size_t column(const Table& table,
                     std::initializer_list<const char*> names,
                     int fallback,
                     const char* what) const {
    for (const char* name : names) {
      const auto it = std::find(table.columns.begin(), table.columns.end(), name);
      if (it != table.columns.end()) return static_cast<std::size_t>(it - table.columns.begin());
    }
    if (fallback < 0) fail(table.header_line, fmt::format("no '{}' column in the header", what));
    return static_cast<std::size_t>(fallback);
  }
  const std::string& cell(const std::pair<int, std::vector<std::string>>& row,
                          std::size_t index,
                          const char* what) const {
    if (index >= row.second.size()) fail(row.first, fmt::format("missing value for '{}'", what));
    return row.second[index];
  }
  double value(const std::pair<int, std::vector<std::string>>& row,
               std::size_t index,
               const char* what) const {
    const std::string& text = cell(row, index, what);
    const auto parsed = number(text);
    if (!parsed) {
      const std::string why = special_number(text);
      fail(row.first,
           fmt::format("'{}': '{}' is {}", what, text, why.empty() ? "not a number" : why));
    }
    return *parsed;
  }
  // A value that must not be negative (a mass, a diameter, a volume).
  double non_negative(const std::pair<int, std::vector<std::string>>& row,
                      std::size_t index,
                      const char* what) const {
    const double parsed = value(row, index, what);
    if (parsed < 0.0)
      fail(row.first, fmt::format("'{}' = {} is negative", what, cell(row, index, what)));
    return parsed;
  }
  // An integer (an ID, a segment count): a whole number that fits an int.
  int integer(const std::pair<int, std::vector<std::string>>& row,
              std::size_t index,
              const char* what) const {
    const double parsed = value(row, index, what);
    if (parsed != std::floor(parsed) || std::abs(parsed) > 1.0e9)
      fail(row.first, fmt::format("'{}': '{}' is not an integer of at most 9 digits", what,
                                  cell(row, index, what)));
    return static_cast<int>(parsed);
  }
  // A cell that may be a constant or text (EA, BA: a curve file, "BA|BA_D"): a hexadecimal,
  // NaN or infinite number is refused rather than read as a curve's name.
  const std::string& text_or_number(const std::pair<int, std::vector<std::string>>& row,
                                    std::size_t index,
                                    const char* what) const {
    const std::string& text = cell(row, index, what);
    const std::string why = special_number(text);
    if (!why.empty() && why != "not a number")
      fail(row.first, fmt::format("'{}': '{}' is {}", what, text, why));
    return text;
  }
};

// The cells of `row` in columns not in `used`, with the column's name as written (a cell beyond
// the header's names is named by its position).
std::vector<std::pair<std::string, std::string>> other_columns(
    const Table& table,
    const std::pair<int, std::vector<std::string>>& row,
    std::initializer_list<std::size_t> used) {
  std::vector<std::pair<std::string, std::string>> out;
  for (std::size_t i = 0; i < row.second.size(); ++i) {
    if (std::find(used.begin(), used.end(), i) != used.end()) continue;
    out.emplace_back(i < table.names.size() ? table.names[i] : fmt::format("column {}", i + 1),
                     row.second[i]);
  }
  return out;
}

Section section_of(const std::string& header, int line, const std::string& file) {
  const std::string text = upper(header);
  for (const auto& [name, section] : kSectionNames) {
    if (text.find(name) != std::string::npos) return section;
  }
  throw InvalidInput(fmt::format("{}:{}: unknown section '{}'", file, line, header));
}

// One line of a table section: the column names, the units row, or a data row. A leading count
// line of old decks ("3  NTypes  - number of line types") is skipped.
void add_table_line(Table& table, const std::vector<std::string>& words, int line) {
  if (table.columns.empty()) {
    if (words.size() >= 2 && number(words[0]) &&
        std::toupper(static_cast<unsigned char>(words[1][0])) == 'N')
      return;
    for (const auto& word : words) table.columns.push_back(lower(word));
    table.names = words;
    table.header_line = line;
  } else if (!table.units_seen && table.rows.empty() && words[0].front() == '(') {
    table.units_seen = true;
  } else {
    table.rows.push_back({line, words});
  }
}

void add_option(Reader& reader, const std::vector<std::string>& words, int line) {
  if (words.size() < 2) return;  // MoorDyn ignores such lines too
  const std::string name = lower(words[1]);
  // WtrDpth may be MoorDyn-F's "DEFAULT" (OpenFAST's depth) or a bathymetry file: kept as written
  // and reported, not used (moordyn_notes.cpp).
  for (const auto* names :
       {&kGravityNames, &kDensityNames, &kBottomStiffnessNames, &kBottomDampingNames}) {
    if (std::find(names->begin(), names->end(), name) == names->end()) continue;
    const auto value = number(words[0]);
    if (!value) {
      const std::string why = special_number(words[0]);
      reader.fail(line, fmt::format("option {}: '{}' is {}", words[1], words[0],
                                    why.empty() ? "not a number" : why));
    }
    // g is a magnitude (MoorDyn's z is up): negative is a sign error. g = 0 is a deck of MoorDyn's
    // own tests: read, and each line then not converted with the reason (moordyn_import.cpp).
    // No negative density or seabed coefficients either.
    if (*value < 0.0 && names == &kGravityNames)
      reader.fail(line, fmt::format("option {} = {}: gravity must not be negative (it is a "
                                    "magnitude; MoorDyn's z points up)",
                                    words[1], words[0]));
    if (*value < 0.0)
      reader.fail(line, fmt::format("option {} = {} is negative", words[1], words[0]));
  }
  reader.deck.options[name] = words[0];
  reader.deck.option_rows.push_back({words[1], words[0], line});
}

// A deck is text: a NUL or another control character (other than tab, CR, form feed) means a
// binary file or a corrupted one, refused rather than read as names.
void refuse_binary(const Reader& reader, const std::string& line, int line_number) {
  for (const char c : line) {
    const auto byte = static_cast<unsigned char>(c);
    if ((byte < 0x20 && c != '\t' && c != '\r' && c != '\f') || byte == 0x7F)
      reader.fail(line_number,
                  fmt::format("byte 0x{:02X}: not a text file (a MoorDyn deck is text)", byte));
  }
}

// Reads the sections; returns the number of the last line read (0 for an empty text).
int read_lines_of_file(Reader& reader, const std::string& text) {
  std::istringstream in(text);
  Section section = Section::Preamble;
  int line_number = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const auto words = tokens(line);
    refuse_binary(reader, line, line_number);
    if (words.empty() || words[0][0] == '#' || words[0][0] == '!') continue;
    if (words[0].rfind("---", 0) == 0) {
      const std::size_t first = line.find_first_not_of(" \t-");
      if (first == std::string::npos)
        reader.fail(line_number, "a section header of dashes only (no section name)");
      std::string header = line.substr(first);
      header = header.substr(0, header.find_last_not_of(" \t-") + 1);
      section = section_of(header, line_number, reader.file);
      // A second table of the same kind would read its column names as a data row.
      const bool read_table =
          section == Section::LineTypes || section == Section::Points || section == Section::Lines;
      if (read_table && reader.tables.count(section) && reader.tables[section].section_line > 0)
        reader.fail(line_number, fmt::format("a second '{}' section (the first is at line {})",
                                             header, reader.tables[section].section_line));
      reader.tables[section].section_line = line_number;
      if (section == Section::End) return line_number;
      if (section == Section::Rods) reader.deck.has_rods = true;
      if (section == Section::Bodies) reader.deck.has_bodies = true;
      continue;
    }
    if (section == Section::Options)
      add_option(reader, words, line_number);
    else if (section == Section::Outputs)
      reader.deck.outputs.push_back(words[0]);
    else if (section != Section::Preamble)
      add_table_line(reader.tables[section], words, line_number);
  }
  return line_number;
}

void convert_types(Reader& r) {
  const Table& t = r.tables[Section::LineTypes];
  if (t.rows.empty()) return;
  // v1: Name Diam MassDen EA BA Can Cat Cdn Cdt; v2: Name Diam MassDen EA BA EI Cd Ca CdAx CaAx
  // (the unnamed fallbacks are where MoorDyn-C's readLineProps reads them, source/MoorDyn2.cpp).
  const bool v1 = t.columns.size() <= 9;
  const auto diam = r.column(t, {"diam", "d"}, 1, "Diam");
  const auto mass = r.column(t, {"massden", "mass/m", "massdeninair", "mass", "m"}, 2, "MassDen");
  const auto ea = r.column(t, {"ea"}, 3, "EA");
  const auto ba = r.column(t, {"ba/-zeta", "ba", "ba/zeta", "ba/-zeta/-"}, 4, "BA");
  const auto ca = r.column(t, {"can", "ca"}, v1 ? 5 : 7, "Ca");
  const auto cd = r.column(t, {"cdn", "cd"}, v1 ? 7 : 6, "Cd");
  const auto cd_axial = r.column(t, {"cdt", "cdax"}, 8, "CdAx");
  const auto ca_axial = r.column(t, {"cat", "caax"}, v1 ? 6 : 9, "CaAx");
  // v1 has no EI column; v2 has it where MoorDyn reads it.
  const std::size_t ei = v1 ? std::size_t(-1) : r.column(t, {"ei"}, 5, "EI");
  for (const auto& row : t.rows) {
    MoorDynLineType type;
    type.name = row.second[0];
    for (const auto& other : r.deck.types) {
      if (other.name == type.name)
        r.fail(row.first, fmt::format("line type '{}' is defined twice (first at line {})",
                                      type.name, other.file_line));
    }
    type.diameter_m = r.non_negative(row, diam, "Diam");
    type.mass_kg_per_m = r.non_negative(row, mass, "MassDen");
    type.axial_stiffness_text = r.text_or_number(row, ea, "EA");
    type.normal_added_mass_coefficient = r.value(row, ca, "Ca");
    type.file_line = row.first;
    type.axial_stiffness_n = number(type.axial_stiffness_text);
    type.axial_damping_text = r.text_or_number(row, ba, "BA");
    type.axial_damping = number(type.axial_damping_text);
    type.normal_drag_coefficient = r.value(row, cd, "Cd");
    type.tangential_drag_coefficient = r.value(row, cd_axial, "CdAx");
    type.tangential_added_mass_coefficient = r.value(row, ca_axial, "CaAx");
    if (!v1 && ei < row.second.size()) type.bending_stiffness_text = row.second[ei];
    type.other_columns =
        other_columns(t, row, {0, diam, mass, ea, ba, ca, cd, cd_axial, ca_axial, ei});
    r.deck.types.push_back(type);
  }
}

MoorDynPointKind point_kind(const std::string& attachment) {
  std::string letters;
  for (char c : upper(attachment)) {
    if (!std::isalpha(static_cast<unsigned char>(c))) break;
    letters += c;
  }
  const auto is = [&](std::initializer_list<const char*> names) {
    return std::any_of(names.begin(), names.end(), [&](const char* n) { return letters == n; });
  };
  if (is({"FIXED", "FIX", "ANCHOR"})) return MoorDynPointKind::Fixed;
  if (is({"VESSEL", "VES", "COUPLED", "CPLD", "FAIRLEAD"})) return MoorDynPointKind::Coupled;
  if (is({"FREE", "CONNECT", "CON", "POINT"})) return MoorDynPointKind::Free;
  if (is({"BODY"})) return MoorDynPointKind::Body;
  return MoorDynPointKind::Other;
}

void convert_points(Reader& r) {
  const Table& t = r.tables[Section::Points];
  if (t.rows.empty()) return;
  const auto mass = r.column(t, {"m", "mass"}, 5, "Mass");
  const auto volume = r.column(t, {"v", "volume"}, 6, "Volume");
  const auto ca = r.column(t, {"ca"}, static_cast<int>(t.columns.size()) - 1, "CA");
  for (const auto& row : t.rows) {
    MoorDynPoint p;
    p.id = r.integer(row, 0, "ID");
    for (const auto& other : r.deck.points) {
      if (other.id == p.id)
        r.fail(row.first,
               fmt::format("point {} is defined twice (first at line {})", p.id, other.file_line));
    }
    p.attachment = r.cell(row, 1, "Attachment");
    p.kind = point_kind(p.attachment);
    p.x_m = r.value(row, 2, "X");
    p.y_m = r.value(row, 3, "Y");
    p.z_m = r.value(row, 4, "Z");
    p.mass_kg = r.non_negative(row, mass, "Mass");
    p.volume_m3 = r.non_negative(row, volume, "Volume");
    p.added_mass_coefficient = row.second.size() > ca ? r.value(row, ca, "CA") : 0.0;
    p.file_line = row.first;
    p.other_columns = other_columns(t, row, {0, 1, 2, 3, 4, mass, volume, ca});
    r.deck.points.push_back(p);
  }
}

void convert_lines(Reader& r) {
  const Table& t = r.tables[Section::Lines];
  if (t.rows.empty()) return;
  const auto type = r.column(t, {"linetype", "type"}, 1, "LineType");
  // Unnamed columns are where MoorDyn v2 reads them: ID LineType AttachA AttachB UnstrLen NumSegs.
  const auto a = r.column(t, {"attacha", "enda", "nodea", "nodeanch", "anchor"}, 2, "AttachA");
  const auto b = r.column(t, {"attachb", "endb", "nodeb", "nodefair", "fairlead"}, 3, "AttachB");
  const auto length = r.column(t, {"unstrlen", "length"}, 4, "UnstrLen");
  const auto segments = r.column(t, {"numsegs", "nsegs"}, 5, "NumSegs");
  for (const auto& row : t.rows) {
    const int id = r.integer(row, 0, "ID");
    for (const auto& other : r.deck.lines) {
      if (other.id == id)
        r.fail(row.first,
               fmt::format("line {} is defined twice (first at line {})", id, other.file_line));
    }
    const double unstretched = r.value(row, length, "UnstrLen");
    if (!(unstretched > 0.0))
      r.fail(row.first, fmt::format("'UnstrLen' = {} is not positive", unstretched));
    r.deck.lines.push_back({id, r.cell(row, type, "LineType"), r.cell(row, a, "AttachA"),
                            r.cell(row, b, "AttachB"), unstretched,
                            r.integer(row, segments, "NumSegs"), row.first,
                            other_columns(t, row, {0, type, a, b, length, segments})});
  }
}

// FAILURE rows: the attachment, then the lines (comma separated) that may break free there.
void convert_failures(Reader& r) {
  for (const auto& row : r.tables[Section::Failure].rows) {
    if (row.second.size() < 2) continue;
    std::istringstream ids(row.second[1]);
    for (std::string id; std::getline(ids, id, ',');) {
      if (const auto n = number(id)) r.deck.failing_lines.push_back(static_cast<int>(*n));
    }
  }
}

double option_or(const MoorDynDeck& deck, const std::vector<std::string>& names, double fallback) {
  for (const auto& name : names) {
    if (const auto it = deck.options.find(name); it != deck.options.end())
      return *number(it->second);
  }
  return fallback;
}

}  // namespace

double MoorDynDeck::gravity() const { return option_or(*this, kGravityNames, 9.80665); }
double MoorDynDeck::water_density() const { return option_or(*this, kDensityNames, 1025.0); }
double MoorDynDeck::bottom_stiffness() const {
  return option_or(*this, kBottomStiffnessNames, 3.0e6);
}
double MoorDynDeck::bottom_damping() const { return option_or(*this, kBottomDampingNames, 3.0e5); }
std::optional<double> MoorDynDeck::water_depth() const {
  for (const auto& name : kDepthNames) {
    if (const auto it = options.find(name); it != options.end()) {
      const auto depth = number(it->second);
      return depth && *depth > 0.0 ? depth : std::nullopt;
    }
  }
  return std::nullopt;
}
std::string MoorDynDeck::bathymetry_file() const {
  if (const auto it = options.find("seafloorfile"); it != options.end()) return it->second;
  for (const auto& name : kDepthNames) {
    const auto it = options.find(name);
    // MoorDyn-F reads a WtrDpth that is neither a number nor DEFAULT as a bathymetry file.
    if (it != options.end() && !number(it->second) && upper(it->second) != "DEFAULT")
      return it->second;
  }
  return "";
}

MoorDynDeck read_moordyn_deck(const std::filesystem::path& path) {
  return parse_moordyn_deck_text(read_input_file(path, "MoorDyn deck"), path_text(path));
}

namespace {

// The sections Catena reads must be there and hold rows: an empty or cut-off file is refused
// here, naming where it ends, instead of importing nothing with exit 0.
void require_tables(Reader& reader, int last_line) {
  if (last_line == 0) throw InvalidInput(fmt::format("{}: empty deck (no lines)", reader.file));
  const std::pair<Section, const char*> required[] = {
      {Section::LineTypes, "LINE TYPES"}, {Section::Points, "POINTS"}, {Section::Lines, "LINES"}};
  // A deck of rods or bodies alone is complete without lines (nothing for Catena to convert).
  if (reader.tables[Section::Lines].section_line == 0 &&
      (!reader.tables[Section::Rods].rows.empty() || !reader.tables[Section::Bodies].rows.empty()))
    return;
  for (const auto& [section, name] : required) {
    const Table& table = reader.tables[section];
    // A deck whose lines end only at rods or bodies may have no POINTS section.
    if (section == Section::Points && table.section_line == 0) continue;
    if (table.section_line == 0)
      reader.fail(last_line, fmt::format("no {} section before the end of the deck", name));
    if (table.rows.empty())
      reader.fail(table.section_line,
                  fmt::format("the {} section has no data rows (a truncated deck?)", name));
  }
}

}  // namespace

MoorDynDeck parse_moordyn_deck_text(const std::string& text, const std::string& file) {
  Reader reader;
  reader.file = file;
  reader.deck.file = reader.file;
  require_tables(reader, read_lines_of_file(reader, text));
  convert_types(reader);
  convert_points(reader);
  convert_lines(reader);
  convert_failures(reader);
  reader.deck.rod_type_rows = static_cast<int>(reader.tables[Section::RodTypes].rows.size());
  reader.deck.rod_rows = static_cast<int>(reader.tables[Section::Rods].rows.size());
  reader.deck.body_rows = static_cast<int>(reader.tables[Section::Bodies].rows.size());
  reader.deck.syrope_rows = static_cast<int>(reader.tables[Section::SyropeIc].rows.size());
  return reader.deck;
}

}  // namespace catena
