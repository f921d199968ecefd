// solver/sweep/sweep_csv.h: a row's result columns are each number formatted alone (printf's
// %.12g through solver/format.h), whatever the row copies instead of formatting again.
#include "solver/sweep/sweep_csv.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "solver/format.h"

namespace ivv {
namespace {

// The row of `r` as its definition says, one field at a time.
std::string expected_row(double v0, double zeta, const ImpactResult& r) {
  std::string row;
  append_shortest(row, v0);
  row += ',';
  append_shortest(row, zeta);
  row += ',';
  for (double x : {r.e, r.e_poisson, r.e_energetic, r.F_max, r.t_F_max, r.t_contact, r.z_max,
                   r.alpha_max, r.z_perm, r.energy.residual}) {
    if (r.ok()) append_general(row, x, 12);
    row += ',';
  }
  append_integer(row, r.steps);
  row += ',';
  row.append(r.route).append(",").append(r.integrator).append(",");
  row.append(to_string(r.status)).append(",");
  if (!r.reason.empty()) row.append("\"").append(r.reason).append("\"");
  return row + "\n";
}

ImpactResult separated_result() {
  ImpactResult r;
  r.status = ImpactStatus::separated;
  r.e = r.e_poisson = r.e_energetic = 0.914364987837123;
  r.F_max = 187.71369782612;
  r.t_F_max = 4.5847778400123e-4;
  r.t_contact = 9.3832960244812e-4;
  r.z_max = 3.0490068473312e-5;
  r.alpha_max = 3.1954815790812e-5;
  r.z_perm = 0.0;
  r.energy.residual = -4.9035276707123e-12;
  r.steps = 16;
  r.integrator = "dop853";
  return r;
}

// A number the same as the one before it is copied from that one's text (e_poisson after e,
// e_energetic after e_poisson): the copies hold for the longest text a 12-digit number has (19
// characters), for zeros of either sign next to each other (equal as numbers, not as bits: "0"
// and "-0"), for numbers one ulp apart and for every pair in the rest of the row.
TEST(SweepCsv, RepeatedNumbersPrintAsEachAlone) {
  const double longest = -1.23456789012e-100;       // "-1.23456789012e-100": 19 characters
  const double longest_fixed = -0.000123456789012;  // "-0.000123456789012": 18
  std::vector<ImpactResult> results;
  for (double x :
       {0.5, 1.0, 0.0, -0.0, longest, longest_fixed, 1.0 / 3.0, 123456789012.0,
        std::numeric_limits<double>::max(), -std::numeric_limits<double>::denorm_min()}) {
    ImpactResult r = separated_result();
    r.e = r.e_poisson = r.e_energetic = x;  // all three copied
    results.push_back(r);
    r.e_poisson = std::nextafter(x, 1.0);  // one ulp off: e_poisson and e_energetic formatted
    results.push_back(r);
    r.e_poisson = x;
    r.e_energetic = -x;  // -0 after 0 and 0 after -0: formatted, not copied
    results.push_back(r);
    r.z_max = r.alpha_max = r.z_perm = r.energy.residual = x;
    results.push_back(r);
  }
  for (const ImpactResult& r : results) {
    EXPECT_EQ(sweep_csv_row(0.25, 0.1, r), expected_row(0.25, 0.1, r));
    std::string row = "0.25,0.1,";
    append_sweep_csv_results(row, 0, r);
    EXPECT_EQ(row, expected_row(0.25, 0.1, r));
  }
}

// The route, integrator and status names are copied a word at a time: every length from empty
// to past the buffered limit (40 characters), on a separated and on a failed row.
TEST(SweepCsv, NamesOfEveryLengthAreCopiedWhole) {
  std::string alphabet;
  for (int i = 0; i < 64; ++i) alphabet += static_cast<char>('a' + i % 26);
  for (std::size_t n = 0; n <= 60; ++n) {
    ImpactResult r = separated_result();
    r.route = std::string_view(alphabet).substr(0, n);
    r.integrator = std::string_view(alphabet).substr(60 - n, n);
    EXPECT_EQ(sweep_csv_row(1.0, 0.0, r), expected_row(1.0, 0.0, r)) << n;
    r.status = ImpactStatus::failed;
    r.reason = "a reason";
    EXPECT_EQ(sweep_csv_row(1.0, 0.0, r), expected_row(1.0, 0.0, r)) << n;
  }
}

}  // namespace
}  // namespace ivv
