#include "solver/laws/expression.h"

#include <muParser.h>

#include <algorithm>
#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cctype>
#include <cmath>
#include <functional>
#include <limits>
#include <set>
#include <sstream>

namespace ivv {
namespace {

std::string caret_message(const std::string& expression, int position, const std::string& what) {
  std::ostringstream os;
  os << what << "\n    " << expression << "\n    ";
  if (position >= 0) os << std::string(static_cast<std::size_t>(position), ' ') << '^';
  return os.str();
}

// Position of identifier `name` as a whole token in `text`, or -1.
int token_position(const std::string& text, const std::string& name) {
  auto is_ident = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  for (std::size_t at = text.find(name); at != std::string::npos; at = text.find(name, at + 1)) {
    const bool starts = at == 0 || !is_ident(text[at - 1]);
    const bool ends = at + name.size() >= text.size() || !is_ident(text[at + name.size()]);
    if (starts && ends) return static_cast<int>(at);
  }
  return -1;
}

// Position of the first ',' outside parentheses in `text`, or -1.
int top_level_comma(const std::string& text) {
  int depth = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '(') ++depth;
    if (text[i] == ')') --depth;
    if (text[i] == ',' && depth <= 0) return static_cast<int>(i);
  }
  return -1;
}

// The names muParser itself defines (constants _pi, _e and the built-in functions): a --param
// of that name would silently redefine them (--param _pi=1 did).
const std::set<std::string>& builtin_names() {
  static const std::set<std::string> names = [] {
    mu::Parser parser;
    std::set<std::string> out;
    for (const auto& [name, value] : parser.GetConst()) out.insert(name);
    for (const auto& [name, callback] : parser.GetFunDef()) out.insert(name);
    return out;
  }();
  return names;
}

// Thrown by the variable factory, which muParser calls for a name it does not know.
struct UnknownName {
  std::string name;
};
double* reject_unknown_name(const char* name, void*) {
  throw UnknownName{name};
}

using Constants = std::vector<std::pair<std::string, double>>;

// Defines variables and constants, parses `text` and evaluates it once (syntax errors and
// unknown names surface here, not mid-run). Returns whether `rate_variable` is used.
bool setup_parser(mu::Parser& parser, const std::string& text, const std::string& field,
                  const std::vector<std::pair<std::string, double*>>& variables,
                  const Constants& constants, const std::string& known,
                  const std::string& rate_variable) {
  try {
    for (const auto& [name, slot] : variables) parser.DefineVar(name, slot);
    for (const auto& [name, value] : constants) parser.DefineConst(name, value);
    parser.SetVarFactory(reject_unknown_name, nullptr);
    parser.SetExpr(text);
    parser.Eval();
  } catch (const UnknownName& u) {
    const bool number = std::isdigit(static_cast<unsigned char>(u.name[0])) || u.name[0] == '.';
    if (number)  // muParser hands a number it cannot represent (1e400) to the variable factory
      throw ExpressionError(field, text, token_position(text, u.name),
                            "the number '" + u.name +
                                "' is outside the range of double (magnitudes 2.2e-308 to "
                                "1.8e308)");
    throw ExpressionError(field, text, token_position(text, u.name),
                          "unknown variable '" + u.name + "' (known: " + known + ")");
  } catch (const mu::Parser::exception_type& e) {
    const std::string what = e.GetMsg();
    throw ExpressionError(field, text, e.GetPos(),
                          what.find("Internal error") != std::string::npos
                              ? "syntax error at the caret (muParser gives up with '" + what +
                                    "'; e.g. an operator without its operand, as in 'z++')"
                              : what);
  }
  if (parser.GetNumResults() > 1) {
    // muParser's comma operator: "K_h*z^1,5" is two expressions and only the last, 5, counts
    throw ExpressionError(field, text, top_level_comma(text),
                          "',' outside a function's arguments separates expressions, and only "
                          "the last would count; write decimals with '.', e.g. z^1.5");
  }
  return parser.GetUsedVar().count(rate_variable) > 0;
}

