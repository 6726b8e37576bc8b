#include "design/import/moordyn_deck.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "design/project/input_error.hpp"

namespace spiral::design {
namespace {

std::string lower(std::string_view text) {
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return std::tolower(c); });
  return out;
}

struct Token {
  std::string text;
  int column = 1;  ///< 1-based
};

/// Whitespace-separated tokens of a row, without a trailing comment: MoorDyn
/// v2 reads `!`, `#` and `%` as comment characters (MoorDyn docs, "The V2
/// Input File").
std::vector<Token> tokens_of(std::string_view row) {
  std::vector<Token> out;
  std::size_t i = 0;
  while (i < row.size()) {
    while (i < row.size() && std::isspace(static_cast<unsigned char>(row[i]))) ++i;
    if (i >= row.size() || row[i] == '!' || row[i] == '#' || row[i] == '%') break;
    const std::size_t start = i;
    while (i < row.size() && !std::isspace(static_cast<unsigned char>(row[i]))) ++i;
    out.push_back({std::string(row.substr(start, i - start)), static_cast<int>(start) + 1});
  }
  return out;
}

enum class Section { front, line_types, points, lines, bodies, options, outputs, skipped, end };

/// A section header is a row of dashes around a key phrase.
bool is_header(std::string_view row) {
  const auto first = row.find_first_not_of(" \t");
  return first != std::string_view::npos && row.substr(first).starts_with("---");
}

/// The key phrase of a header row, upper case, dashes and outer blanks removed.
std::string header_phrase(std::string_view row) {
  std::string phrase;
  for (char c : row) phrase += c == '-' ? ' ' : static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  const auto a = phrase.find_first_not_of(' ');
  const auto b = phrase.find_last_not_of(' ');
  if (a == std::string::npos) return {};
  std::string collapsed;
  for (std::size_t i = a; i <= b; ++i)
    if (phrase[i] != ' ' || collapsed.empty() || collapsed.back() != ' ') collapsed += phrase[i];
  return collapsed;
}

class DeckParser {
 public:
  explicit DeckParser(std::string source) { deck_.source = std::move(source); }

  MoorDynDeck parse(std::string_view text) {
    std::istringstream in{std::string(text)};
    std::string row;
    int number = 0;
    while (std::getline(in, row)) {
      ++number;
      if (!row.empty() && row.back() == '\r') row.pop_back();
      if (section_ == Section::end) break;
      if (is_header(row)) {
        start_section(header_phrase(row), number);
        continue;
      }
      read_row(row, number);
    }
    finish_skipped();
    if (deck_.lines.empty() && issues_.empty())
      fail(std::max(number, 1), 1,
           "the deck defines no line (a LINES / LINE PROPERTIES section with at least one row)");
    check_references();
    if (!issues_.empty()) throw InputError(std::move(issues_));
    return std::move(deck_);
  }

 private:
  void fail(int line, int column, std::string message) {
    issues_.push_back({deck_.source, line, column, "", InputOrigin::file, std::move(message), "moordyn_deck"});
  }

  void start_section(const std::string& phrase, int number) {
    finish_skipped();
    table_rows_ = 0;
    header_.clear();
    const auto has = [&](std::string_view key) { return phrase.find(key) != std::string::npos; };
    if (has("NEED THIS LINE")) {
      section_ = Section::end;
    } else if (has("LINE DICTIONARY") || has("LINE TYPES")) {
      if (has("LINE DICTIONARY")) deck_.format_version = 1;
      section_ = Section::line_types;
    } else if (has("ROD TYPES") || has("ROD DICTIONARY") || has("RODS") || has("ROD LIST") || has("ROD PROPERTIES")) {
      skip(phrase, number, "rods (rigid cylinders): spiral has no rod element");
    } else if (has("BODIES") || has("BODY LIST") || has("BODY PROPERTIES")) {
      section_ = Section::bodies;
    } else if (has("POINT") || has("CONNECTION") || has("NODE PROPERTIES")) {
      if (has("CONNECTION") || has("NODE PROPERTIES")) deck_.format_version = 1;
      section_ = Section::points;
    } else if (has("LINE PROPERTIES") || phrase == "LINES" || has("LINE LIST") || phrase.starts_with("LINES ")) {
      if (has("LINE PROPERTIES")) deck_.format_version = 1;
      section_ = Section::lines;
    } else if (has("OPTIONS")) {
      if (has("SOLVER")) deck_.format_version = 1;
      section_ = Section::options;
    } else if (has("OUTPUT")) {
      section_ = Section::outputs;
    } else if (section_ == Section::front && deck_.front_matter.empty()) {
      // The first dashed row ("MoorDyn Input File") opens the front matter.
    } else {
      skip(phrase, number, "not read by spiral");
    }
  }

