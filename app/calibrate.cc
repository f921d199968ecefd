// ivv calibrate, ivv predict: a law's parameters fitted to measured restitution with their
// uncertainty, and predictions with bands and the ASME V&V 20 comparison. The flags
// and the runs are in app/calibrate_command.h, on the library validation/.
#include "app/calibrate_command.h"
#include "app/command.h"
#include "app/model_flags.h"

namespace ivv::app {
namespace {

class Calibrate final : public Command {
 public:
  explicit Calibrate(CLI::App& app)
      : Command(app.add_subcommand(
            "calibrate",
            "fit law or scene parameters to measured restitution (Ceres), with standard errors, "
            "95 % intervals, correlations, chi^2 and identifiability; --compare ranks laws")) {
    add_model_flags(cli(), flags_, {});
    add_calibrate_flags(cli(), calibrate_);
  }

  int run(const Invocation& inv) override {
    return run_calibrate(to_request(to_options(flags_)), calibrate_, inv.command_line);
  }

 private:
  ModelFlags flags_;
  CalibrateFlags calibrate_;
};

class Predict final : public Command {
 public:
  explicit Predict(CLI::App& app)
      : Command(app.add_subcommand(
            "predict",
            "COR with a 95 % band from a calibration (seeded Monte Carlo over its covariance); "
            "against held-back data, the ASME V&V 20 comparison")) {
    add_predict_flags(cli(), predict_);
  }

  int run(const Invocation&) override { return run_predict(predict_); }

 private:
  PredictFlags predict_;
};

}  // namespace

std::unique_ptr<Command> make_calibrate(CLI::App& app) {
  return std::make_unique<Calibrate>(app);
}

std::unique_ptr<Command> make_predict(CLI::App& app) {
  return std::make_unique<Predict>(app);
}

}  // namespace ivv::app