// The scene's constants (z_y, K_y only where the scene defines them) and the parameters,
// checked against the reserved names.
Constants scene_constants(const Scene& scene, const DerivedParameters& p,
                          const LawParameters& parameters, const std::set<std::string>& reserved) {
  Constants constants = {{"m", p.effective_mass},
                         {"R", p.effective_radius},
                         {"E_star", p.E_star},
                         {"K_h", p.K_h},
                         {"v0", scene.velocity}};
  if (p.has_yield()) {
    constants.push_back({"z_y", p.z_y});
    constants.push_back({"K_y", p.K_y});
  }
  std::set<std::string> taken = reserved;
  for (const auto& c : constants) taken.insert(c.first);
  for (const auto& [name, value] : parameters) {
    if (taken.count(name))
      throw InputError("--param " + name,
                       "'" + name + "' is already a variable or scene constant of expression laws");
    if (builtin_names().count(name))
      throw InputError("--param " + name, "'" + name +
                                              "' is a built-in constant or function of the "
                                              "expression language; choose another name");
    bool ident =
        !name.empty() && (std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_');
    for (char c : name) ident = ident && (std::isalnum(static_cast<unsigned char>(c)) || c == '_');
    if (!ident)
      throw InputError("--param " + name,
                       "a parameter name is letters, digits and _, not starting with a digit");
    if (!std::isfinite(value)) throw InputError("--param " + name, "must be a finite number");
    constants.push_back({name, value});
  }
  return constants;
}

// The functions of `functions` defined on `parser` (one or two arguments each).
void define_functions(mu::Parser& parser, std::span<const ExpressionFunction> functions) {
  for (const ExpressionFunction& f : functions) {
    if (f.one) parser.DefineFun(std::string(f.name), f.one);
    if (f.two) parser.DefineFun(std::string(f.name), f.two);
  }
}

// "; functions hc_cor(u0) ..." for error messages ("" without functions).
std::string function_names(std::span<const ExpressionFunction> functions) {
  std::string known;
  if (!functions.empty()) known += "; functions";
  for (const ExpressionFunction& f : functions) {
    known += ' ';  // two appends: `" " + std::string(...)` trips GCC 12's -Wrestrict
    known += f.signature;
  }
  return known;
}

std::string known_names(const std::string& variables, const Constants& constants) {
  std::string known = "variables " + variables + "; constants";
  for (const auto& c : constants) known += " " + c.first;
  return known;
}

}  // namespace

ExpressionError::ExpressionError(std::string field, const std::string& expression, int position,
                                 const std::string& what)
    : InputError(std::move(field), caret_message(expression, position, what)),
      position_(position) {}

struct CompiledExpressions::Parsers {
  mu::Parser load, unload, onset;
  double z = 0, zdot = 0, zmax = 0;
  std::string known;  // the names an expression may use, for error messages
};

CompiledExpressions::CompiledExpressions(const ExpressionLawSpec& spec,
                                         const LawParameters& parameters, const Scene& scene,
                                         const DerivedParameters& p)
    : parsers_(std::make_unique<Parsers>()), has_unload_(!spec.unload.empty()) {
  if (spec.force.empty())
    throw InputError("--force", "the expression law needs a force expression, e.g. 'K_h*z^1.5'");
  Parsers& P = *parsers_;
  std::set<std::string> reserved = {"z", "zdot", "zmax"};
  for (const ExpressionFunction& f : spec.functions) reserved.insert(std::string(f.name));
  const Constants constants = scene_constants(scene, p, parameters, reserved);
  // Hertz scales of the scene: z_ref = (5 m v0^2 / (4 K_h))^{2/5}, F_ref = K_h z_ref^{3/2}.
  v_ref_ = scene.velocity;
  z_ref_ = std::pow(5.0 * p.effective_mass * v_ref_ * v_ref_ / (4.0 * p.K_h), 0.4);
  k_ref_ = p.K_h * std::sqrt(z_ref_);
  P.known = known_names("z, zdot, zmax", constants) + function_names(spec.functions);
  for (mu::Parser* parser : {&P.load, &P.unload, &P.onset})
    define_functions(*parser, spec.functions);
  const std::vector<std::pair<std::string, double*>> variables = {
      {"z", &P.z}, {"zdot", &P.zdot}, {"zmax", &P.zmax}};
  P.z = P.zmax = z_ref_;  // a point inside contact for the trial evaluation
  P.zdot = v_ref_;
  uses_rate_ = setup_parser(P.load, spec.force, "--force", variables, constants, P.known, "zdot");
  if (has_unload_)
    uses_rate_ =
        setup_parser(P.unload, spec.unload, "--unload", variables, constants, P.known, "zdot") ||
        uses_rate_;
  has_onset_ = spec.onset_force.find_first_not_of(" \t") != std::string::npos;
  if (!spec.onset_force.empty() && !has_onset_)
    throw InputError("--onset-force", "an empty expression; give the force at z = 0, e.g. '-Fad'");
  if (has_onset_)
    setup_parser(P.onset, spec.onset_force, "--onset-force", variables, constants, P.known, "zdot");
}

double CompiledExpressions::pull_off_work(double z_max,
                                          const std::function<double()>& compute) const {
  if (!pull_off_ || pull_off_->first != z_max) pull_off_ = std::pair{z_max, compute()};
  return pull_off_->second;
}