  void skip(const std::string& phrase, int number, std::string why) {
    section_ = Section::skipped;
    skipped_ = {phrase, std::move(why), number, number, 0};
    skipped_seen_ = 0;
  }

  void finish_skipped() {
    if (section_ != Section::skipped) return;
    if (skipped_.rows > 0)
      deck_.notes.push_back(fmt::format("{} (lines {}-{}, {} rows): {}", skipped_.phrase, skipped_.first, skipped_.last,
                                        skipped_.rows, skipped_.why));
    section_ = Section::front;
  }

  void read_row(const std::string& row, int number) {
    const std::vector<Token> tokens = tokens_of(row);
    switch (section_) {
      case Section::front: {
        const auto first = row.find_first_not_of(" \t");
        if (first == std::string::npos) return;
        const auto last = row.find_last_not_of(" \t");
        deck_.front_matter.push_back(row.substr(first, last - first + 1));
        if (deck_.title.empty()) deck_.title = deck_.front_matter.back();
        return;
      }
      case Section::skipped:
        if (tokens.empty()) return;
        // The two rows of column names and units are not entries.
        if (++skipped_seen_ > 2 || skipped_.phrase.find("OPTION") != std::string::npos) ++skipped_.rows;
        skipped_.last = number;
        return;
      case Section::outputs:
        if (tokens.empty()) return;
        if (lower(tokens[0].text) == "end") {
          section_ = Section::front;
          return;
        }
        for (const Token& t : tokens) deck_.outputs.push_back(t.text);
        return;
      case Section::options:
        if (tokens.empty()) return;
        if (tokens.size() < 2) {
          fail(number, tokens[0].column, fmt::format("an option row is `value name`, got \"{}\"", tokens[0].text));
          return;
        }
        deck_.options.push_back({tokens[1].text, tokens[0].text, number});
        return;
      case Section::end:
        return;
      default:
        break;
    }
    if (tokens.empty()) return;
    if (table_rows_ < 2) {
      // Column names, then units.
      if (table_rows_ == 0)
        for (const Token& t : tokens) header_.push_back(lower(t.text));
      ++table_rows_;
      return;
    }
    ++table_rows_;
    if (section_ == Section::line_types) read_line_type(tokens, number);
    if (section_ == Section::points) read_point(tokens, number);
    if (section_ == Section::lines) read_line(tokens, number);
    if (section_ == Section::bodies) read_body(tokens, number);
  }

  /// The column of a field: its header name (any of `names`), else its v2 position.
  int column(std::initializer_list<std::string_view> names, int v2_position) const {
    for (std::size_t i = 0; i < header_.size(); ++i)
      for (std::string_view name : names)
        if (header_[i] == name) return static_cast<int>(i);
    return v2_position;
  }
  bool has_column(std::initializer_list<std::string_view> names) const {
    for (const std::string& h : header_)
      for (std::string_view name : names)
        if (h == name) return true;
    return false;
  }

  /// Token `index` of the row, or an issue when the row is too short.
  const Token* field(const std::vector<Token>& tokens, int index, int number, std::string_view what) {
    if (index < static_cast<int>(tokens.size())) return &tokens[index];
    fail(number, tokens.back().column,
         fmt::format("{} row has {} columns, {} (column {}) is missing", section_name(), tokens.size(), what,
                     index + 1));
    return nullptr;
  }

