// ivv: the command line. A thin layer: everything it prints is computable through the
// libraries (solver, oracles, verification, reports).
//
// Exit codes: 0 success; 1 a computation failed (integrator could not meet its tolerance,
// a verification case failed); 2 bad input (message names the field and accepted range).
#include <signal.h>
#include <unistd.h>
#include <CLI/CLI.hpp>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <iomanip>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>

#include "app/cli_args.h"
#include "app/mpi_sweep.h"
#include "app/progress.h"
#include "app/result_json.h"
#include "app/sweep_sidecar.h"
#include "bench/benchmarks.h"
#include "bench/speed_bench.h"
#include "reports/law_report.h"
#include "reports/report.h"
#include "solver/atomic_file.h"
#include "solver/fit_hunt_crossley.h"
#include "solver/input_error.h"
#include "solver/integrator_accuracy.h"
#include "solver/integrator_choice.h"
#include "solver/model_choice.h"
#include "solver/simulate.h"
#include "solver/sweep.h"
#include "verification/conformance.h"
#include "verification/registry.h"

namespace ivv {
namespace {

constexpr int kExitFailure = 1;
constexpr int kExitBadInput = 2;

// Options shared by simulate and sweep. Numeric values are kept as typed and parsed by
// app/cli_args.h, so that '', '1e3x' or a count out of range is an InputError naming the flag.
struct ModelFlags {
  std::string scene;
  std::optional<std::string> v0;
  std::optional<std::string> zeta;
  std::optional<std::string> c;
  bool no_dashpot = false;
  std::string law = "elastoplastic";
  std::string integrator = "auto";
  std::string model = "auto";
  std::optional<std::string> rtol, atol, dt;
  std::optional<std::string> hc_k;
  std::optional<std::string> hc_mu;
  std::optional<std::string> max_steps;
  std::vector<std::string> params;  // NAME=VALUE
  std::string force, unload;        // expression law
  bool allow_tension = false;
};

std::optional<double> number(const std::optional<std::string>& text, const std::string& field) {
  if (!text) return std::nullopt;
  return parse_number(*text, field);
}

void add_model_flags(CLI::App& cmd, ModelFlags& f, bool with_velocity_and_damping,
                     bool scene_required = true) {
  auto* scene =
      cmd.add_option("--scene", f.scene,
                     "scene file (TOML, SPEC §5), 'paper' (Table 1), or a shipped scene's name");
  if (scene_required) scene->required();
  if (with_velocity_and_damping) {
    cmd.add_option("--v0", f.v0, "impact velocity [m/s] (overrides the scene)");
    auto* z = cmd.add_option("--zeta", f.zeta, "damping ratio of the series dashpot");
    auto* c = cmd.add_option("--c", f.c, "dashpot coefficient [N s/m]");
    auto* n = cmd.add_flag("--no-dashpot", f.no_dashpot, "ignore the scene's dashpot");
    z->excludes(c)->excludes(n);
    c->excludes(n);
  }
  auto* law = cmd.add_option("--law", f.law, "contact law (see `ivv laws`)")->capture_default_str();
  auto* force = cmd.add_option(
      "--force", f.force,
      "expression law: loading force [N] in z, zdot, zmax, m, R, E_star, K_h, z_y, K_y, v0 and "
      "--param names (muParser), e.g. 'K_h*z^1.5'");
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
                 "integrator (see `ivv integrators`), or auto: chosen by stiffness")
      ->capture_default_str();
  cmd.add_option("--model", f.model,
                 "auto: what the scene needs within --rtol (exact closed forms where they exist, "
                 "the linearized closed form where its estimated error is within --rtol, else "
                 "the integrator); full: always integrate the law's ODE model")
      ->capture_default_str();
  cmd.add_option("--rtol", f.rtol, "relative tolerance, adaptive integrators (default 1e-10)");
  cmd.add_option("--atol", f.atol, "absolute tolerance, normalised units (default 1e-12)");
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

SimulationRequest build_request(const ModelFlags& flags) {
  struct {
    std::optional<double> v0, zeta, c, rtol, atol, dt, hc_k, hc_mu;
    bool no_dashpot;
  } f = {number(flags.v0, "--v0"),     number(flags.zeta, "--zeta"),   number(flags.c, "--c"),
         number(flags.rtol, "--rtol"), number(flags.atol, "--atol"),   number(flags.dt, "--dt"),
         number(flags.hc_k, "--hc-k"), number(flags.hc_mu, "--hc-mu"), flags.no_dashpot};
  SimulationRequest req;
  req.scene = load_scene(flags.scene);
  if (f.v0) {
    if (!(std::isfinite(*f.v0) && *f.v0 > 0))
      throw InputError("--v0", "must be a finite number > 0 m/s");
    req.scene.velocity = *f.v0;
  }
  if (f.zeta) {
    if (!(std::isfinite(*f.zeta) && *f.zeta > 0))
      throw InputError("--zeta", "must be a finite number > 0 (use --no-dashpot for none)");
    req.scene.damping = Damping::ratio(*f.zeta);
  }
  if (f.c) {
    if (!(std::isfinite(*f.c) && *f.c > 0))
      throw InputError("--c", "must be a finite number > 0 N s/m (use --no-dashpot for none)");
    req.scene.damping = Damping::coefficient(*f.c);
  }
  if (f.no_dashpot) req.scene.damping = Damping::none();
  if (!flags.force.empty()) {
    req.law = LawKind::expression;
    req.expression = {flags.force, flags.unload, flags.allow_tension};
  } else {
    req.law = parse_law(flags.law);
  }
  // auto: chosen below, once the scene, law and tolerances are known (and per point of a sweep)
  req.auto_integrator = flags.integrator == "auto";
  req.integrator =
      req.auto_integrator ? IntegratorKind::dop853 : parse_integrator(flags.integrator);
  req.model = parse_model(flags.model);
  req.parameters = parse_parameters(flags.params);
  if (f.hc_k || f.hc_mu) {
    const char* flag = f.hc_k ? "--hc-k" : "--hc-mu";
    if (req.law != LawKind::hunt_crossley)
      throw InputError(flag, "only the hunt-crossley law has K and mu (--law hunt-crossley)");
    if (f.hc_k && !(std::isfinite(*f.hc_k) && *f.hc_k > 0))
      throw InputError("--hc-k", "must be a finite number > 0 N/m^1.5");
    if (f.hc_mu && !(std::isfinite(*f.hc_mu) && *f.hc_mu >= 0))
      throw InputError("--hc-mu", "must be a finite number >= 0 s/m");
    if (f.hc_k) req.parameters["K"] = *f.hc_k;
    if (f.hc_mu) req.parameters["mu"] = *f.hc_mu;
  }
  if (f.rtol) req.options.rtol = *f.rtol;
  if (f.atol) req.options.atol = *f.atol;
  if (f.dt) {
    if (!(*f.dt > 0)) throw InputError("--dt", "must be > 0 (normalised time)");
    req.options.dt = *f.dt;
  }
  if (flags.max_steps)
    req.options.max_steps =
        parse_count(*flags.max_steps, "--max-steps", 1, std::numeric_limits<long>::max());
  try {
    validate(req);
  } catch (const InputError& e) {
    // a scene value the user overrode on the command line is named by its flag
    const std::string prefix = e.field() + ": ";
    const std::string message = std::string(e.what()).substr(prefix.size());
    if (e.field() == "impact.velocity" && f.v0) throw InputError("--v0", message);
    if (e.field() == "damping.zeta" && f.zeta) throw InputError("--zeta", message);
    if (e.field() == "damping.c" && f.c) throw InputError("--c", message);
    throw;
  }
  if (req.auto_integrator) req.integrator = choose_integrator(req).integrator;
  return req;
}

void print_summary(std::ostream& out, const SimulationRequest& req, const ImpactResult& r) {
  const DerivedParameters p = derive(req.scene);
  out << std::setprecision(6);
  out << "scene " << req.scene.name << ", law " << to_string(req.law) << ", integrator "
      << to_string(req.integrator) << "\n";
  out << "  v0 = " << req.scene.velocity << " m/s";
  if (p.has_yield()) out << " (v_y = " << p.v_yield << " m/s)";
  out << ", ";
  if (p.has_dashpot() && p.has_yield())
    out << "zeta = " << p.zeta << " (c = " << p.c << " N s/m)\n";
  else if (p.has_dashpot())
    out << "c = " << p.c << " N s/m\n";
  else
    out << "no dashpot\n";
  out << "  status       " << to_string(r.status);
  if (!r.reason.empty()) out << ": " << r.reason;
  out << "\n";
  if (!r.ok()) return;
  out << std::setprecision(8);
  out << "  COR          e = " << r.e;
  if (r.status == ImpactStatus::captured) out << " (captured: e <= " << r.e_bound << ")";
  out << "  (Poisson " << r.e_poisson << ", energetic " << r.e_energetic << ")\n";
  out << std::setprecision(6);
  out << "  peak force   F_max = " << r.F_max << " N at t = " << r.t_F_max * 1e3 << " ms\n";
  out << "  contact      t_contact = " << r.t_contact * 1e3 << " ms\n";
  out << "  deformation  z_max = " << r.z_max * 1e3 << " mm, alpha_max = " << r.alpha_max * 1e3
      << " mm, z_perm = " << r.z_perm * 1e3 << " mm\n";
  out << "  energy [J]   initial " << r.energy.initial << " = final " << r.energy.final
      << " + plastic " << r.energy.plastic << " + viscous " << r.energy.viscous;
  if (r.energy.stored > 0) out << " + stored " << r.energy.stored;
  out << " + residual " << r.energy.residual << "\n";
  out << "  impulse      " << r.impulse
      << " N s (m* v0 (1 + e) = " << p.effective_mass * req.scene.velocity * (1 + r.e) << ")\n";
  if (req.scene.free_target()) {
    out << "  after impact impactor " << r.impactor_velocity_after << " m/s, target "
        << r.target_velocity_after << " m/s (frame: target at rest before; + towards it)\n";
  }
  out << "  work         " << r.steps << " steps, " << r.rhs_evaluations << " RHS evaluations\n";
}

int run_simulate(const ModelFlags& f, bool json,
                 const std::optional<std::string>& trajectory_flag) {
  const SimulationRequest req = build_request(f);
  // given but empty is an error (resolve_output_path says so), not "no trajectory"
  if (trajectory_flag) resolve_output_path(*trajectory_flag, "--trajectory");
  const std::string trajectory_path = trajectory_flag.value_or("");
  std::vector<TrajectoryPoint> trajectory;
  std::vector<TrajectoryPoint>* wanted = trajectory_path.empty() ? nullptr : &trajectory;
  std::optional<ModelChoice> model_choice;
  ImpactResult r;
  if (req.model == ModelKind::automatic) {
    ModelRun run = simulate_model(ValidatedRequest(req), wanted);
    r = std::move(run.result);
    model_choice = std::move(run.choice);
  } else {
    r = simulate(req, wanted);
  }
  if (r.failure == FailureKind::law_domain) throw InputError("--law", r.reason);
  if (!trajectory_path.empty() && r.ok()) {
    write_file_atomically(
        trajectory_path,
        [&](std::ostream& out) {
          out << "t,alpha,alpha_dot,y,z,F,tau,alpha_bar,F_bar\n" << std::setprecision(12);
          for (const auto& p : trajectory)
            out << p.t << ',' << p.alpha << ',' << p.alpha_dot << ',' << p.y << ',' << p.z << ','
                << p.force << ',' << p.tau << ',' << p.alpha_bar << ',' << p.force_bar << '\n';
        },
        "--trajectory");
  }
  if (json) {
    nlohmann::json j = simulation_json(req, r);
    if (model_choice) {
      j["model_choice"] = {{"model", "auto"},
                           {"route", to_string(model_choice->decision.route)},
                           {"law", model_choice->law},
                           {"integrator", model_choice->integrator},
                           {"reasons", model_choice->reasons},
                           {"estimated_error", model_choice->estimated_error}};
    } else if (req.auto_integrator) {
      const IntegratorChoice c = choose_integrator(req);
      j["model_choice"] = {{"model", "full"},
                           {"route", to_string(ModelRoute::integrated)},
                           {"law", std::string(to_string(req.law)) + " (full model, integrated)"},
                           {"integrator", std::string(to_string(c.integrator))},
                           {"reasons", c.reasons},
                           {"estimated_error", c.estimated_error}};
    }
    std::cout << j.dump(2) << std::endl;
  } else {
    print_summary(std::cout, req, r);
    if (model_choice) {
      std::cout << "  model        " << model_choice->law << " (integrator "
                << model_choice->integrator << ", estimated error " << model_choice->estimated_error
                << "; --model full to integrate always)\n";
    }
  }
  if (!r.ok()) {
    if (json) std::cerr << "ivv simulate: " << r.reason << "\n";
    return kExitFailure;
  }
  return 0;
}

// SIGINT/SIGTERM during a sweep: stop handing out work, finish the points in flight, keep the
// journal. A second signal ends the process at once (SA_RESETHAND); the journal survives it.
std::atomic<bool> g_sweep_stop{false};
std::atomic<int> g_sweep_signal{0};
extern "C" void on_sweep_signal(int sig) {
  g_sweep_signal = sig;
  g_sweep_stop = true;
}
void install_sweep_signal_handlers() {
  struct sigaction sa {};
  sa.sa_handler = on_sweep_signal;
  sa.sa_flags = SA_RESETHAND;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
}

struct SweepFlags {
  std::string v0_grid, zeta_grid, out_path;
  bool log = false;
  bool resume = false;
  bool quiet = false;
  int threads = 0;
};

int run_sweep_command(const ModelFlags& f, const SweepFlags& sf, const std::string& command) {
  SweepRequest req;
  ModelFlags base = f;
  req.base = build_request(base);
  req.velocities = parse_grid(sf.v0_grid, "--v0", sf.log);
  req.zetas = parse_grid(sf.zeta_grid, "--zeta", false);
  if (sf.threads < 0) throw InputError("--threads", "must be >= 0 (0: all cores)");
  req.threads = sf.threads;
  resolve_output_path(sf.out_path, "--out");  // a bad output path fails before the sweep runs
  validate(req);  // the one validation of a sweep, before any file is touched

  const nlohmann::json inputs = sweep_inputs_json(req, {sf.v0_grid, sf.log}, {sf.zeta_grid, false});
  install_sweep_signal_handlers();
  std::optional<mpi::World> world;
  if (mpi::launched_by_mpirun()) world.emplace();
  const bool writer = !world || world->rank() == 0;

  std::unique_ptr<SweepSink> sink;
  int start_code = 0;
  std::string start_error;
  if (writer) {
    try {
      sink = std::make_unique<SweepSink>(req,
                                         SweepOutputOptions{sf.out_path, sf.resume, inputs.dump()});
    } catch (const InputError& e) {
      start_code = kExitBadInput;
      start_error = e.what();
    } catch (const std::exception& e) {
      start_code = kExitFailure;
      start_error = e.what();
    }
  }
  if (world) start_code = world->agree_on_start(start_code);
  if (start_code != 0) {
    if (writer) std::cerr << "ivv: error: " << start_error << "\n";
    return start_code;
  }
  if (writer && sink->resumed() > 0)
    std::cerr << "ivv sweep: resuming: " << sink->resumed() << " of " << sink->total()
              << " points read back from " << sink->journal_path().string() << "\n";

  ProgressLine progress("ivv sweep", writer ? sink->resumed() : 0);
  SweepRunOptions run;
  run.stop = &g_sweep_stop;
  if (writer && !sf.quiet)
    run.progress = [&](std::size_t d, std::size_t t) { progress.update(d, t); };
  if (world) {
    const auto per_rank = mpi::run_sweep_ranks(*world, req, sink.get(), run);
    if (writer) {
      progress.finish();
      std::cerr << "ivv sweep: " << world->size() << " MPI ranks computed";
      for (std::size_t r = 0; r < per_rank.size(); ++r)
        std::cerr << (r ? ", " : " ") << per_rank[r];
      std::cerr << " points\n";
    }
    if (!writer) return 0;
  } else {
    run_sweep_points(req, *sink, run);
  }
  progress.finish();

  const bool complete = sink->finish([&](const SweepCounts& counts) {
    const nlohmann::json sidecar = sweep_sidecar_json(inputs, counts, sf.out_path, command);
    write_file_atomically(sidecar_path(sf.out_path),
                          [&](std::ostream& out) { out << sidecar.dump(2) << "\n"; });
  });
  if (!complete) {
    std::cerr << "ivv sweep: interrupted: " << sink->done() << " of " << sink->total()
              << " points done and kept in " << sink->journal_path().string()
              << ". Resume with:\n  "
              << (world ? "mpirun -np " + std::to_string(world->size()) + " ... " : "") << command
              << (command.find(" --resume") == std::string::npos ? " --resume" : "") << "\n";
    const int sig = g_sweep_signal.load();
    return 128 + (sig ? sig : SIGINT);
  }
  const SweepCounts& c = sink->counts();
  std::cerr << "ivv sweep: wrote " << sink->total() << " impacts to " << sf.out_path << " and "
            << sidecar_path(sf.out_path).string() << " (" << c.separated << " separated, "
            << c.captured << " captured, " << c.failed << " failed";
  if (c.failed) std::cerr << ": see the reason column";
  std::cerr << ")\n";
  return c.failed ? kExitFailure : 0;
}

int run_scene_show(const std::string& scene_name, bool json) {
  const Scene s = load_scene(scene_name);
  const DerivedParameters p = derive(s);
  if (json) {
    std::cout << scene_json(s, p).dump(2) << std::endl;
    return 0;
  }
  std::cout << std::setprecision(6) << "scene " << s.name << "\n"
            << "  impactor  m = " << s.mass << " kg, R = " << s.radius
            << " m, E1 = " << s.impactor_youngs_modulus << " Pa, nu1 = " << s.impactor_poisson_ratio
            << "\n";
  std::cout << "  target    ";
  if (s.free_target())
    std::cout << "free sphere m2 = " << *s.target_mass << " kg, R2 = " << *s.target_radius
              << " m, ";
  else
    std::cout << "half-space, ";
  if (s.rigid_target())
    std::cout << "rigid target (E2 = inf)";
  else
    std::cout << "E2 = " << s.target_youngs_modulus << " Pa, nu2 = " << s.target_poisson_ratio;
  if (s.yield_strength)
    std::cout << ", S_y = " << *s.yield_strength << " Pa\n";
  else
    std::cout << ", no yield strength (laws without yield only: hertz, hunt-crossley)\n";
  std::cout << "  impact    v0 = " << s.velocity << " m/s"
            << (s.free_target() ? " (relative approach speed)" : "") << "\n"
            << "derived\n"
            << "  R*     = " << p.effective_radius << " m\n"
            << "  m*     = " << p.effective_mass << " kg\n"
            << "  E*     = " << p.E_star << " Pa" << (s.rigid_target() ? " (rigid target)" : "")
            << "\n"
            << "  K_h    = " << p.K_h << " N/m^1.5\n";
  if (p.has_yield()) {
    std::cout << "  z_y    = " << p.z_y << " m\n"
              << "  K_y    = " << p.K_y << " N/m\n"
              << "  omega0 = " << p.omega0 << " rad/s\n"
              << "  v_y    = " << p.v_yield << " m/s\n";
  }
  if (p.has_dashpot() && p.has_yield())
    std::cout << "  zeta   = " << p.zeta << ", c = " << p.c << " N s/m\n";
  else if (p.has_dashpot())
    std::cout << "  c      = " << p.c << " N s/m\n";
  else
    std::cout << "  no dashpot (c = inf, zeta = 0)\n";
  return 0;
}

int run_fit_hc(const ModelFlags& f, bool json) {
  const SimulationRequest req = build_request(f);
  const HuntCrossleyFit fit = fit_hunt_crossley(req);
  if (json) {
    std::cout << nlohmann::json{{"K", fit.K},
                                {"mu", fit.mu},
                                {"e", fit.e},
                                {"F_max", fit.F_max},
                                {"t_contact_hc", fit.t_contact_hc},
                                {"t_contact_model", fit.t_contact_model},
                                {"e_hc", fit.hc.e},
                                {"F_max_hc", fit.hc.F_max},
                                {"hc_runs", fit.evaluations}}
                     .dump(2)
              << std::endl;
    return 0;
  }
  std::cout << std::setprecision(8) << "Hunt-Crossley fitted to the " << to_string(req.law)
            << " model at v0 = " << req.scene.velocity << " m/s\n"
            << "  K  = " << fit.K << " N/m^1.5\n"
            << "  mu = " << fit.mu << " s/m   (mu v0 = " << fit.mu * req.scene.velocity << ")\n"
            << "  targets   e = " << fit.e << ", F_max = " << fit.F_max << " N\n"
            << "  HC gives  e = " << fit.hc.e << ", F_max = " << fit.hc.F_max << " N\n"
            << "  contact time: model " << fit.t_contact_model * 1e3 << " ms, Hunt-Crossley "
            << fit.t_contact_hc * 1e3 << " ms\n";
  return 0;
}

struct CheckLawFlags {
  std::string expect_cor;
  std::optional<double> cor_tolerance;
  bool elastic_at_low_speed = false;
  bool no_monotone = false;
  std::string v0_grid, zeta_grid;
  bool json = false;
  std::string report_dir;
};

int run_check_law(ModelFlags f, const CheckLawFlags& c, const std::string& command_line) {
  if (f.scene.empty()) f.scene = "paper";
  if (f.force.empty() && f.law == "elastoplastic" && f.params.empty() && !f.hc_k && !f.hc_mu)
    throw InputError("--force", "give the law to check: --force EXPR (or --law NAME)");
  const SimulationRequest req = build_request(f);
  conformance::Grid grid = conformance::default_grid(req.scene);
  grid.options = req.options;
  if (!c.v0_grid.empty()) grid.velocities = parse_grid(c.v0_grid, "--v0", false);
  for (double v : grid.velocities)
    if (!(v > 0)) throw InputError("--v0", "velocities must be > 0 m/s");
  if (!c.zeta_grid.empty()) grid.zetas = parse_grid(c.zeta_grid, "--zeta", false);
  for (double z : grid.zetas)
    if (!(z >= 0)) throw InputError("--zeta", "damping ratios must be >= 0 (0: no dashpot)");
  conformance::Claims claims;
  claims.elastic_at_low_speed = c.elastic_at_low_speed;
  claims.cor_nonincreasing_in_v0 = claims.cor_nonincreasing_in_damping = !c.no_monotone;
  if (!c.expect_cor.empty()) {
    claims.expected_cor = compile_cor_claim(c.expect_cor, req.parameters, req.scene);
    claims.expected_cor_text = c.expect_cor;
  }
  if (c.cor_tolerance) {
    if (!(*c.cor_tolerance > 0 && *c.cor_tolerance < 1))
      throw InputError("--cor-tolerance", "must lie in (0, 1)");
    claims.cor_tolerance = *c.cor_tolerance;
    claims.cor_tolerance_reason = "given on the command line (--cor-tolerance)";
  }
  if (!c.report_dir.empty()) reports::check_report_dir(c.report_dir);
  const conformance::Report report =
      conformance::run_conformance(conformance::registry_law(req), claims, grid);
  if (!c.report_dir.empty()) {
    const auto index = reports::write_law_report(report, c.report_dir, command_line);
    std::cerr << "ivv check-law: wrote " << index.string() << "\n";
  }
  if (c.json) {
    nlohmann::json j = conformance::to_json(report);
    j["law"]["parameters"] = req.parameters;
    if (req.law == LawKind::expression) {
      j["law"]["force"] = req.expression.force;
      j["law"]["unload"] = req.expression.unload;
      j["law"]["allow_tension"] = req.expression.allow_tension;
    }
    j["law"]["scene"] = req.scene.name;
    if (claims.expected_cor) j["law"]["expect_cor"] = c.expect_cor;
    std::cout << j.dump(2) << std::endl;
  } else {
    std::cout << report.full();
  }
  return report.passed() ? 0 : kExitFailure;
}

int run_verify(const std::string& filter, const std::string& out_path, int threads, bool list) {
  using namespace verification;
  const auto cases = all_cases().matching(filter);
  if (cases.empty()) throw InputError("--filter", "no verification case matches '" + filter + "'");
  if (list) {
    for (const Case* c : cases)
      std::cout << c->id << "\t" << to_string(c->tier) << (c->slow ? "\tslow" : "") << "\t"
                << c->title << "\n";
    return 0;
  }
  if (out_path.empty()) throw InputError("--out", "required (the results JSON file)");
  if (threads < 0) throw InputError("--threads", "must be >= 0 (0: all cores)");
  resolve_output_path(out_path, "--out", true);
  const bool tty = isatty(fileno(stderr));
  const auto records =
      run_cases(cases, threads, [tty](std::size_t done, std::size_t total, const Case& c) {
        if (tty) {
          std::fprintf(stderr, "\r[%zu/%zu] %-70.70s", done, total, c.id.c_str());
          if (done == total) std::fprintf(stderr, "\n");
        } else if (done == total || done % std::max<std::size_t>(1, total / 10) == 0) {
          std::fprintf(stderr, "verify: %zu/%zu cases run\n", done, total);
        }
        std::fflush(stderr);
      });
  nlohmann::json out = {{"cases", nlohmann::json::array()}};
  std::size_t failed = 0;
  for (const CaseRecord& r : records) {
    const Outcome& o = r.outcome;
    if (!o.passed) {
      ++failed;
      std::cerr << "FAILED " << r.c->id << ": " << o.detail << "\n";
    }
    out["cases"].push_back({{"id", r.c->id},
                            {"title", r.c->title},
                            {"tier", to_string(r.c->tier)},
                            {"passed", o.passed},
                            {"measured", o.measured},
                            {"reference", o.reference},
                            {"tolerance", o.tolerance},
                            {"comparison", to_string(o.comparison)},
                            {"margin", std::isfinite(o.margin()) ? nlohmann::json(o.margin())
                                                                 : nlohmann::json(nullptr)},
                            {"reason", r.c->reason},
                            {"detail", o.detail},
                            {"slow", r.c->slow},
                            {"seconds", r.seconds}});
  }
  write_file_atomically(
      out_path, [&](std::ostream& os) { os << out.dump(2) << "\n"; }, "--out", true);
  (out_path == "-" ? std::cerr : std::cout)
      << "verify: " << records.size() - failed << " passed, " << failed << " failed\n";
  return failed ? kExitFailure : 0;
}

int run_report(const reports::ReportOptions& base, bool quiet) {
  reports::ReportOptions opt = base;
  if (opt.out_dir.empty()) throw InputError("--out", "required (the report directory)");
  if (opt.threads < 0) throw InputError("--threads", "must be >= 0 (0: all cores)");
  if (!quiet) {
    opt.progress = [](const std::string& line) { std::cerr << "ivv report: " << line << "\n"; };
  }
  const reports::ReportSummary s = reports::write_report(opt);
  std::cout << "report: " << s.passed << " passed, " << s.failed << " failed (" << s.plots
            << " plots";
  if (s.plot_errors) std::cout << ", " << s.plot_errors << " could not be drawn";
  if (s.section_errors) std::cout << ", " << s.section_errors << " sections failed";
  std::cout << ") in " << std::setprecision(3) << s.seconds << " s\n"
            << s.index_html.string() << "\n";
  const bool bad = s.failed > 0 || s.section_errors > 0 || s.plot_errors > 0;
  if (bad && !opt.allow_failures) {
    std::cerr << "ivv report: verification failed (the report was still written); "
                 "--allow-failures to exit 0\n";
    return kExitFailure;
  }
  return 0;
}

}  // namespace
}  // namespace ivv

