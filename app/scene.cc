// ivv scene show: a scene and its derived parameters.
#include <iostream>

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
    if (json_)
      std::cout << scene_json(s, derive(s)).dump(2) << std::endl;
    else
      std::cout << scene_summary(s);
    return 0;
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