  /// A number; an issue names the field when the text is not one.
  double number_of(const std::vector<Token>& tokens, int index, int number, std::string_view what,
                   bool first_of_list = false) {
    const Token* t = field(tokens, index, number, what);
    if (t == nullptr) return 0.0;
    std::string text = t->text;
    if (first_of_list) text = text.substr(0, text.find('|'));
    double value = 0.0;
    // MoorDyn (C and Fortran) reads Fortran-style exponents too: 1.0D6.
    std::replace_if(
        text.begin(), text.end(), [](char c) { return c == 'd' || c == 'D'; }, 'e');
    const char* end = text.data() + text.size();
    const auto result = std::from_chars(text.data(), end, value);
    if (result.ec != std::errc() || result.ptr != end || !std::isfinite(value)) {
      fail(number, t->column, fmt::format("{}: expected a number, got \"{}\"", what, t->text));
      return 0.0;
    }
    return value;
  }

  int integer_of(const std::vector<Token>& tokens, int index, int number, std::string_view what) {
    const Token* t = field(tokens, index, number, what);
    if (t == nullptr) return 0;
    int value = 0;
    const auto result = std::from_chars(t->text.data(), t->text.data() + t->text.size(), value);
    if (result.ec != std::errc() || result.ptr != t->text.data() + t->text.size()) {
      fail(number, t->column, fmt::format("{}: expected a whole number, got \"{}\"", what, t->text));
      return 0;
    }
    return value;
  }

  const char* section_name() const {
    switch (section_) {
      case Section::line_types:
        return "a LINE TYPES";
      case Section::points:
        return "a POINTS";
      case Section::lines:
        return "a LINES";
      case Section::bodies:
        return "a BODIES";
      default:
        return "a";
    }
  }

  void read_line_type(const std::vector<Token>& tokens, int number) {
    MoorDynLineType t;
    t.line = number;
    t.name = tokens[0].text;
    t.diameter_m = number_of(tokens, column({"diam", "diameter", "d"}, 1), number, "Diam");
    t.mass_per_length_kg_per_m =
        number_of(tokens, column({"massden", "mass/m", "massdeninair", "mass"}, 2), number, "MassDen");
    const int ea = column({"ea"}, 3);
    if (const Token* e = field(tokens, ea, number, "EA")) {
      t.EA_text = e->text;
      const bool table = !e->text.empty() && !std::isdigit(static_cast<unsigned char>(e->text[0])) &&
                         e->text[0] != '.' && e->text[0] != '+';
      if (table) {
        fail(number, e->column,
             fmt::format("EA: a nonlinear EA table (\"{}\") has no spiral equivalent: give the line's EA as a number",
                         e->text));
      } else {
        t.EA_N = number_of(tokens, ea, number, "EA", true);
      }
    }
    if (const Token* b = field(tokens, column({"ba/-zeta", "ba", "c", "ba/-zeta(n-s)"}, 4), number, "BA/-zeta"))
      t.damping_text = b->text;
    // EI exists in MoorDyn-F v1 and every v2 deck; MoorDyn-C v1 decks have none.
    const bool v2_positions = has_column({"ei"}) || tokens.size() >= 10;
    if (v2_positions) t.EI_N_m2 = number_of(tokens, column({"ei"}, 5), number, "EI");
    const int base = v2_positions ? 6 : 5;
    t.Cd = number_of(tokens, column({"cd", "cdn"}, base), number, "Cd");
    t.Ca = number_of(tokens, column({"ca", "can"}, base + 1), number, "Ca");
    t.CdAx = number_of(tokens, column({"cdax", "cdt"}, base + 2), number, "CdAx");
    t.CaAx = number_of(tokens, column({"caax", "cat"}, base + 3), number, "CaAx");
    for (const MoorDynLineType& other : deck_.line_types)
      if (other.name == t.name)
        fail(number, tokens[0].column,
             fmt::format("line type \"{}\" is defined twice (first on line {})", t.name, other.line));
    if (t.diameter_m <= 0.0 || t.mass_per_length_kg_per_m <= 0.0 || t.EA_N <= 0.0) {
      if (issues_.empty() || issues_.back().line != number)
        fail(number, tokens[0].column,
             fmt::format("line type \"{}\": Diam, MassDen and EA must be > 0, got {} m, {} kg/m, {} N", t.name,
                         t.diameter_m, t.mass_per_length_kg_per_m, t.EA_N));
    }
    deck_.line_types.push_back(std::move(t));
  }

