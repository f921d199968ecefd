// ivv: the command line. One file per subcommand under app/ (app/command.h); this file only
// builds the parser from them, runs the one the user named and turns errors into exit codes.
// A thin layer: everything a command prints is computed by the libraries (solver, oracles,
// verification, reports).
//
// Exit codes: 0 success; 1 a computation failed (integrator could not meet its tolerance,
// a verification case failed); 2 bad input (message names the field and accepted range).
#include <CLI/CLI.hpp>

#include <iostream>
#include <memory>
#include <vector>

#include "app/command.h"
#include "app/shell_quote.h"
#include "scene/input_error.h"

int main(int argc, char** argv) {
  using namespace ivv::app;
  CLI::App app{
      "ivv - verification and validation of impact contact models.\n"
      "A sphere strikes a half-space through a nonlinear elastoplastic contact spring in\n"
      "series with a dashpot. Start with:\n"
      "  ivv simulate --scene paper --v0 1 --c 11440\n"
      "  ivv scene show --scene paper\n"
      "  ivv integrators"};
  app.require_subcommand(1);
  app.set_help_all_flag("--help-all", "help for every subcommand");

  std::vector<std::unique_ptr<Command>> commands;
  for (auto make :
       {make_simulate, make_sweep, make_scene_show, make_integrators, make_laws, make_fit_hc,
        make_verify, make_report, make_check_law, make_bench, make_calibrate, make_predict})
    commands.push_back(make(app));

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "ivv: " << e.what() << "\n(run with --help for usage)\n";
    return kExitBadInput;
  }

  Invocation invocation{argc, argv, {}};
  invocation.command_line = ivv::app::shell_command_line(argc, argv);  // pastes back into a shell
  try {
    for (const auto& command : commands)
      if (command->cli()) return command->run(invocation);
  } catch (const ivv::InputError& e) {
    std::cerr << "ivv: error: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "ivv: failed: " << e.what() << "\n";
    return kExitFailure;
  }
  return 0;
}
