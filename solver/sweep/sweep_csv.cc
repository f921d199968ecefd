#include "solver/sweep/sweep_csv.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <stdexcept>

#include "scene/scene_values.h"
#include "solver/format.h"

namespace ivv {
namespace {

// Results at 12 significant digits: the same bytes as printf's %.12g (solver/format.h).
constexpr int kResultDigits = 12;

// Room for a row without its reason: 12 numbers of at most 24 characters, the step count, the
// route, integrator and status names and the separators.
constexpr std::size_t kSweepRowCapacity = 12 * 24 + 20 + 3 * 32 + 17;

struct Column {
  const char* name;
  const char* unit;
};
constexpr std::array<Column, 2> kInputColumns = {{{"v0", "m/s"}, {"zeta", "-"}}};
constexpr std::array<Column, 15> kResultColumns = {{{"e", "-"},
                                                    {"e_poisson", "-"},
                                                    {"e_energetic", "-"},
                                                    {"F_max", "N"},
                                                    {"t_F_max", "s"},
                                                    {"t_contact", "s"},
                                                    {"z_max", "m"},
                                                    {"alpha_max", "m"},
                                                    {"z_perm", "m"},
                                                    {"energy_residual", "J"},
                                                    {"steps", "-"},
                                                    {"route", ""},
                                                    {"integrator", ""},
                                                    {"status", ""},
                                                    {"reason", ""}}};

}  // namespace

std::vector<SweepColumn> sweep_csv_columns(const std::vector<SceneAxis>& axes) {
  std::vector<SweepColumn> columns;
  for (const Column& c : kInputColumns) columns.push_back({c.name, c.unit});
  for (const SceneAxis& a : axes) {
    const SceneValueInfo* info = find_scene_value(a.key);
    columns.push_back({a.key, info ? std::string(info->unit) : std::string()});
  }
  for (const Column& c : kResultColumns) columns.push_back({c.name, c.unit});
  return columns;
}

std::string sweep_csv_header(const std::vector<SceneAxis>& axes) {
  std::string header;
  for (const SweepColumn& c : sweep_csv_columns(axes)) {
    if (!header.empty()) header += ',';
    header += c.name;
  }
  return header + '\n';
}

std::string sweep_csv_columns_text(const std::vector<SceneAxis>& axes) {
  std::string text;
  for (const SweepColumn& c : sweep_csv_columns(axes)) {
    if (!text.empty()) text += ", ";
    text += c.name;
    if (!c.unit.empty()) text += " [" + c.unit + "]";
  }
  return text;
}

int sweep_csv_column_index(std::string_view name, std::size_t axis_count) {
  for (std::size_t i = 0; i < kInputColumns.size(); ++i)
    if (name == kInputColumns[i].name) return static_cast<int>(i);
  for (std::size_t i = 0; i < kResultColumns.size(); ++i)
    if (name == kResultColumns[i].name)
      return static_cast<int>(kInputColumns.size() + axis_count + i);
  throw std::logic_error("sweep CSV has no column '" + std::string(name) + "'");
}

namespace {
void append_inputs(std::string& row, const PointInputs& in) {
  append_shortest(row, in.v0);
  row += ',';
  append_shortest(row, in.zeta);
  row += ',';
  for (double x : in.axes) {
    append_shortest(row, x);
    row += ',';
  }
}
}  // namespace

std::string sweep_csv_inputs(const PointInputs& inputs) {
  std::string s;
  append_inputs(s, inputs);
  return s;
}

SweepInputColumns::Text SweepInputColumns::text(double x) {
  static_assert(kMaxNumberChars <= sizeof(Text::chars), "a number's text and its comma fit");
  Text t;
  t.chars.fill(',');
  char* end = write_shortest(t.chars.data(), x);                // room for kMaxNumberChars
  t.size = static_cast<std::size_t>(end - t.chars.data()) + 1;  // and its comma
  *end = ',';
  return t;
}

SweepInputColumns::SweepInputColumns(const SweepRequest& request) : request_(&request) {
  for (double v : request.velocities) velocities_.push_back(text(v));
  if (!request.scene_dashpot)
    for (double z : request.zetas) zetas_.push_back(text(z));
  for (const SceneAxis& axis : request.axes) {
    axes_.emplace_back();
    for (double v : axis.values) {
      const Text t = text(v);
      axes_.back().emplace_back(t.chars.data(), t.size);
    }
  }
}

void SweepInputColumns::append(std::string& row, std::size_t index) const {
  const GridPosition at = grid_position(*request_, index);
  // v0's text and zeta's, each copied whole into `both` (at most 25 + 32 characters)
  std::array<char, 2 * sizeof(Text::chars)> both;
  const Text& v0 = velocities_[at.velocity];
  std::memcpy(both.data(), v0.chars.data(), sizeof v0.chars);
  Text derived;  // the zeta the scene's dashpot gives at this point
  if (request_->scene_dashpot) derived = text(point_inputs(*request_, index).zeta);
  const Text& zeta = request_->scene_dashpot ? derived : zetas_[at.zeta];
  std::memcpy(both.data() + v0.size, zeta.chars.data(), sizeof zeta.chars);
  row.append(both.data(), v0.size + zeta.size);
  if (axes_.empty()) return;
  const std::size_t first = row.size();
  std::size_t rest = at.axes;
  for (std::size_t k = axes_.size(); k-- > 0;) {  // the last axis fastest: filled back to front
    const std::vector<std::string>& values = axes_[k];
    row.insert(first, values[rest % values.size()]);
    rest /= values.size();
  }
}

namespace {

// The names a row carries (route, integrator, status) are copied into the row's buffer when each
// is at most this long (every name ivv gives is; a longer one is appended on its own).
constexpr std::size_t kMaxBufferedName = 40;

// Copies `name` (at most kMaxBufferedName characters) and a comma to `out`; returns the end. In
// words of eight (or four) bytes, the last one overlapping the one before: the library's memcpy
// of a name's few bytes was a call, ~20 instructions a name against ~8 (callgrind).
char* put_name(char* out, std::string_view name) {
  const char* s = name.data();
  const std::size_t n = name.size();
  if (n >= 8) {
    for (std::size_t i = 0; i + 8 < n; i += 8) std::memcpy(out + i, s + i, 8);
    std::memcpy(out + n - 8, s + n - 8, 8);
  } else if (n >= 4) {
    std::memcpy(out, s, 4);
    std::memcpy(out + n - 4, s + n - 4, 4);
  } else {  // three characters at most, one by one (a loop here became a call to memcpy)
    if (n > 0) out[0] = s[0];
    if (n > 1) out[1] = s[1];
    if (n > 2) out[2] = s[2];
  }
  out[n] = ',';
  return out + n + 1;
}

// The reason column: quoted (RFC 4180, inner quotes doubled, line breaks as spaces), empty for a
// run that did not fail, "failed without a reason" for one that failed without saying why.
void append_reason(std::string& row, const ImpactResult& r) {
  if (!r.reason.empty()) {
    row += '"';
    for (char c : r.reason) {
      if (c == '"') row += '"';
      row += (c == '\n' || c == '\r') ? ' ' : c;
    }
    row += '"';
  } else if (!r.ok()) {
    row += "\"failed without a reason\"";
  }
  row += '\n';
}

}  // namespace

namespace {

constexpr std::size_t kResultNumbers = 10;

// x at kResultDigits and a comma at `out` (room for kMaxNumberChars + 1); returns the end.
char* put_number(char* out, double x) {
  out = write_general<kResultDigits>(out, x);
  *out++ = ',';
  return out;
}

// y and a comma at `out`, where the text of x and its comma end: copied from that text when y is
// x bit for bit, ~10 instructions against ~140 to format it (callgrind). In 32 bytes (the text of a
// number is at most 25 with its comma) through a temporary, as the copy overlaps its source.
char* put_number_after(char* out, double y, const char* x_text, double x) {
  if (std::bit_cast<std::uint64_t>(y) != std::bit_cast<std::uint64_t>(x)) return put_number(out, y);
  std::array<char, kMaxNumberChars> copy;
  std::memcpy(copy.data(), x_text, copy.size());
  std::memcpy(out, copy.data(), copy.size());
  return out + (out - x_text);
}

// The result numbers, each followed by a comma, at `out` (room for
// kResultNumbers (kMaxNumberChars + 1) characters); returns the end. e_poisson is often e bit for
// bit, and e_energetic sometimes e_poisson: those are copied (put_number_after; 754 copies in the
// 1,800 rows of the 60 x 30 paper map, and 98 % of the 300 x 300 map's rows print e_poisson as e).
// Written out, not a loop over an array of the ten (which cost ~19 instructions a number besides
// the formatting).
char* write_result_numbers(char* out, const ImpactResult& r) {
  const char* const e = out;
  out = put_number(out, r.e);
  const char* const e_poisson = out;
  out = put_number_after(out, r.e_poisson, e, r.e);
  out = put_number_after(out, r.e_energetic, e_poisson, r.e_poisson);
  out = put_number(out, r.F_max);
  out = put_number(out, r.t_F_max);
  out = put_number(out, r.t_contact);
  out = put_number(out, r.z_max);
  out = put_number(out, r.alpha_max);
  out = put_number(out, r.z_perm);
  return put_number(out, r.energy.residual);
}

}  // namespace

SweepRowFacts append_sweep_csv_results(std::string& row, std::size_t row_start,
                                       const ImpactResult& r) {
  // The numbers, the step count and the names formatted into one buffer and appended once (each
  // append to the row was ~25 instructions, a dozen of them a row, callgrind).
  constexpr std::size_t kCapacity = kResultNumbers * (kMaxNumberChars + 1) + kMaxIntegerChars + 1 +
                                    3 * (kMaxBufferedName + 1) + 1;
  std::array<char, kCapacity> text;
  char* end = text.data();
  if (r.ok()) {
    end = write_result_numbers(end, r);
  } else {  // no number is better than a plausible wrong one
    std::memset(end, ',', kResultNumbers);
    end += kResultNumbers;
  }
  end = write_integer(end, r.steps);
  *end++ = ',';
  const std::string_view status = to_string(r.status);
  SweepRowFacts facts;
  facts.status = r.status;
  facts.route_size = r.route.size();
  facts.integrator_size = r.integrator.size();
  const std::size_t at = row.size() - row_start;  // the buffer's first character in the row
  if (r.route.size() <= kMaxBufferedName && r.integrator.size() <= kMaxBufferedName &&
      status.size() <= kMaxBufferedName) {
    facts.route = at + static_cast<std::size_t>(end - text.data());
    end = put_name(end, r.route);
    facts.integrator = at + static_cast<std::size_t>(end - text.data());
    end = put_name(end, r.integrator);
    end = put_name(end, status);
    if (r.reason.empty() && r.ok()) {  // an empty reason: the row ends here
      *end++ = '\n';
      row.append(text.data(), static_cast<std::size_t>(end - text.data()));
      return facts;
    }
    row.append(text.data(), static_cast<std::size_t>(end - text.data()));
  } else {
    row.append(text.data(), static_cast<std::size_t>(end - text.data()));
    facts.route = row.size() - row_start;
    row.append(r.route).append(1, ',');
    facts.integrator = row.size() - row_start;
    row.append(r.integrator).append(1, ',').append(status).append(1, ',');
  }
  append_reason(row, r);
  return facts;
}

void append_sweep_csv_row(std::string& row, const PointInputs& in, const ImpactResult& r) {
  const std::size_t start = row.size();
  append_inputs(row, in);
  append_sweep_csv_results(row, start, r);
}

std::string sweep_csv_row(const PointInputs& inputs, const ImpactResult& r) {
  std::string row;
  row.reserve(kSweepRowCapacity + 25 * inputs.axes.size() + r.reason.size());
  append_sweep_csv_row(row, inputs, r);
  return row;
}

std::string sweep_csv_row(double v0, double zeta, const ImpactResult& r) {
  return sweep_csv_row(PointInputs{v0, zeta, {}}, r);
}

}  // namespace ivv
