#include "catena/verification/report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fmt/format.h>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <variant>
#include <vector>

#include "catena/core/error.hpp"

namespace catena {
namespace {

using nlohmann::json;

// A tiny document model rendered twice: Markdown for people reading diffs, HTML for browsers.
struct Heading { int level; std::string text; std::string anchor; };
struct Paragraph { std::string text; };
struct Table { std::vector<std::string> header; std::vector<std::vector<std::string>> rows; std::string css_class; };
struct Image { std::filesystem::path file; std::string caption; };
using Block = std::variant<Heading, Paragraph, Table, Image>;

std::string html_escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '&': out += "&amp;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string md_cell(const std::string& text) {
  std::string out;
  for (char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

std::string base64(const std::string& bytes) {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned v = (unsigned(uint8_t(bytes[i])) << 16) | (unsigned(uint8_t(bytes[i + 1])) << 8) | uint8_t(bytes[i + 2]);
    out += table[v >> 18];
    out += table[(v >> 12) & 63];
    out += table[(v >> 6) & 63];
    out += table[v & 63];
  }
  if (i < bytes.size()) {
    unsigned v = unsigned(uint8_t(bytes[i])) << 16;
    if (i + 1 < bytes.size()) v |= unsigned(uint8_t(bytes[i + 1])) << 8;
    out += table[v >> 18];
    out += table[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? table[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

std::string render_markdown(const std::vector<Block>& blocks, const std::filesystem::path& base) {
  std::string out;
  for (const auto& block : blocks) {
    if (const auto* h = std::get_if<Heading>(&block)) {
      out += std::string(static_cast<std::size_t>(h->level), '#') + " " + h->text + "\n\n";
    } else if (const auto* p = std::get_if<Paragraph>(&block)) {
      out += p->text + "\n\n";
    } else if (const auto* t = std::get_if<Table>(&block)) {
      out += "|";
      for (const auto& h2 : t->header) out += " " + md_cell(h2) + " |";
      out += "\n|";
      for (std::size_t i = 0; i < t->header.size(); ++i) out += "---|";
      out += "\n";
      for (const auto& row : t->rows) {
        out += "|";
        for (const auto& cell : row) out += " " + md_cell(cell) + " |";
        out += "\n";
      }
      out += "\n";
    } else if (const auto* img = std::get_if<Image>(&block)) {
      out += fmt::format("![{}]({})\n\n*{}*\n\n", img->caption,
                         std::filesystem::relative(img->file, base).string(), img->caption);
    }
  }
  return out;
}

std::string render_html(const std::vector<Block>& blocks, const std::string& title) {
  std::string out = "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>" + html_escape(title) +
                    "</title>\n<style>\n"
                    "body{font-family:system-ui,sans-serif;max-width:1200px;margin:2em auto;padding:0 1em;color:#222}\n"
                    "table{border-collapse:collapse;margin:0.5em 0 1.5em;font-size:0.9em}\n"
                    "th,td{border:1px solid #ccc;padding:3px 8px;text-align:right}th{background:#f0f0f0}\n"
                    "td:first-child,th:first-child{text-align:left}\n"
                    ".PASS{color:#176117}.FAIL{color:#b00;font-weight:bold}.SOURCE{color:#a15c00;font-weight:bold}\n"
                    "figure{margin:1em 0}figure img{max-width:100%;border:1px solid #ddd}\n"
                    "figcaption{font-size:0.9em;color:#555}h2{border-bottom:1px solid #ccc;margin-top:2em}\n"
                    "</style></head><body>\n";
  for (const auto& block : blocks) {
    if (const auto* h = std::get_if<Heading>(&block)) {
      out += fmt::format("<h{0} id=\"{2}\">{1}</h{0}>\n", h->level, html_escape(h->text), html_escape(h->anchor));
    } else if (const auto* p = std::get_if<Paragraph>(&block)) {
      out += "<p>" + html_escape(p->text) + "</p>\n";
    } else if (const auto* t = std::get_if<Table>(&block)) {
      out += "<table class=\"" + t->css_class + "\"><thead><tr>";
      for (const auto& h2 : t->header) out += "<th>" + html_escape(h2) + "</th>";
      out += "</tr></thead><tbody>\n";
      for (const auto& row : t->rows) {
        out += "<tr>";
        for (const auto& cell : row) {
          const bool verdict = cell == "PASS" || cell == "FAIL" || cell == "SOURCE" || cell == "WARN" || cell == "SKIP";
          out += (verdict ? "<td class=\"" + cell + "\">" : std::string("<td>")) + html_escape(cell) + "</td>";
        }
        out += "</tr>\n";
      }
      out += "</tbody></table>\n";
    } else if (const auto* img = std::get_if<Image>(&block)) {
      out += "<figure><img alt=\"" + html_escape(img->caption) + "\" src=\"data:image/png;base64," +
             base64(read_file(img->file)) + "\"><figcaption>" + html_escape(img->caption) + "</figcaption></figure>\n";
    }
  }
  out += "</body></html>\n";
  return out;
}

std::string number(const json& value, const char* format = "{:.6g}") {
  if (value.is_null() || !value.is_number()) return "-";
  return fmt::format(fmt::runtime(format), value.get<double>());
}

// scene[key] by reference (json::value() would copy), or an empty array.
const json& list_or_empty(const json& object, const char* key) {
  static const json empty = json::array();
  return object.contains(key) ? object.at(key) : empty;
}

// The unit a scene's frequencies read best in: its published unit, Gale's ratio for Gale
// scenes, kL/pi for taut-inclined ones, rad/s otherwise.
std::string display_unit(const json& scene) {
  for (const auto& p : list_or_empty(scene, "published")) {
    if (p.value("quantity", "") != "forced_max_tension") return p.value("unit", "rad/s");
  }
  const auto tags = scene.value("tags", std::vector<std::string>{});
  if (std::find(tags.begin(), tags.end(), "gale") != tags.end()) return "gale";
  if (std::find(tags.begin(), tags.end(), "taut-inclined") != tags.end()) return "kL/pi";
  return "rad/s";
}

json mode_value(const json& mode, const std::string& unit) {
  if (unit == "gale") return mode.value("gale_ratio", json(nullptr));
  if (unit == "kL/pi") return mode.value("k_l_over_pi", json(nullptr));
  if (unit == "Hz") return mode.value("frequency_hz", json(nullptr));
  return mode.value("omega_rad_s", json(nullptr));
}

void add_csv(std::ofstream& out, const std::vector<std::string>& cells) {
  for (std::size_t i = 0; i < cells.size(); ++i) {
    std::string cell = cells[i];
    if (cell.find_first_of(",\"\n") != std::string::npos) {
      std::string quoted = "\"";
      for (char c : cell) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
      cell = quoted + "\"";
    }
    out << (i ? "," : "") << cell;
  }
  out << '\n';
}

std::string json_text(const json& value) {
  if (value.is_null()) return "";
  if (value.is_number()) return fmt::format("{:.17g}", value.get<double>());
  if (value.is_string()) return value.get<std::string>();
  return value.dump();
}

void write_data(const json& document, const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  std::ofstream frequencies(dir / "frequencies.csv");
  frequencies << "# Every natural frequency every solver returned. Written by catena report from report.json.\n";
  add_csv(frequencies, {"scene", "solver", "plane", "mode", "omega_rad_s", "frequency_hz", "k_l_over_pi", "gale_ratio",
                        "relative_error_estimate"});
  std::ofstream checks(dir / "checks.csv");
  checks << "# Every check of the run. measured and tolerance: see each check kind in verification/README.md.\n";
  add_csv(checks, {"scene", "check", "compare", "plane", "mode", "value_a", "value_b", "measured", "tolerance", "verdict", "detail"});
  std::ofstream published(dir / "published.csv");
  published << "# Our values beside the published ones (value_a = ours, value_b = printed, in the table's unit).\n";
  add_csv(published, {"scene", "compare", "plane", "mode", "ours", "printed", "abs_difference", "tolerance", "verdict", "detail"});
  for (const auto& scene : document["scenes"]) {
    const std::string name = scene.value("name", "");
    for (const auto& [solver, output] : scene["solvers"].items()) {
      for (const char* plane : {"inplane", "outofplane"}) {
        if (!output.contains(plane)) continue;
        for (const auto& mode : output[plane]["modes"]) {
          add_csv(frequencies, {name, solver, plane, json_text(mode["index"]), json_text(mode["omega_rad_s"]),
                                json_text(mode["frequency_hz"]), json_text(mode["k_l_over_pi"]),
                                json_text(mode["gale_ratio"]), json_text(mode["relative_error_estimate"])});
        }
      }
    }
    for (const auto& check : scene["checks"]) {
      std::vector<std::string> row = {name, json_text(check["check"]), json_text(check["compare"]), json_text(check["plane"]),
                                      json_text(check["mode"]), json_text(check["value_a"]), json_text(check["value_b"]),
                                      json_text(check["measured"]), json_text(check["tolerance"]), json_text(check["verdict"]),
                                      json_text(check["detail"])};
      add_csv(checks, row);
      if (check.value("check", "") == "published") {
        add_csv(published, {name, row[2], row[3], row[4], row[5], row[6], row[7], row[8], row[9], row[10]});
      }
    }
  }
}

// Runs figures.py; returns the list of (file, caption) it drew, or a note why none.
std::vector<Image> draw_figures(const std::filesystem::path& results_json, const ReportOptions& options, std::string& note) {
  const std::filesystem::path script = options.tools_dir / "figures.py";
  const std::filesystem::path figures = options.out_dir / "figures";
  if (!std::filesystem::exists(script)) {
    note = "figures not drawn: " + script.string() + " not found";
    return {};
  }
  std::filesystem::create_directories(figures);
  const std::string command = fmt::format("{} '{}' --results '{}' --published '{}' --out '{}' > '{}' 2>&1", options.python,
                                          script.string(), results_json.string(),
                                          (options.tools_dir / ".." / "reference" / "published").string(), figures.string(),
                                          (figures / "figures.log").string());
  const int status = std::system(command.c_str());
  if (status != 0) {
    note = fmt::format("figures not drawn: '{}' failed (status {}); see {}", options.python, status,
                       (figures / "figures.log").string());
    return {};
  }
  std::vector<Image> images;
  std::ifstream index(figures / "index.json");
  if (!index) {
    note = "figures not drawn: figures.py wrote no index.json";
    return {};
  }
  const json list = json::parse(index, nullptr, false);
  if (!list.is_array()) {
    note = "figures not drawn: unreadable figures/index.json";
    return {};
  }
  for (const auto& item : list) images.push_back({figures / item.value("file", ""), item.value("caption", "")});
  return images;
}

}  // namespace

ReportFiles write_report(const std::filesystem::path& results_json, const ReportOptions& options) {
  std::ifstream in(results_json);
  if (!in) throw ParseError(fmt::format("{}: cannot open results JSON", results_json.string()));
  const json document = json::parse(in, nullptr, false);
  if (document.is_discarded() || !document.contains("scenes")) {
    throw ParseError(fmt::format("{}: not a catena results JSON (no \"scenes\")", results_json.string()));
  }
  std::filesystem::create_directories(options.out_dir);
  ReportFiles files;
  files.data_dir = options.out_dir / "data";
  write_data(document, files.data_dir);

  // --- counts ---
  std::map<std::string, int> verdicts;
  int scenes = 0;
  for (const auto& scene : document["scenes"]) {
    ++scenes;
    for (const auto& check : scene["checks"]) ++verdicts[check.value("verdict", "?")];
  }
  int total = 0;
  for (const auto& [k, v] : verdicts) total += v;
  const json& meta = document["catena"];

  std::vector<Block> blocks;
  blocks.push_back(Heading{1, "Catena verification report", "top"});
  blocks.push_back(Paragraph{fmt::format("catena {} (git {}) · {} · {} · {} · {} scenes, {} checks, {} failed, {} source discrepancies",
                                         meta.value("version", "?"), meta.value("git", "?"), meta.value("compiler", "?"),
                                         meta.value("build_type", "?"), meta.value("generated_utc", "?"), scenes, total,
                                         verdicts["FAIL"], verdicts["SOURCE"])});
  {
    Table t{{"verdict", "checks", "meaning"}, {}, "summary"};
    const std::map<std::string, std::string> meaning = {
        {"PASS", "within tolerance"}, {"FAIL", "beyond tolerance: a defect of ours"},
        {"SOURCE", "a published value contradicted by our agreeing solvers (or a reviewed finding)"},
        {"WARN", "beyond tolerance for a documented reason"}, {"SKIP", "not evaluated (reason given)"}};
    for (const auto& [k, text] : meaning) t.rows.push_back({k, std::to_string(verdicts[k]), text});
    blocks.push_back(t);
  }

  // --- solvers ---
  blocks.push_back(Heading{2, "Solvers", "solvers"});
  {
    struct Stats { int run = 0, converged = 0, declined = 0, failed = 0; double time = 0, max_est = 0; std::vector<double> times; };
    std::map<std::string, Stats> stats;
    for (const auto& scene : document["scenes"]) {
      for (const auto& [solver, output] : scene["solvers"].items()) {
        Stats& s = stats[solver];
        const std::string termination = output["summary"].value("termination", "");
        if (termination == "not-applicable") { ++s.declined; continue; }
        ++s.run;
        s.converged += termination == "converged";
        s.failed += termination == "numerical-failure";
        const double t = output["summary"].value("wall_time_s", 0.0);
        s.time += t;
        s.times.push_back(t);
        if (output["summary"]["max_error_estimate"].is_number()) {
          s.max_est = std::max(s.max_est, output["summary"]["max_error_estimate"].get<double>());
        }
      }
    }
    Table t{{"solver", "scenes run", "converged", "failed", "declined (not applicable)", "median time [ms]", "total time [s]",
             "largest error estimate"}, {}, "solvers"};
    for (auto& [solver, s] : stats) {
      std::sort(s.times.begin(), s.times.end());
      const double median = s.times.empty() ? 0.0 : s.times[s.times.size() / 2];
      t.rows.push_back({solver, std::to_string(s.run), std::to_string(s.converged), std::to_string(s.failed),
                        std::to_string(s.declined), fmt::format("{:.3g}", median * 1e3), fmt::format("{:.3g}", s.time),
                        fmt::format("{:.2e}", s.max_est)});
    }
    blocks.push_back(t);
  }

  // --- source discrepancies and failures ---
  blocks.push_back(Heading{2, "Source discrepancies", "source-discrepancies"});
  blocks.push_back(Paragraph{"Published entries we believe wrong: two of our independent solvers agree with each other "
                             "and not with the printed value, or a reviewed finding (verification/findings.toml) "
                             "explains the difference."});
  {
    Table t{{"scene", "compared", "mode", "ours", "printed", "difference", "evidence"}, {}, "discrepancies"};
    for (const auto& scene : document["scenes"]) {
      for (const auto& check : scene["checks"]) {
        if (check.value("verdict", "") != "SOURCE") continue;
        t.rows.push_back({scene.value("name", ""), check.value("compare", ""), std::to_string(check.value("mode", 0)),
                          number(check["value_a"], "{:.6g}"), number(check["value_b"], "{:.6g}"),
                          number(check["measured"], "{:.3g}"), check.value("detail", "")});
      }
    }
    if (t.rows.empty()) blocks.push_back(Paragraph{"None."});
    else blocks.push_back(t);
  }
  blocks.push_back(Heading{2, "Failures and warnings", "failures"});
  {
    Table t{{"scene", "check", "compared", "plane", "mode", "measured", "tolerance", "verdict", "detail"}, {}, "failures"};
    for (const auto& scene : document["scenes"]) {
      if (!scene["error"].is_null()) {
        t.rows.push_back({scene.value("name", ""), "scene", "-", "-", "-", "-", "-", "FAIL", scene["error"].get<std::string>()});
      }
      for (const auto& check : scene["checks"]) {
        const std::string verdict = check.value("verdict", "");
        if (verdict != "FAIL" && verdict != "WARN") continue;
        t.rows.push_back({scene.value("name", ""), check.value("check", ""), check.value("compare", ""), check.value("plane", ""),
                          std::to_string(check.value("mode", 0)), number(check["measured"], "{:.3e}"),
                          number(check["tolerance"], "{:.3e}"), verdict, check.value("detail", "")});
      }
    }
    if (t.rows.empty()) blocks.push_back(Paragraph{"None."});
    else blocks.push_back(t);
  }

  // --- stress suite: every outcome accurate (checks pass) or a clear diagnostic ---
  {
    Table t{{"stress scene", "solver", "outcome", "failed checks", "message"}, {}, "stress"};
    for (const auto& scene : document["scenes"]) {
      const auto tags = scene.value("tags", std::vector<std::string>{});
      if (std::find(tags.begin(), tags.end(), "stress") == tags.end()) continue;
      for (const auto& [solver, output] : scene["solvers"].items()) {
        int failed = 0;
        for (const auto& check : scene["checks"]) {
          if (check.value("verdict", "") == "FAIL" && check.value("compare", "").find(solver) != std::string::npos) ++failed;
        }
        const std::string termination = output["summary"].value("termination", "");
        const std::string outcome = termination == "converged" ? (failed ? "FAIL" : "accurate")
                                    : termination == "not-applicable" ? "declined"
                                                                      : "diagnosed";
        std::string message = output["summary"].value("message", "");
        if (message.size() > 160) message = message.substr(0, 157) + "...";
        t.rows.push_back({scene.value("name", ""), solver, outcome, std::to_string(failed), message});
      }
    }
    if (!t.rows.empty()) {
      blocks.push_back(Heading{2, "Stress suite outcomes", "stress"});
      blocks.push_back(Paragraph{"Each solver on each stress scene: accurate (all its checks pass), diagnosed (a "
                                 "clear numerical diagnostic instead of a number), or declined (outside its model)."});
      blocks.push_back(t);
    }
  }

  // --- time to accuracy (benchmarks/results/time-vs-error.csv, when present) ---
  {
    const std::filesystem::path csv = options.tools_dir / ".." / ".." / "benchmarks" / "results" / "time-vs-error.csv";
    std::ifstream timing_csv(csv);
    std::string line;
    std::map<std::string, std::map<std::string, std::map<double, double>>> best;  // scene -> solver -> target -> s
    std::vector<std::string> order;
    while (std::getline(timing_csv, line)) {
      if (line.empty() || line[0] == '#' || line.rfind("scene,", 0) == 0) continue;
      // "scene",solver,setting,time_s,max_rel_error,status
      const auto close = line.find('"', 1);
      if (line[0] != '"' || close == std::string::npos) continue;
      const std::string scene = line.substr(1, close - 1);
      std::vector<std::string> cells;
      std::stringstream rest(line.substr(close + 2));
      for (std::string cell; std::getline(rest, cell, ',');) cells.push_back(cell);
      if (cells.size() < 4) continue;
      const double time_s = std::atof(cells[2].c_str());
      const double error = std::atof(cells[3].c_str());
      if (std::find(order.begin(), order.end(), scene) == order.end()) order.push_back(scene);
      for (double target : {1e-3, 1e-6, 1e-9}) {
        if (!(error <= target)) continue;
        auto& slot = best[scene][cells[0]];
        if (!slot.count(target) || time_s < slot[target]) slot[target] = time_s;
      }
    }
    if (!order.empty()) {
      blocks.push_back(Heading{2, "Time to accuracy", "time-to-accuracy"});
      blocks.push_back(Paragraph{"Fastest wall time for each solver to reach a relative error on the first six in-plane "
                                 "frequencies (benchmarks/results/time-vs-error.csv; error against shooting at rtol "
                                 "1e-13; 'cannot': no setting reached it)."});
      Table t{{"case", "solver", "1e-3", "1e-6", "1e-9"}, {}, "timing"};
      for (const auto& scene : order) {
        for (const auto& [solver, targets] : best[scene]) {
          std::vector<std::string> row = {scene, solver};
          for (double target : {1e-3, 1e-6, 1e-9}) {
            row.push_back(targets.count(target) ? fmt::format("{:.3g} ms", targets.at(target) * 1e3) : "cannot");
          }
          t.rows.push_back(row);
        }
      }
      blocks.push_back(t);
    }
  }

  // --- figures ---
  std::vector<Image> images;
  if (options.figures) images = draw_figures(results_json, options, files.figures_note);
  else files.figures_note = "figures not drawn (--no-figures)";
  files.figures = static_cast<int>(images.size());
  blocks.push_back(Heading{2, "Figures", "figures"});
  if (!files.figures_note.empty()) blocks.push_back(Paragraph{files.figures_note});
  for (const auto& image : images) blocks.push_back(image);

  // --- per scene: every solver's frequencies beside the published ones ---
  blocks.push_back(Heading{2, "Scenes", "scenes"});
  for (const auto& scene : document["scenes"]) {
    const std::string name = scene.value("name", "");
    blocks.push_back(Heading{3, name, name});
    std::string info = scene.value("description", "");
    if (scene.contains("groups")) {
      const json& g = scene["groups"];
      info += fmt::format(" — eps = {}, phi_a = {} deg, lambda^2 = {}, h = {}", number(g["eps"]), number(g["chord_angle_deg"]),
                          g["lambda2"].is_null() ? std::string("inf") : number(g["lambda2"]), number(g["mass_ratio"]));
      if (g.contains("gale")) info += fmt::format(", Gale xi = ({}, {})", number(g["gale"]["xi1"], "{:.4f}"), number(g["gale"]["xi2"], "{:.4f}"));
    }
    if (!scene["error"].is_null()) info += " — ERROR: " + scene["error"].get<std::string>();
    int failed = 0, count = 0;
    for (const auto& check : scene["checks"]) {
      ++count;
      failed += check.value("verdict", "") == "FAIL";
    }
    info += fmt::format(" — {} checks, {} failed.", count, failed);
    blocks.push_back(Paragraph{info});
    const std::string unit = display_unit(scene);
    for (const char* plane : {"inplane", "outofplane"}) {
      std::vector<std::string> solvers;
      std::size_t modes = 0;
      for (const auto& [solver, output] : scene["solvers"].items()) {
        if (!output.contains(plane)) continue;
        solvers.push_back(solver);
        modes = std::max(modes, output[plane]["modes"].size());
      }
      std::vector<const json*> published;
      for (const auto& p : list_or_empty(scene, "published")) {
        if (p.value("quantity", "") == std::string(plane) + "_frequency") published.push_back(&p);
      }
      if (solvers.empty() && published.empty()) continue;
      Table t{{std::string(plane == std::string("inplane") ? "in-plane" : "out-of-plane") + " mode [" + unit + "]"}, {}, "frequencies"};
      for (const auto& s : solvers) t.header.push_back(s);
      for (const auto* p : published) t.header.push_back(p->value("source", "published"));
      for (const auto* p : published) modes = std::max(modes, static_cast<std::size_t>(*std::max_element(p->at("modes").begin(), p->at("modes").end())));
      for (std::size_t i = 0; i < modes; ++i) {
        std::vector<std::string> row = {std::to_string(i + 1)};
        for (const auto& s : solvers) {
          const json& list = scene["solvers"][s][plane]["modes"];
          row.push_back(i < list.size() ? number(mode_value(list[i], unit), "{:.8g}") : "-");
        }
        for (const auto* p : published) {
          std::string cell = "-";
          for (std::size_t k = 0; k < p->at("modes").size(); ++k) {
            if (p->at("modes")[k].get<int>() == static_cast<int>(i + 1)) cell = number(p->at("values")[k], "{:g}");
          }
          row.push_back(cell);
        }
        t.rows.push_back(row);
      }
      blocks.push_back(t);
    }
    // Forced response maxima.
    std::vector<std::string> forced_solvers;
    for (const auto& [solver, output] : scene["solvers"].items()) {
      if (output.contains("forced")) forced_solvers.push_back(solver);
    }
    if (!forced_solvers.empty()) {
      Table t{{"forcing [rad/s]"}, {}, "forced"};
      for (const auto& s : forced_solvers) t.header.push_back(s + " max|tau|/H");
      const json& first = scene["solvers"][forced_solvers[0]]["forced"];
      const double H = scene["statics"].value("horizontal_force_n", 1.0);
      for (std::size_t i = 0; i < first.size(); ++i) {
        std::vector<std::string> row = {number(first[i]["omega_rad_s"])};
        for (const auto& s : forced_solvers) {
          const json& list = scene["solvers"][s]["forced"];
          if (i >= list.size()) { row.push_back("-"); continue; }
          const std::string diag = list[i].value("diagnostic", "");
          row.push_back(diag.empty() ? fmt::format("{:.6g}", list[i].value("max_abs_tension_n", 0.0) / H) : diag);
        }
        t.rows.push_back(row);
      }
      blocks.push_back(t);
    }
  }

  files.markdown = options.out_dir / "report.md";
  files.html = options.out_dir / "report.html";
  std::ofstream md(files.markdown);
  md << render_markdown(blocks, options.out_dir);
  std::ofstream html(files.html);
  html << render_html(blocks, "Catena verification report");
  if (!md || !html) throw InvalidInput(fmt::format("{}: cannot write the report", options.out_dir.string()));
  return files;
}

}  // namespace catena
