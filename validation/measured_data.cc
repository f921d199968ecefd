#include "validation/measured_data.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "scene/input_error.h"

namespace ivv::validation {
namespace {

// Files are read up to this size: 1e5 impacts of ~100 bytes leave room; a larger input
// (e.g. /dev/zero) is refused rather than read without end.
constexpr std::size_t kMaxDataFileBytes = std::size_t{16} << 20;

std::string trim(std::string_view s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string_view::npos) return {};
  const auto e = s.find_last_not_of(" \t\r");
  return std::string(s.substr(b, e - b + 1));
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::size_t start = 0;
  for (;;) {
    const auto comma = line.find(',', start);
    cells.push_back(trim(std::string_view(line).substr(start, comma - start)));
    if (comma == std::string::npos) return cells;
    start = comma + 1;
  }
}

// The column layout: which header name sits in which cell.
enum class Column { v0, value, uncertainty };
struct ColumnRole {
  Column kind;
  Quantity q = Quantity::e;
  std::string name;
};

ColumnRole column_role(const std::string& name, const std::string& where) {
  if (name == "v0") return {Column::v0, Quantity::e, name};
  for (Quantity q : kQuantities) {
    if (name == to_string(q)) return {Column::value, q, name};
    if (name == "u_" + std::string(to_string(q))) return {Column::uncertainty, q, name};
  }
  throw InputError(where, "unknown column '" + name +
                              "'; accepted columns: v0, e, u_e, F_max, u_F_max, t_contact, "
                              "u_t_contact (v0 and e required)");
}

// Whether a cell may hold 0 (a measured e of 0 is a capture; a speed or an uncertainty of 0 is
// not a measurement).
enum class Zero { refused, allowed };

double parse_cell(const std::string& cell, const std::string& where, Zero zero) {
  const bool allow_zero = zero == Zero::allowed;
  double v = 0.0;
  const char* end = cell.data() + cell.size();
  const auto [ptr, ec] = std::from_chars(cell.data(), end, v);
  if (cell.empty() || ec != std::errc() || ptr != end || !std::isfinite(v) || v < 0 ||
      (!allow_zero && v == 0))
    throw InputError(where, std::string("must be a finite number ") +
                                (allow_zero ? ">= 0" : "> 0") + ", got '" + cell + "'");
  return v;
}

std::vector<ColumnRole> read_header(const std::string& line, const std::string& where_line,
                                    MeasuredData& data) {
  std::vector<ColumnRole> roles;
  std::map<std::string, int> seen;
  const auto cells = split(line);
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const std::string where = where_line + ":" + std::to_string(i + 1);
    if (seen.count(cells[i])) throw InputError(where, "column '" + cells[i] + "' appears twice");
    seen[cells[i]] = 1;
    roles.push_back(column_role(cells[i], where));
    const ColumnRole& r = roles.back();
    const auto qi = static_cast<std::size_t>(r.q);
    if (r.kind == Column::value) data.has_quantity[qi] = true;
    if (r.kind == Column::uncertainty) data.has_uncertainty[qi] = true;
  }
  if (!seen.count("v0") || !seen.count("e"))
    throw InputError(where_line, "the header must name the columns v0 [m/s] and e [-]");
  for (Quantity q : kQuantities) {
    const auto qi = static_cast<std::size_t>(q);
    if (data.has_uncertainty[qi] && !data.has_quantity[qi])
      throw InputError(where_line, "column u_" + std::string(to_string(q)) + " needs the column " +
                                       std::string(to_string(q)));
  }
  return roles;
}

Measurement read_row(const std::vector<ColumnRole>& roles, const std::string& line,
                     const std::string& where_line, int line_number) {
  const auto cells = split(line);
  if (cells.size() != roles.size())
    throw InputError(where_line, "has " + std::to_string(cells.size()) + " cells; the header has " +
                                     std::to_string(roles.size()));
  Measurement m;
  m.line = line_number;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const ColumnRole& r = roles[i];
    const std::string where = where_line + ":" + r.name;
    const auto qi = static_cast<std::size_t>(r.q);
    const bool required = r.kind == Column::v0 || (r.kind == Column::value && r.q == Quantity::e);
    if (cells[i].empty() && !required) continue;
    if (r.kind == Column::v0) m.v0 = parse_cell(cells[i], where, Zero::refused);
    if (r.kind == Column::value)
      m.value[qi] = parse_cell(cells[i], where, r.q == Quantity::e ? Zero::allowed : Zero::refused);
    if (r.kind == Column::uncertainty)
      m.uncertainty[qi] = parse_cell(cells[i], where, Zero::refused);
  }
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const ColumnRole& r = roles[i];
    const auto qi = static_cast<std::size_t>(r.q);
    if (r.kind == Column::uncertainty && m.value[qi] && !m.uncertainty[qi])
      throw InputError(where_line + ":" + r.name,
                       "is blank beside a measured " + std::string(to_string(r.q)) +
                           "; give its standard uncertainty (> 0) or drop the column");
  }
  return m;
}

}  // namespace

