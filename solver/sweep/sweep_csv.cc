#include "solver/sweep/sweep_csv.h"

#include <algorithm>
#include <array>
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

SweepInputColumns::SweepInputColumns(const SweepRequest& request) : request_(&request) {
  auto text = [](double x) {
    std::string s;
    append_shortest(s, x);
    return s + ',';
  };
  for (double v : request.velocities) velocities_.push_back(text(v));
  if (!request.scene_dashpot)
    for (double z : request.zetas) zetas_.push_back(text(z));
  for (const SceneAxis& axis : request.axes) {
    axes_.emplace_back();
    for (double v : axis.values) axes_.back().push_back(text(v));
  }
}

void SweepInputColumns::append(std::string& row, std::size_t index) const {
  const GridPosition at = grid_position(*request_, index);
  row += velocities_[at.velocity];
  if (request_->scene_dashpot) {  // the zeta the scene's dashpot gives at this point
    append_shortest(row, point_inputs(*request_, index).zeta);
    row += ',';
  } else {
    row += zetas_[at.zeta];
  }
  if (axes_.empty()) return;
  const std::size_t first = row.size();
  std::size_t rest = at.axes;
  for (std::size_t k = axes_.size(); k-- > 0;) {  // the last axis fastest: filled back to front
    const std::vector<std::string>& values = axes_[k];
    row.insert(first, values[rest % values.size()]);
    rest /= values.size();
  }
}

SweepRowFacts append_sweep_csv_results(std::string& row, std::size_t row_start,
                                       const ImpactResult& r) {
  if (r.ok()) {  // formatted into one buffer, appended once (ten appends were ~500 instructions)
    const std::array<double, 10> numbers = {r.e,       r.e_poisson,      r.e_energetic, r.F_max,
                                            r.t_F_max, r.t_contact,      r.z_max,       r.alpha_max,
                                            r.z_perm,  r.energy.residual};
    std::array<char, numbers.size() * (kMaxNumberChars + 1)> text;
    char* end = text.data();
    for (double x : numbers) {
      end = write_general(end, x, kResultDigits);
      *end++ = ',';
    }
    row.append(text.data(), end);
  } else {
    row.append(10, ',');  // no number is better than a plausible wrong one
  }
  append_integer(row, r.steps);
  SweepRowFacts facts;
  facts.status = r.status;
  row += ',';
  facts.route = row.size() - row_start;
  facts.route_size = r.route.size();
  row += r.route;
  row += ',';
  facts.integrator = row.size() - row_start;
  facts.integrator_size = r.integrator.size();
  row += r.integrator;
  row += ',';
  row += to_string(r.status);
  row += ',';
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
