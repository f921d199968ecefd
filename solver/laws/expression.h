// Expression contact law: a force law typed on the command line, parsed by muParser
// (docs/design.md §5).
//
//   loading     F = force (z, zdot, zmax = z)            until dz/dt = 0
//   unloading   F = unload(z, zdot, zmax = z_m)          after it; default: the loading
//                                                        expression with zmax held at z_m
//
// Variables: z [m] spring deformation, zdot [m/s] its rate, zmax [m] the largest z so far.
// Constants of the scene: m [kg] and R [m] (the effective mass and radius: the impactor's
// against a half-space, m1 m2/(m1 + m2) and R1 R2/(R1 + R2) sphere on sphere), E_star [Pa],
// K_h [N/m^1.5], v0 [m/s], and, when the scene has a yield strength, z_y [m], K_y [N/m]. Every
// `--param NAME=VALUE` is a constant too. muParser syntax: + - * / ^, sqrt, exp, log (natural),
// abs, min, max, `a < b ? x : y`.
//
// The force is clamped to F >= 0 by ending contact at F = 0 (paper eq. 3), unless
// `allow_tension`: then F may go negative and contact ends at z = 0 (DEM codes that do not
// clamp). Below z = 0, where a typed law like K_h*z^1.5 is undefined, the force is continued
// linearly, min(F(0, zdot), 0) + k_ref z with k_ref = F_ref/z_ref (the scene's Hertz scales),
// so a step that overshoots separation stays finite and the end of contact is a sign change.
// A force that does not vanish at z = 0 (F(0) > 0, e.g. K_h*z^1.5 + 100): the contact ends at
// z = 0 at the latest, where the surfaces part and the force drops to 0 (the continuation
// starts at 0, not at F(0)). Continuing from F(0) > 0 instead let the force push on below
// z = 0 and a conservative law gained energy (e = 1.0006 for K_h*z^1.5 + 100 on the paper
// scene at 1 m/s, with negative plastic work, at any rtol). The jump at onset is the conformance
// check static.onset's finding (verification/conformance.h); the run itself is well defined.
//
// The law runs in double only (no 50-digit reference). dF/dz and dF/dzdot are central
// differences with step eps^{1/3} of the scale (relative error ~1e-10 where F is smooth); they
// serve implicit integrators and the peak-force event, never a verdict. An expression that
// evaluates to NaN or infinity inside contact is recorded and turns the impact into a failure
// naming the expression, z and zdot.
//
// Not thread-safe: one compiled law per impact (muParser parsers are not thread-safe).
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "scene/input_error.h"
#include "scene/scene.h"
#include "solver/laws/law.h"
#include "solver/laws/law_parameters.h"

namespace ivv {

// A function an expression may call, e.g. a published COR formula (oracles/expression_functions.h
// lists them; the solver defines none itself). One or two arguments; a value outside the
// function's domain evaluates to NaN.
struct ExpressionFunction {
  std::string_view name;                    // e.g. "hc_cor"
  std::string_view signature;               // e.g. "hc_cor(u0)"
  std::string_view meaning;                 // one line: what it computes, its source
  double (*one)(double) = nullptr;          // arity 1, or
  double (*two)(double, double) = nullptr;  // arity 2
};

struct ExpressionLawSpec {
  std::string force;   // loading force [N]; required for LawKind::expression
  std::string unload;  // unloading force [N]; empty: the loading expression, zmax fixed
  bool allow_tension = false;
  // The force the law intends at z = 0 on first loading [N] (an adhesive law's jump-in, e.g.
  // "-Fad"), an expression like --force evaluated at z = 0, zdot = v0, zmax = 0; empty: none
  // declared (the law's F(0) should then be 0). Read by the conformance check static.onset.
  std::string onset_force = {};
  // Functions the expressions may call besides muParser's own (the published COR formulas of
  // oracles/expression_functions.h, which a front end passes; the solver defines none). The
  // span must outlive the compiled law (the front ends pass a static table).
  std::span<const ExpressionFunction> functions = {};
};

// A malformed expression: the message shows the expression with a caret under the column
// at fault (or names the unknown variable). Field "--force" or "--unload"; exit code 2.
class ExpressionError : public InputError {
 public:
  ExpressionError(std::string field, const std::string& expression, int position,
                  const std::string& what);
  int position() const { return position_; }

 private:
  int position_;
};

// The parsed expressions with their variables; evaluation mutates the variable slots.
class CompiledExpressions {
 public:
  // Throws ExpressionError for a syntax error or an unknown name, InputError for a --param
  // that shadows a variable or constant.
  CompiledExpressions(const ExpressionLawSpec& spec, const LawParameters& parameters,
                      const Scene& scene, const DerivedParameters& p);
  ~CompiledExpressions();
  CompiledExpressions(const CompiledExpressions&) = delete;
  CompiledExpressions& operator=(const CompiledExpressions&) = delete;