int main(int argc, char** argv) {
  using namespace ivv;
  CLI::App app{
      "ivv - verification and validation of impact contact models.\n"
      "A sphere strikes a half-space through a nonlinear elastoplastic contact spring in\n"
      "series with a dashpot. Start with:\n"
      "  ivv simulate --scene paper --v0 1 --c 11440\n"
      "  ivv scene show --scene paper\n"
      "  ivv integrators"};
  app.require_subcommand(1);
  app.set_help_all_flag("--help-all", "help for every subcommand");

  ModelFlags sim_flags;
  bool json = false;
  std::optional<std::string> trajectory;
  auto* sim =
      app.add_subcommand("simulate", "run one impact and print COR, peak force, contact time");
  add_model_flags(*sim, sim_flags, true);
  sim->add_flag("--json", json, "print one JSON object on stdout instead of the summary");
  sim->add_option("--trajectory", trajectory,
                  "write t, alpha, alpha_dot, y, z, F, tau, alpha_bar, F_bar to this CSV");

  ModelFlags sweep_flags;
  SweepFlags sf;
  auto* sweep = app.add_subcommand(
      "sweep",
      "COR and peak force over a v0 x zeta grid, to CSV (+ a JSON sidecar); runs across MPI "
      "ranks under mpirun");
  add_model_flags(*sweep, sweep_flags, false);
  sweep->add_option("--v0", sf.v0_grid, "velocities [m/s]: LO:HI:N or a,b,c")->required();
  sweep->add_flag("--log", sf.log, "logarithmic spacing of the LO:HI:N velocity grid");
  sweep->add_option("--zeta", sf.zeta_grid, "damping ratios: LO:HI:N or a,b,c (0 = no dashpot)")
      ->required();
  sweep->add_option("--out", sf.out_path, "output CSV (the sidecar goes beside it: NAME.json)")
      ->required();
  sweep->add_option("--threads", sf.threads, "worker threads per process (0 = all cores)")
      ->capture_default_str();
  sweep->add_flag("--resume", sf.resume,
                  "continue an interrupted sweep from its journal (OUT.journal)");
  sweep->add_flag("-q,--quiet", sf.quiet, "no progress on stderr");

  auto* scene_cmd = app.add_subcommand("scene", "scene utilities");
  scene_cmd->require_subcommand(1);
  std::string show_scene;
  bool show_json = false;
  auto* show = scene_cmd->add_subcommand("show", "print a scene and its derived parameters");
  show->add_option("--scene", show_scene, "scene file or 'paper'")->required();
  show->add_flag("--json", show_json, "JSON output");

  auto* integrators = app.add_subcommand("integrators", "list the integrators, one per line");
  bool verbose = false;
  integrators->add_flag("-v,--verbose", verbose, "add a description to each");
  auto* laws = app.add_subcommand("laws", "list the contact laws, one per line");
  bool laws_verbose = false;
  laws->add_flag("-v,--verbose", laws_verbose, "add each law's equation and parameters");

  ModelFlags fit_flags;
  bool fit_json = false;
  auto* fit = app.add_subcommand(
      "fit-hc", "Hunt-Crossley K and mu reproducing a model's F_max and e (as the paper did)");
  add_model_flags(*fit, fit_flags, true);
  fit->add_flag("--json", fit_json, "JSON {K, mu, e, F_max, t_contact_hc, t_contact_model}");

  std::string verify_filter, verify_out;
  int verify_threads = 0;
  bool verify_list = false;
  auto* verify = app.add_subcommand("verify", "run the verification cases, write results JSON");
  verify->add_option("--filter", verify_filter, "only cases whose id matches this glob");
  verify->add_option("--out", verify_out, "results JSON file");
  verify->add_option("--threads", verify_threads, "worker threads (0 = all cores)");
  verify->add_flag("--list", verify_list, "list the matching cases instead of running them");

  reports::ReportOptions report_opt;
  bool report_quiet = false;
  auto* report = app.add_subcommand(
      "report", "run every verification case and write DIR/index.html (+ JSON, CSV, JUnit)");
  report->add_option("--out", report_opt.out_dir, "report directory (created if missing)")
      ->required();
  report->add_option("--filter", report_opt.filter, "only cases whose id matches this glob");
  report->add_option("--threads", report_opt.threads, "worker threads (0 = all cores)");
  report->add_flag("--allow-failures", report_opt.allow_failures,
                   "exit 0 even when a case fails (the report shows it)");
  report->add_flag("--quick", report_opt.quick, "fewer sweep and timing points (smoke runs)");
  report->add_flag("-q,--quiet", report_quiet, "no progress lines on stderr");

  ModelFlags check_flags;
  CheckLawFlags check;
  auto* check_law = app.add_subcommand(
      "check-law",
      "put a contact law (--force EXPR, or --law NAME) through the conformance checks");
  add_model_flags(*check_law, check_flags, false, false);
  check_law->add_option("--expect-cor", check.expect_cor,
                        "the COR the law is meant to deliver: an expression in v0, the scene's "
                        "constants and --param names");
  check_law->add_option("--cor-tolerance", check.cor_tolerance,
                        "allowed |e - expected| (default 1e-9: 10x the reference's error of e)");
  check_law->add_flag("--elastic-at-low-speed", check.elastic_at_low_speed,
                      "claim e -> 1 as v0 -> 0 (checked)");
  check_law->add_flag("--no-monotone", check.no_monotone,
                      "do not claim that e falls with v0 and with damping");
  check_law->add_option("--v0", check.v0_grid,
                        "velocity grid [m/s], LO:HI:N or a,b,c (default: 7 points over three "
                        "decades around the scene's v0)");
  check_law->add_option("--zeta", check.zeta_grid,
                        "damping ratios of the series dashpot (default 0,0.1; rate-dependent "
                        "laws: 0 only)");
  check_law->add_flag("--json", check.json, "print the verdict and every check as JSON");
  check_law->add_option("--report", check.report_dir, "write DIR/index.html for this law");

  auto* bench =
      app.add_subcommand("bench",
                         "speed against error, peers and targets: ivv bench [--json] [--quick]; "
                         "Google Benchmark timings: ivv bench --gbench [--benchmark_*]");
  bench->allow_extras();
  bench->prefix_command();

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "ivv: " << e.what() << "\n(run with --help for usage)\n";
    return 2;
  }

  try {
    if (*sim) return run_simulate(sim_flags, json, trajectory);
    if (*sweep) {
      std::string command;
      for (int i = 0; i < argc; ++i) command += (i ? " " : "") + std::string(argv[i]);
      return run_sweep_command(sweep_flags, sf, command);
    }
    if (*show) return run_scene_show(show_scene, show_json);
    if (*integrators) {
      for (const IntegratorTraits& t : integrator_table()) {
        std::cout << t.name;
        if (verbose)
          std::cout << "\torder " << t.order << (t.implicit ? ", implicit" : ", explicit")
                    << (t.dense_output ? ", dense output" : ", Hermite interpolant")
                    << (t.fixed_step ? ", fixed step" : ", adaptive")
                    << (t.reference ? ", reference" : "") << "\t" << t.description
                    << "\n\t  accuracy: " << accuracy_statement(t.kind);
        std::cout << "\n";
      }
      return 0;
    }
    if (*fit) return run_fit_hc(fit_flags, fit_json);
    if (*check_law) {
      std::string command_line;
      for (int i = 0; i < argc; ++i) command_line += (i ? " " : "") + std::string(argv[i]);
      return run_check_law(check_flags, check, command_line);
    }
    if (*report) {
      for (int i = 0; i < argc; ++i)
        report_opt.command_line += (i ? " " : "") + std::string(argv[i]);
      return run_report(report_opt, report_quiet);
    }
    if (*verify) return run_verify(verify_filter, verify_out, verify_threads, verify_list);
    if (*bench) {
      std::vector<std::string> extras = bench->remaining();
      bool gbench = false, bench_json = false, bench_quick = false;
      for (const auto& e : extras) {
        gbench = gbench || e == "--gbench" || e.rfind("--benchmark_", 0) == 0;
        bench_json = bench_json || e == "--json";
        bench_quick = bench_quick || e == "--quick";
      }
      if (gbench) {
        std::vector<char*> args{argv[0]};
        for (auto& e : extras)
          if (e != "--gbench") args.push_back(e.data());
        int n = static_cast<int>(args.size());
        return bench::run_benchmarks(n, args.data());
      }
      for (const auto& e : extras)
        if (e != "--json" && e != "--quick")
          throw InputError(e,
                           "unknown flag; ivv bench takes --json, --quick, or --gbench "
                           "[--benchmark_*]");
      const bench::BenchReport rep = bench::run_bench(
          {bench_quick}, [](const std::string& line) { std::cerr << line << "\n"; });
      std::cout << (bench_json ? bench::to_json(rep) + "\n" : bench::to_text(rep));
      return 0;
    }
    if (*laws) {
      for (const LawInfo& l : all_law_info()) {
        std::cout << l.name;
        if (laws_verbose) {
          std::cout << "\t" << l.summary;
          for (const ParameterSpec& ps : l.parameters)
            std::cout << "\n\t--param " << ps.name << " [" << ps.unit << "]: " << ps.meaning;
        }
        std::cout << "\n";
      }
      return 0;
    }
  } catch (const InputError& e) {
    std::cerr << "ivv: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "ivv: failed: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
