#include "app/model_flags.h"

#include <limits>
#include <utility>

#include "app/cli_args.h"
#include "oracles/expression_functions.h"
#include "scene/input_error.h"

namespace ivv::app {
namespace {

std::optional<double> number(const std::optional<std::string>& text, const std::string& field) {
  if (!text) return std::nullopt;
  return parse_number(*text, field);
}

}  // namespace

void add_model_flags(CLI::App& cmd, ModelFlags& f, ModelFlagSet set) {
  auto* scene = cmd.add_option(
      "--scene", f.scene,
      "scene file (TOML, docs/design.md §5), 'paper' (Table 1), or a shipped scene's name");
  if (set.scene_required) scene->required();
  if (set.single_velocity_and_damping) {
    cmd.add_option("--v0", f.v0, "impact velocity [m/s] (overrides the scene)");
    auto* z = cmd.add_option("--zeta", f.zeta, "damping ratio of the series dashpot");
    auto* c = cmd.add_option("--c", f.c, "dashpot coefficient [N s/m]");
    auto* l = cmd.add_option("--lambda", f.lambda,
                             "Zener's lambda = m*^(3/5) K_h^(2/5) v0^(1/5) / c: the dashpot that "
                             "gives it at this v0");
    auto* n = cmd.add_flag("--no-dashpot", f.no_dashpot, "ignore the scene's dashpot");
    z->excludes(c)->excludes(l)->excludes(n);
    c->excludes(l)->excludes(n);
    l->excludes(n);
  }
  auto* law = cmd.add_option("--law", f.law, "contact law (see `ivv laws`)")->capture_default_str();
  auto* force = cmd.add_option(
      "--force", f.force,
      "expression law: loading force [N] in z, zdot, zmax, m, R, E_star, K_h, z_y, K_y, v0 and "
      "--param names (muParser), and the published formulas of `ivv check-law --functions`, "
      "e.g. 'K_h*z^1.5'");
  force->excludes(law);
  cmd.add_option("--unload", f.unload,
                 "expression law: unloading force [N] after dz/dt = 0 (zmax = z_m); default: "
                 "the --force expression")
      ->needs(force);
  cmd.add_flag("--allow-tension", f.allow_tension,
               "expression law: F may go negative and contact ends at z = 0 (default: F >= 0, "
               "contact ends at F = 0)")
      ->needs(force);
  cmd.add_option("--param", f.params,
                 "law parameter NAME=VALUE (repeatable; `ivv laws -v` lists each law's)");
  cmd.add_option("--integrator", f.integrator,
                 "integrator (see `ivv integrators`), or auto: chosen by stiffness; a finite "
                 "plate: exponential (auto), dop853 or odeint-dopri5")
      ->capture_default_str();
  cmd.add_option("--model", f.model,
                 "auto: what the scene needs within --rtol (exact closed forms where they exist, "
                 "the linearized closed form where its estimated error is within --rtol, else "
                 "the integrator); full: always integrate the law's ODE model. A finite plate "
                 "also takes half-space, infinite-plate, quasi-static (solver/plate/"
                 "plate_regime.h)")
      ->capture_default_str();
  cmd.add_option("--model-tol", f.model_tolerance,
                 "a finite plate: the tolerance of the model choice, in e (units of v0) and "
                 "relative in F_max (default 1e-3)");
  cmd.add_option(
      "--rtol", f.rtol,
      "relative tolerance, adaptive integrators (default 1e-10; 1e-8 on a finite plate)");
  cmd.add_option("--atol", f.atol,
                 "absolute tolerance, normalised units (default 1e-12; 1e-10 on a finite plate)");
  cmd.add_option("--dt", f.dt,
                 "fixed step of rk4 in normalised time tau = omega t (default 1e-3; omega = "
                 "omega0 for laws with yield, v0/z_mH for hertz and hunt-crossley)");
  cmd.add_option("--max-steps", f.max_steps,
                 "give up after this many steps (default " +
                     std::to_string(IntegratorOptions{}.max_steps) + ")");
  cmd.add_option("--hc-k", f.hc_k,
                 "Hunt-Crossley stiffness K [N/m^1.5] (default: the scene's K_h)");
  cmd.add_option("--hc-mu", f.hc_mu, "Hunt-Crossley damping mu [s/m] (default 0)");
}

RequestOptions to_options(const ModelFlags& f) {
  RequestOptions o;
  o.scene = f.scene;
  o.v0 = number(f.v0, "--v0");
  o.zeta = number(f.zeta, "--zeta");
  o.c = number(f.c, "--c");
  o.lambda = number(f.lambda, "--lambda");
  o.no_dashpot = f.no_dashpot;
  o.law = f.law;
  for (const auto& [text, flag] :
       {std::pair{&f.force, "--force"}, std::pair{&f.unload, "--unload"}})
    if (*text && text->value().find_first_not_of(" \t") == std::string::npos)
      throw InputError(flag, "is empty; give the force [N] as an expression, e.g. 'K_h*z^1.5'");
  o.expression = {f.force.value_or(""), f.unload.value_or(""), f.allow_tension};
  o.expression.functions = oracles::expression_functions();  // as in --expect-cor
  o.integrator = f.integrator;
  o.model = f.model;
  o.rtol = number(f.rtol, "--rtol");
  o.atol = number(f.atol, "--atol");
  o.dt = number(f.dt, "--dt");
  o.model_tolerance = number(f.model_tolerance, "--model-tol");
  if (f.max_steps)
    o.max_steps = parse_count(*f.max_steps, "--max-steps", 1, std::numeric_limits<long>::max());
  o.hc_k = number(f.hc_k, "--hc-k");
  o.hc_mu = number(f.hc_mu, "--hc-mu");
  o.parameters = parse_parameters(f.params);
  return o;
}

}  // namespace ivv::app