  void read_point(const std::vector<Token>& tokens, int number) {
    MoorDynPoint p;
    p.line = number;
    p.id = integer_of(tokens, 0, number, "ID");
    const Token* type = field(tokens, 1, number, "Attachment");
    if (type == nullptr) return;
    p.attachment = type->text;
    const std::string kind = lower(type->text);
    if (kind == "fixed" || kind == "fix" || kind == "anchor") {
      p.kind = MoorDynPointKind::fixed;
    } else if (kind == "vessel" || kind == "coupled" || kind == "fairlead" || kind == "vessel1" ||
               kind.starts_with("turbine") || kind == "cpld") {
      p.kind = MoorDynPointKind::coupled;
    } else if (kind == "connect" || kind == "free" || kind == "point" || kind == "con") {
      p.kind = MoorDynPointKind::free;
    } else if (kind.starts_with("body")) {
      p.kind = MoorDynPointKind::body;
      int body = 0;
      const auto r = std::from_chars(kind.data() + 4, kind.data() + kind.size(), body);
      if (r.ec != std::errc() || r.ptr != kind.data() + kind.size()) {
        fail(number, type->column, fmt::format("point attachment \"{}\": expected BodyN", type->text));
      }
      p.body = body;
    } else {
      fail(number, type->column,
           fmt::format("point attachment \"{}\" is not one of Fixed, Vessel, Coupled, Free, Connect, BodyN",
                       type->text));
    }
    for (int k = 0; k < 3; ++k)
      p.position_m[k] = number_of(tokens,
                                  column({k == 0   ? "x"
                                          : k == 1 ? "y"
                                                   : "z"},
                                         2 + k),
                                  number,
                                  k == 0   ? "X"
                                  : k == 1 ? "Y"
                                           : "Z");
    p.mass_kg = number_of(tokens, column({"m", "mass"}, 5), number, "Mass");
    p.volume_m3 = number_of(tokens, column({"v", "volume", "vol"}, 6), number, "Volume");
    for (std::size_t i = 7; i < tokens.size(); ++i) {
      double value = 0.0;
      const auto r = std::from_chars(tokens[i].text.data(), tokens[i].text.data() + tokens[i].text.size(), value);
      if (r.ec == std::errc() && value != 0.0) p.has_point_loads = true;
    }
    for (const MoorDynPoint& other : deck_.points)
      if (other.id == p.id)
        fail(number, tokens[0].column, fmt::format("point {} is defined twice (first on line {})", p.id, other.line));
    deck_.points.push_back(std::move(p));
  }

  void read_line(const std::vector<Token>& tokens, int number) {
    MoorDynLine l;
    l.line = number;
    l.id = integer_of(tokens, 0, number, "ID");
    l.type = tokens.size() > 1 ? tokens[1].text : std::string();
    if (const Token* a = field(tokens, column({"attacha", "nodeanch", "anchor", "enda"}, 2), number, "AttachA"))
      l.end_a = a->text;
    if (const Token* b = field(tokens, column({"attachb", "nodefair", "fairlead", "endb"}, 3), number, "AttachB"))
      l.end_b = b->text;
    const int length_column = column({"unstrlen", "length", "unstrlen(m)"}, 4);
    l.length_m = number_of(tokens, length_column, number, "UnstrLen");
    const int segments_column = column({"numsegs", "nsegs", "segments"}, 5);
    l.segments = integer_of(tokens, segments_column, number, "NumSegs");
    if (l.length_m <= 0.0 && static_cast<int>(tokens.size()) > length_column)
      fail(number, tokens[length_column].column, fmt::format("UnstrLen must be > 0 m, got {} m", l.length_m));
    if (l.segments < 1 && static_cast<int>(tokens.size()) > segments_column)
      fail(number, tokens[segments_column].column, fmt::format("NumSegs must be >= 1, got {}", l.segments));
    for (const MoorDynLine& other : deck_.lines)
      if (other.id == l.id)
        fail(number, tokens[0].column, fmt::format("line {} is defined twice (first on line {})", l.id, other.line));
    columns_of_line_.push_back(tokens.size() > 1 ? tokens[1].column : 1);
    deck_.lines.push_back(std::move(l));
  }