std::string_view to_string(Quantity q) {
  switch (q) {
    case Quantity::e:
      return "e";
    case Quantity::F_max:
      return "F_max";
    case Quantity::t_contact:
      return "t_contact";
  }
  return "?";
}

std::string_view unit(Quantity q) {
  switch (q) {
    case Quantity::e:
      return "-";
    case Quantity::F_max:
      return "N";
    case Quantity::t_contact:
      return "s";
  }
  return "?";
}

std::size_t MeasuredData::count(Quantity q) const {
  std::size_t n = 0;
  for (const auto& p : points) n += p.value[static_cast<std::size_t>(q)].has_value();
  return n;
}

namespace {

// The text as lines end in it: a UTF-8 byte-order mark (Excel's "CSV UTF-8") dropped, and
// CR LF (Windows) and a lone CR (classic Mac OS) read as LF, so that no '\r' reaches a cell or
// a message and every line is counted.
std::string normalised(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  const std::size_t start = text.rfind("\xEF\xBB\xBF", 0) == 0 ? 3 : 0;
  for (std::size_t i = start; i < text.size(); ++i) {
    if (text[i] != '\r') {
      out += text[i];
    } else if (i + 1 >= text.size() || text[i + 1] != '\n') {
      out += '\n';
    }
  }
  return out;
}

}  // namespace

MeasuredData parse_measured_data(const std::string& given, const std::string& source) {
  MeasuredData data;
  data.source = source;
  const std::string text = normalised(given);
  std::istringstream in(text);
  std::string line;
  std::vector<ColumnRole> roles;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    const std::string where = source + ":" + std::to_string(number);
    const std::string t = trim(line);
    if (t.empty()) continue;
    if (t[0] == '#') {
      data.provenance.push_back(trim(std::string_view(t).substr(1)));
      continue;
    }
    if (roles.empty()) {
      roles = read_header(t, where, data);
      continue;
    }
    data.points.push_back(read_row(roles, t, where, number));
  }
  if (roles.empty()) throw InputError(source, "no header line (expected e.g. 'v0,e,u_e')");
  if (data.points.empty()) throw InputError(source, "no data rows after the header");
  // An optional column blank in every row measured nothing: it is an absent column (left
  // present, the fit would count a quantity with no points and estimate its noise from none).
  for (Quantity q : kQuantities) {
    const auto qi = static_cast<std::size_t>(q);
    if (data.count(q) == 0) data.has_quantity[qi] = data.has_uncertainty[qi] = false;
  }
  return data;
}

MeasuredData read_measured_data(const std::filesystem::path& path) {
  const std::string name = path.string();
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError("--data", name + " is a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("--data", "cannot read " + name);
  std::string text(kMaxDataFileBytes + 1, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  if (text.size() > kMaxDataFileBytes)
    throw InputError("--data", name + " is larger than 16 MiB; a data file is one impact a line");
  return parse_measured_data(text, name);
}

std::string to_csv(const MeasuredData& data) {
  std::ostringstream os;
  os.precision(17);
  for (const auto& p : data.provenance) os << "# " << p << '\n';
  os << "v0";
  for (Quantity q : kQuantities) {
    const auto qi = static_cast<std::size_t>(q);
    if (data.has_quantity[qi]) os << ',' << to_string(q);
    if (data.has_uncertainty[qi]) os << ",u_" << to_string(q);
  }
  os << '\n';
  for (const auto& m : data.points) {
    os << m.v0;
    for (Quantity q : kQuantities) {
      const auto qi = static_cast<std::size_t>(q);
      if (data.has_quantity[qi]) {
        os << ',';
        if (m.value[qi]) os << *m.value[qi];
      }
      if (data.has_uncertainty[qi]) {
        os << ',';
        if (m.uncertainty[qi]) os << *m.uncertainty[qi];
      }
    }
    os << '\n';
  }
  return os.str();
}

}  // namespace ivv::validation