std::optional<double> CompiledExpressions::onset_force() const {
  if (!has_onset_) return std::nullopt;
  Parsers& P = *parsers_;
  P.z = P.zmax = 0.0;
  P.zdot = v_ref_;
  try {
    return P.onset.Eval();
  } catch (const mu::Parser::exception_type&) {
    return std::numeric_limits<double>::quiet_NaN();
  }
}

CompiledExpressions::~CompiledExpressions() = default;

double CompiledExpressions::evaluate(bool unload, double z, double zdot, double zmax) const {
  // below z = 0: continued from min(F(0), 0), so contact ends at z = 0 at the latest (header)
  if (z < 0) return std::min(evaluate(unload, 0.0, zdot, unload ? zmax : 0.0), 0.0) + k_ref_ * z;
  Parsers& P = *parsers_;
  P.z = z;
  P.zdot = zdot;
  P.zmax = zmax;
  double F;
  try {
    F = (unload && has_unload_ ? P.unload : P.load).Eval();
  } catch (const mu::Parser::exception_type&) {
    F = std::numeric_limits<double>::quiet_NaN();
  }
  if (!std::isfinite(F) && !non_finite_) {
    std::ostringstream os;
    os.precision(17);
    os << (unload && has_unload_ ? "--unload" : "--force") << " evaluated to " << F
       << " at z = " << z << " m, zdot = " << zdot << " m/s, zmax = " << zmax
       << " m: the expression must be finite wherever contact can reach";
    non_finite_ = os.str();
    non_finite_at_onset_ = z <= 0 && zmax <= 0;
  }
  return F;
}

double CompiledExpressions::loading(double z, double zdot) const {
  return evaluate(false, z, zdot, std::max(z, 0.0));
}

double CompiledExpressions::unloading(double z, double zdot, double zmax) const {
  return evaluate(true, z, zdot, zmax);
}

template <bool Rate>
double ExpressionLaw<Rate>::step(double scale, double at) {
  // eps^{1/3} balances truncation O(d^2 F''') against rounding O(eps F / d)
  // relative to |at| so that a difference near z = 0 does not reach across it
  return std::cbrt(std::numeric_limits<double>::epsilon()) * std::max(1e-9 * scale, std::abs(at));
}

template <bool Rate>
void ExpressionLaw<Rate>::begin_unloading(Branch<double>& h, double z_m) const {
  if (!std::isfinite(z_m))  // the bisection below would never end on a NaN bracket
    throw LawDomainError("unloading from a maximum compression z_m that is not a finite number");
  h.phase = Phase::unloading;
  h.z_max = z_m;
  auto F = [&](double z) { return expr->unloading(z, 0.0, z_m); };
  if (F(0.0) >= 0.0) {
    h.z_perm = 0.0;
    return;
  }
  if (F(z_m) <= 0.0) {
    h.z_perm = z_m;
    return;
  }
  // bisection to adjacent doubles: always converges (at most ~1100 halvings of [0, z_m])
  double lo = 0.0, hi = z_m;
  for (;;) {
    const double mid = lo + 0.5 * (hi - lo);
    if (mid <= lo || mid >= hi) break;
    (F(mid) < 0.0 ? lo : hi) = mid;
  }
  h.z_perm = hi;
}

template <bool Rate>
double ExpressionLaw<Rate>::stored_energy(const Branch<double>& h, double z) const {
  const bool loading = h.phase == Phase::loading;
  const double lo = loading ? 0.0 : h.z_perm;
  if (!(z > lo)) return 0.0;
  auto F = [&](double s) {
    return std::max(0.0, loading ? expr->loading(s, 0.0) : expr->unloading(s, 0.0, h.z_max));
  };
  return boost::math::quadrature::gauss<double, 20>::integrate(F, lo, z);
}

namespace {

// One 31-point Gauss-Kronrod panel over [a, b]: the integral and its error estimate. The panel
// is mapped onto [-1, 1] here: boost's adaptive integrate compares the error of the unmapped
// panel with a tolerance scaled by its half-width, so on a branch 1e-11 m wide (a 100 um bead
// at 1 cm/s) it never met 1e-12 and halved to its depth limit on every call: 6e4 evaluations,
// 9 ms per integration step.
struct Panel {
  double integral = 0, error = 0;
};
template <class F>
Panel gauss_kronrod_panel(const F& f, double a, double b) {
  const double half = 0.5 * (b - a), mid = 0.5 * (a + b);
  double error = 0;
  const double I = boost::math::quadrature::gauss_kronrod<double, 31>::integrate(
      [&](double u) { return f(mid + half * u); }, -1.0, 1.0, 0, 0.0, &error);
  return {half * I, std::abs(half) * error};
}

// The panel p over [a, b], halved (at most `depth` times) while its error estimate exceeds its
// share of `tolerance` [J].
template <class F>
double refined(const F& f, double a, double b, const Panel& p, double tolerance, int depth) {
  if (depth == 0 || p.error <= tolerance) return p.integral;
  const double mid = 0.5 * (a + b);
  return refined(f, a, mid, gauss_kronrod_panel(f, a, mid), 0.5 * tolerance, depth - 1) +
         refined(f, mid, b, gauss_kronrod_panel(f, mid, b), 0.5 * tolerance, depth - 1);
}

}  // namespace

