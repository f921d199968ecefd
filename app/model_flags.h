// The flags that describe one impact (scene, overrides, law, integrator, tolerances), shared by
// simulate, sweep, fit-hc and check-law. Values are kept as typed and parsed by app/cli_args.h,
// so that '', '1e3x' or a count out of range is an InputError naming the flag; every range is
// then checked once, by the library (solver/request_options.h).
#pragma once

#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <vector>

#include "solver/request_options.h"

namespace ivv::app {

struct ModelFlags {
  std::string scene;
  std::optional<std::string> v0, zeta, c, lambda;
  bool no_dashpot = false;
  std::string law = "elastoplastic";
  std::string integrator = "auto";
  std::string model = "auto";
  std::optional<std::string> rtol, atol, dt, max_steps;
  std::optional<std::string> model_tolerance;  // a finite plate's choice of model
  std::optional<std::string> hc_k, hc_mu;
  std::vector<std::string> params;  // NAME=VALUE
  // expression law; given but empty is bad input (not "no expression")
  std::optional<std::string> force, unload;
  bool allow_tension = false;
};

// Which of the shared flags a command takes, and how.
struct ModelFlagSet {
  // --v0, --zeta, --c, --lambda and --no-dashpot as single values (sweep and check-law take
  // grids under the same names instead, and calibrate none).
  bool single_velocity_and_damping = false;
  bool scene_required = true;
};

void add_model_flags(CLI::App& cmd, ModelFlags& flags, ModelFlagSet set);

// The typed values as numbers (InputError naming the flag for a malformed one).
RequestOptions to_options(const ModelFlags& flags);

}  // namespace ivv::app
