// ivv integrators, ivv laws: the two registries, one entry per line (-v: what each one is).
#include <iostream>

#include "app/command.h"
#include "solver/choice/integrator_accuracy.h"
#include "solver/laws/law_registry.h"
#include "solver/steppers/integrators.h"

namespace ivv::app {
namespace {

class Integrators final : public Command {
 public:
  explicit Integrators(CLI::App& app)
      : Command(app.add_subcommand("integrators", "list the integrators, one per line")) {
    cli().add_flag("-v,--verbose", verbose_, "add a description to each");
  }

  int run(const Invocation&) override {
    for (const IntegratorTraits& t : integrator_table()) {
      std::cout << t.name;
      if (verbose_)
        std::cout << "\torder " << t.order << (t.implicit ? ", implicit" : ", explicit")
                  << (t.dense_output ? ", dense output" : ", Hermite interpolant")
                  << (t.fixed_step ? ", fixed step" : ", adaptive")
                  << (t.reference ? ", reference" : "") << "\t" << t.description
                  << "\n\t  accuracy: " << accuracy_statement(t.kind);
      std::cout << "\n";
    }
    return 0;
  }

 private:
  bool verbose_ = false;
};

class Laws final : public Command {
 public:
  explicit Laws(CLI::App& app)
      : Command(app.add_subcommand("laws", "list the contact laws, one per line")) {
    cli().add_flag("-v,--verbose", verbose_, "add each law's equation and parameters");
  }

  int run(const Invocation&) override {
    for (const LawInfo& l : all_law_info()) {
      std::cout << l.name;
      if (verbose_) {
        std::cout << "\t" << l.summary;
        for (const ParameterSpec& ps : l.parameters)
          std::cout << "\n\t--param " << ps.name << " [" << ps.unit << "]: " << ps.meaning;
      }
      std::cout << "\n";
    }
    return 0;
  }

 private:
  bool verbose_ = false;
};

}  // namespace

std::unique_ptr<Command> make_integrators(CLI::App& app) {
  return std::make_unique<Integrators>(app);
}

std::unique_ptr<Command> make_laws(CLI::App& app) {
  return std::make_unique<Laws>(app);
}

}  // namespace ivv::app