double CompiledExpressions::loading_speed_gain(double mass) const {
  auto F = [&](double z) { return loading(z, v_ref_); };
  if (!(F(0.0) < 0.0)) return 1.0;
  // the first zero: bracketed by doubling from 1e-9 z_ref (to 1e6 z_ref, far past any contact
  // the scene's v0 reaches), then bisected to adjacent doubles; none: the well to that reach
  double lo = 0.0, hi = 1e-9 * z_ref_;
  while (F(hi) < 0.0 && hi < 1e6 * z_ref_) lo = hi, hi *= 2;
  if (F(hi) >= 0.0)
    for (double mid = lo + 0.5 * (hi - lo); mid > lo && mid < hi; mid = lo + 0.5 * (hi - lo))
      (F(mid) < 0.0 ? lo : hi) = mid;
  const Panel whole = gauss_kronrod_panel(F, 0.0, hi);
  const double W = -refined(F, 0.0, hi, whole, 1e-10 * std::abs(whole.integral), 10);
  return std::sqrt(1.0 + 2.0 * std::max(W, 0.0) / (mass * v_ref_ * v_ref_));
}

template <bool Rate>
std::optional<double> ExpressionLaw<Rate>::separation_work(const Branch<double>& h,
                                                           double z) const {
  if (h.phase == Phase::loading) return std::nullopt;
  if (!(z > 0)) return 0.0;
  // S(z) = -W + int_{z_f}^{z} F with the pull-off work W = -int_0^{z_f} F: each integral has
  // one sign (F <= 0 below the set z_f, >= 0 above), so the relative tolerance means something
  // (one quadrature over a sign change near S = 0 never met it and subdivided to its depth);
  // W is computed once per unloading branch.
  // Each integral to 1e-12 of itself or 1e-13 F_ref z_ref (= 1.25e-13 m v0^2), whichever is
  // larger: the well's capture allows 1e-9 m v0^2 for the quadrature (capture.h), and where the
  // integrand is the rounding noise of a cancellation (F near zero at z_f) a relative
  // tolerance alone cannot be met.
  auto F = [&](double s) { return expr->unloading(s, 0.0, h.z_max); };
  const double energy_floor = 1e-13 * expr->stiffness_scale() * std::pow(expr->length_scale(), 2);
  auto integral = [&](double a, double b) {
    if (!(a < b)) return 0.0;
    const Panel whole = gauss_kronrod_panel(F, a, b);
    return refined(F, a, b, whole, std::max(1e-12 * std::abs(whole.integral), energy_floor), 10);
  };
  const double z_f = h.z_perm;
  const double W = expr->pull_off_work(h.z_max, [&] { return -integral(0.0, z_f); });
  return -W + (z >= z_f ? integral(z_f, z) : -integral(z, z_f));
}

std::function<double(double)> compile_cor_claim(const std::string& text,
                                                const LawParameters& parameters, const Scene& scene,
                                                std::span<const ExpressionFunction> functions) {
  struct Claim {
    mu::Parser parser;
    double v0 = 0;
  };
  auto claim = std::make_shared<Claim>();
  Scene base = scene;
  const DerivedParameters p = derive(base);
  Constants constants = scene_constants(base, p, parameters, {"z", "zdot", "zmax"});
  std::erase_if(constants, [](const auto& c) { return c.first == "v0"; });
  claim->v0 = scene.velocity;
  if (text.find_first_not_of(" \t") == std::string::npos)
    throw InputError("--expect-cor", "the claimed COR is an empty expression; give e.g. '0.8'");
  const std::string known = known_names("v0", constants) + function_names(functions);
  define_functions(claim->parser, functions);
  setup_parser(claim->parser, text, "--expect-cor", {{"v0", &claim->v0}}, constants, known, "v0");
  return [claim](double v0) {
    claim->v0 = v0;
    try {
      return claim->parser.Eval();
    } catch (const mu::Parser::exception_type&) {
      return std::numeric_limits<double>::quiet_NaN();
    }
  };
}

template struct ExpressionLaw<false>;
template struct ExpressionLaw<true>;

}  // namespace ivv
