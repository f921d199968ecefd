// ivv scene show: a scene and its derived parameters.
#include <iostream>
#include <optional>

#include "app/command.h"
#include "reports/impact_json.h"
#include "reports/impact_text.h"

namespace ivv::app {
namespace {

class SceneShow final : public Command {
 public:
  explicit SceneShow(CLI::App& app) : Command(add(app)) {
    cli().add_option("--scene", scene_, "scene file or 'paper'")->required();
    cli().add_flag("--json", json_, "JSON output");
  }

  int run(const Invocation&) override {
    const Scene s = load_scene(scene_);
    const std::optional<PlateRun> plate = plate_regime_run(s);
    if (json_) {
      nlohmann::json j = scene_json(s, derive(s));
      if (plate) j["regime"] = plate_regime_json(*plate->regime);
      if (plate) j["regime"]["law"] = std::string(to_string(plate->law));
      std::cout << j.dump(2) << std::endl;
    } else {
      std::cout << scene_summary(s);
      if (plate)
        std::cout << "which model this impact needs (" << to_string(plate->law)
                  << " law at the scene's v0; ivv simulate prints the same):\n"
                  << plate_regime_text(*plate);
    }
    return 0;
  }

  // A finite plate's regime at the scene's v0, with the elastoplastic law where the scene has a
  // yield strength and Hertz otherwise; none for other scenes or when the full plate failed.
  static std::optional<PlateRun> plate_regime_run(const Scene& s) {
    if (!has_finite_plate(s)) return std::nullopt;
    RequestOptions o;
    o.law = s.yield_strength ? "elastoplastic" : "hertz";
    PlateRun run = run_plate_simulation(s, o);
    if (!run.regime) return std::nullopt;
    return run;
  }

 private:
  static CLI::App* add(CLI::App& app) {
    CLI::App* scene = app.add_subcommand("scene", "scene utilities");
    scene->require_subcommand(1);
    return scene->add_subcommand("show", "print a scene and its derived parameters");
  }
  std::string scene_;
  bool json_ = false;
};

}  // namespace

std::unique_ptr<Command> make_scene_show(CLI::App& app) {
  return std::make_unique<SceneShow>(app);
}

}  // namespace ivv::app
