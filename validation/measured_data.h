// Measured restitution data for calibration and validation (docs/design.md §5 "Measured data").
//
// File format: CSV with a header line, comma-separated, one impact per row.
//   v0         impact velocity [m/s]                                  required, finite > 0
//   e          Newton coefficient of restitution [-]                  required, finite >= 0
//   u_e        standard uncertainty of e [-]                          optional, finite > 0
//   F_max      peak contact force [N]                                 optional, finite > 0
//   u_F_max    its standard uncertainty [N]                           optional, finite > 0
//   t_contact  contact duration [s]                                   optional, finite > 0
//   u_t_contact its standard uncertainty [s]                          optional, finite > 0
// A u_ column without its quantity is refused; an unknown column is refused (a misspelt
// "u_E" would otherwise be silently ignored). Lines whose first non-blank character is `#`
// carry provenance (who measured, how, or for synthetic data the generating command) and are
// kept verbatim; blank lines are skipped. Cells may be blank only in an optional column (the
// quantity was not measured at that impact); a blank u_ cell beside a given value is refused.
//
// Failure: a malformed file throws InputError whose field is "FILE:LINE:COLUMN" (line counted from
// 1 over the whole file, column the header's name) and whose message says what is accepted - the
// command line turns it into exit code 2.
#pragma once

#include <array>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ivv::validation {

// The measured quantities an impact can give, in the order of this enum everywhere.
enum class Quantity { e, F_max, t_contact };
inline constexpr std::array<Quantity, 3> kQuantities{Quantity::e, Quantity::F_max,
                                                     Quantity::t_contact};
std::string_view to_string(Quantity q);  // the column name: "e", "F_max", "t_contact"
std::string_view unit(Quantity q);       // "-", "N", "s"

struct Measurement {
  double v0 = 0.0;  // [m/s]
  // Per quantity (index = Quantity): the measured value and its standard uncertainty; absent
  // when not measured at this impact (value) or not stated (uncertainty).
  std::array<std::optional<double>, 3> value;
  std::array<std::optional<double>, 3> uncertainty;
  int line = 0;  // line of the file it came from (for messages)
};

struct MeasuredData {
  std::string source;                   // file name (or "<memory>")
  std::vector<std::string> provenance;  // the `#` lines, without the '#'
  std::vector<Measurement> points;      // in file order
  // Which quantities have a column, and which have an uncertainty column.
  std::array<bool, 3> has_quantity{};
  std::array<bool, 3> has_uncertainty{};

  // Number of points at which quantity q was measured.
  std::size_t count(Quantity q) const;
};

// Reads and checks a data file. InputError as described above; at least one data row.
MeasuredData read_measured_data(const std::filesystem::path& path);
MeasuredData parse_measured_data(const std::string& text, const std::string& source);

// Writes the data in the same format (17 significant digits), provenance first.
std::string to_csv(const MeasuredData& data);

}  // namespace ivv::validation
