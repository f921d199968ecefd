// `ivv calibrate` and `ivv predict`: the flags and the runs (app/calibrate.cc makes
// them subcommands).
//
// ivv calibrate --scene S --data measured.csv --fit NAME[,NAME...] [--law L | --force EXPR]
//               [--start NAME=VALUE ...] [--bounds NAME=LO:HI ...] [--scan] [--no-profile]
//               [--compare LAW,LAW,...] [--json] [--out cal.json] [--report DIR]
//               [--threads N]
// ivv predict   --calibration cal.json (--v0 LO:HI:N [--log] | --data other.csv)
//               [--samples N] [--seed S] [--json] [--threads N]
// --compare: each listed law (built-in names, or `expression` for the --force law) is fitted
// to the same data with the --fit names it has (hunt-crossley: no series dashpot; mu, started
// from --start mu=... or 0.1 s/m with a coarse scan), then all are ranked by AIC/BIC.
// Exit codes: 0 success (points beyond 2 u_val are a finding, printed, not a failure); 1 a
// computation failed (the fit, the covariance, a draw); 2 bad input (one message naming the
// flag; no output file written).
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <string>
#include <vector>

#include "solver/simulate.h"

namespace ivv {

struct CalibrateFlags {
  std::string data;
  std::vector<std::string> fit;      // comma lists, joined
  std::vector<std::string> start;    // NAME=VALUE
  std::vector<std::string> bounds;   // NAME=LO:HI
  std::vector<std::string> compare;  // law names (comma lists, joined)
  bool scan = false, no_profile = false, json = false;
  std::string out, report_dir;
  int threads = 0;
};

struct PredictFlags {
  std::string calibration, v0, data;
  bool log = false, json = false;
  int samples = 10000;
  std::uint64_t seed = 1;
  int threads = 0;
};

void add_calibrate_flags(CLI::App& cmd, CalibrateFlags& f);
void add_predict_flags(CLI::App& cmd, PredictFlags& f);

int run_calibrate(const SimulationRequest& base, const CalibrateFlags& f,
                  const std::string& command_line);
int run_predict(const PredictFlags& f);

}  // namespace ivv