  void read_body(const std::vector<Token>& tokens, int number) {
    MoorDynBody b;
    b.line = number;
    b.id = integer_of(tokens, 0, number, "ID");
    if (const Token* a = field(tokens, 1, number, "Attachment")) b.attachment = a->text;
    for (int k = 0; k < 3; ++k) b.position_m[k] = number_of(tokens, 2 + k, number, "X0/Y0/Z0");
    for (int k = 0; k < 3; ++k) b.rotation_deg[k] = number_of(tokens, 5 + k, number, "r0/p0/y0");
    deck_.bodies.push_back(std::move(b));
  }

  /// Every line names a defined line type and defined points (or rod ends).
  void check_references() {
    for (std::size_t i = 0; i < deck_.lines.size(); ++i) {
      const MoorDynLine& l = deck_.lines[i];
      const bool typed = std::any_of(deck_.line_types.begin(), deck_.line_types.end(),
                                     [&](const MoorDynLineType& t) { return t.name == l.type; });
      if (!typed) {
        std::string defined;
        for (const MoorDynLineType& t : deck_.line_types)
          defined += fmt::format("{}{}", defined.empty() ? "" : ", ", t.name);
        fail(l.line, columns_of_line_[i],
             fmt::format("line {}: undefined line type \"{}\" (defined: {})", l.id, l.type,
                         defined.empty() ? "none" : defined));
      }
      for (const std::string* end : {&l.end_a, &l.end_b}) {
        if (end->empty() || std::toupper(static_cast<unsigned char>((*end)[0])) == 'R') continue;  // rod end: noted
        int id = 0;
        const auto r = std::from_chars(end->data(), end->data() + end->size(), id);
        const bool number = r.ec == std::errc() && r.ptr == end->data() + end->size();
        const bool defined = number && std::any_of(deck_.points.begin(), deck_.points.end(),
                                                   [&](const MoorDynPoint& p) { return p.id == id; });
        if (!defined) fail(l.line, 1, fmt::format("line {}: end \"{}\" is not a defined point", l.id, *end));
      }
    }
  }

  struct Skipped {
    std::string phrase, why;
    int first = 0, last = 0, rows = 0;
  };

  MoorDynDeck deck_;
  std::vector<InputIssue> issues_;
  Section section_ = Section::front;
  std::vector<std::string> header_;
  int table_rows_ = 0;
  int skipped_seen_ = 0;
  Skipped skipped_;
  std::vector<int> columns_of_line_;
};

}  // namespace

MoorDynDeck parse_moordyn_deck(std::string_view text, const std::string& source_name) {
  return DeckParser(source_name).parse(text);
}

MoorDynDeck read_moordyn_deck(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    throw InputError({{file.string(), std::nullopt, std::nullopt, "", InputOrigin::file,
                       "cannot read the MoorDyn deck (missing or unreadable)", "missing_file"}});
  }
  if (std::filesystem::is_directory(file)) {
    throw InputError({{file.string(), std::nullopt, std::nullopt, "", InputOrigin::file,
                       "is a folder, not a MoorDyn deck", "missing_file"}});
  }
  std::stringstream text;
  text << in.rdbuf();
  return parse_moordyn_deck(text.str(), file.string());
}

const MoorDynOption* find_option(const MoorDynDeck& deck, std::initializer_list<std::string_view> names) {
  for (const MoorDynOption& option : deck.options)
    for (std::string_view name : names)
      if (lower(option.name) == lower(name)) return &option;
  return nullptr;
}

}  // namespace spiral::design