  double loading(double z, double zdot) const;
  double unloading(double z, double zdot, double zmax) const;
  // The declared onset force (ExpressionLawSpec::onset_force) at z = 0, zdot = v0; nullopt when
  // none was declared.
  std::optional<double> onset_force() const;
  // The pull-off work of the unloading branch from z_max [J], computed by `compute` once per
  // z_max (the last one is kept: one compiled law per impact).
  double pull_off_work(double z_max, const std::function<double()>& compute) const;
  // The largest speed the loading curve's attractive part can give an impactor of mass m [kg]
  // that strikes at v0, in units of v0: sqrt(1 + 2 W/(m v0^2)), W = -int_0^{z0} F_load(s, v0) ds
  // up to the first zero z0 of a loading force that starts below zero (a DMT jump-in: W =
  // (3/5) F_ad z0); 1 where F_load(0) >= 0. The integrators' local error scales with the state,
  // so their stated error of e (in units of v0) grows by this factor (model_choice.h).
  double loading_speed_gain(double mass) const;
  bool uses_rate() const { return uses_rate_; }
  bool has_unloading_expression() const { return has_unload_; }
  double length_scale() const { return z_ref_; }     // z_ref [m]
  double stiffness_scale() const { return k_ref_; }  // k_ref [N/m]
  double velocity_scale() const { return v_ref_; }   // v0 [m/s]
  // The first NaN or infinity met inside contact, if any ("--force = nan at z = ..., ...").
  const std::optional<std::string>& non_finite() const { return non_finite_; }
  // Whether that first non-finite value was at contact onset (z <= 0, zmax = 0), which no
  // impact can avoid, rather than at a state the run reached inside contact.
  bool non_finite_at_onset() const { return non_finite_at_onset_; }

 private:
  double evaluate(bool unload, double z, double zdot, double zmax) const;
  struct Parsers;
  std::unique_ptr<Parsers> parsers_;
  bool uses_rate_ = false;
  bool has_unload_ = false;
  bool has_onset_ = false;
  double z_ref_ = 1.0, k_ref_ = 1.0, v_ref_ = 1.0;
  mutable std::optional<std::string> non_finite_;
  mutable std::optional<std::pair<double, double>> pull_off_;  // (z_max, W) last computed
  mutable bool non_finite_at_onset_ = false;
};

// The law handed to the driver. Rate: whether the expressions use zdot (then the law carries
// its own damping and runs without the series dashpot, like Hunt-Crossley).
template <bool Rate>
struct ExpressionLaw {
  static constexpr std::string_view name = "expression";
  static constexpr bool rate_dependent = Rate;

  std::shared_ptr<const CompiledExpressions> expr;
  bool allows_tension = false;

  double force(const Branch<double>& h, double z, double v) const {
    return h.phase == Phase::loading ? expr->loading(z, v) : expr->unloading(z, v, h.z_max);
  }
  double stiffness(const Branch<double>& h, double z, double v) const {
    const double d = step(expr->length_scale(), z);
    return (force(h, z + d, v) - force(h, z - d, v)) / (2 * d);
  }
  double rate_stiffness(const Branch<double>& h, double z, double v) const {
    if constexpr (!Rate) return 0.0;
    const double d = step(expr->velocity_scale(), v);
    return (force(h, z, v + d) - force(h, z, v - d)) / (2 * d);
  }
  // one loading segment (law.h's default segment_end and next_segment)
  // Records z_m and the permanent set z_f: the zero of the unloading force in [0, z_m] at
  // zdot = 0 (0 when the unloading force is positive down to z = 0).
  void begin_unloading(Branch<double>& h, double z_m) const;
  // int_{z_f}^{z} max(F_unload(s, 0), 0) ds (20-point Gauss-Legendre; loading: from 0).
  double stored_energy(const Branch<double>& h, double z) const;
  std::optional<double> hysteresis_work(const Branch<double>&) const { return std::nullopt; }
  // int_0^z F_unload(s, 0) ds [J] on the unloading branch (law.h: separation_work; read only
  // for a law that allows tension), by 31-point Gauss-Kronrod panels to 1e-12 relative or
  // 1e-13 F_ref z_ref absolute; nullopt on first loading.
  std::optional<double> separation_work(const Branch<double>& h, double z) const;
  // The declared force at z = 0 on first loading (law.h: onset_force), or nullopt.
  std::optional<double> onset_force() const { return expr->onset_force(); }

 private:
  static double step(double scale, double at);
};

// The COR a law claims, as an expression in v0 [m/s], the scene's constants, the law's
// parameters and `functions` (`--expect-cor`). Throws ExpressionError("--expect-cor", ...) when
// malformed. The function is not thread-safe (it owns one parser).
std::function<double(double)> compile_cor_claim(const std::string& text,
                                                const LawParameters& parameters, const Scene& scene,
                                                std::span<const ExpressionFunction> functions = {});

extern template struct ExpressionLaw<false>;
extern template struct ExpressionLaw<true>;

}  // namespace ivv
