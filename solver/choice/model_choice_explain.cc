// ModelChoice in words (solver/choice/model_choice.h): the reasons `simulate --json` prints under
// model_choice, for each route of --model auto, and what a ModelChoice says of itself.
#include <cmath>
#include <sstream>

#include "solver/choice/integrator_choice.h"
#include "solver/choice/model_choice.h"
#include "solver/format.h"
#include "solver/laws/hunt_crossley.h"

namespace ivv {
namespace {

// Three significant digits: enough for a reason, short enough to read.
std::string fmt3(double v) {
  return fmt(v, 3);
}

}  // namespace

// What explain() knows while it writes: the request, the decision, the run and the choice.
struct Explanation {
  const SimulationRequest& req;
  const DerivedParameters& p;
  const ModelDecision& d;
  const ImpactResult& r;
  ModelChoice& c;

  void say(std::string why) { c.reasons.push_back(std::move(why)); }

  void integrator_words() {
    if (req.auto_integrator)
      for (std::string& why : choose_integrator(req).reasons) say(std::move(why));
    else
      say("integrator " + c.integrator + " as requested (--integrator)");
  }

  void closed_form_elastoplastic() {
    c.law = "closed-form elastoplastic (energy)";
    c.integrator = "none";
    say("elastoplastic law without a dashpot: z_m, F_max, z_f, e and the hysteresis work "
        "exactly by energy (docs/design.md §2); t_f in closed form on the loading legs and by "
        "Gauss-Legendre quadrature on the unloading leg; no integration");
    say("events: onset, maximum compression (= maximum displacement) and separation; the "
        "yield event's time is not computed by the closed form (absent)");
    say("estimated relative error: round-off (" + fmt3(kEstimateClosedForm) +
        "); the contact time's quadrature within rtol/10");
  }

  void closed_form_hertz() {
    c.law = "closed-form hertz (energy)";
    c.integrator = "none";
    say("hertz law without a dashpot: z_m = (5 m v0^2/(4 K_h))^(2/5), F_max = K_h z_m^1.5, "
        "t_f = (4/5) B(2/5, 1/2) z_m/v0, e = 1 exactly (docs/design.md §2); no integration");
    say("estimated relative error: round-off (" + fmt3(kEstimateClosedForm) + ")");
  }

  void hunt_crossley_lambert_w() {
    c.law = "hunt-crossley: e by Lambert W, the rest integrated";
    c.integrator = std::string(to_string(d.integrator));
    const double mu = HuntCrossleyLaw::make(req.parameters, p).mu;
    say("hunt-crossley: e = [1 + W0(-(1 + u0) e^-(1 + u0))]/u0 exactly (u0 = mu v0 = " +
        fmt3(mu * req.scene.velocity) +
        ", docs/design.md §2); F_max, t_f, z_max and the impulses have no closed form: integrated");
    integrator_words();
    if (r.separated())
      say("the integrated Poisson COR " + fmt3(r.e_poisson) + " against the exact e " + fmt3(r.e) +
          ": difference " + fmt3(std::abs(r.e_poisson - r.e)));
    say("estimated relative error of F_max, t_f: the integrator's, " + fmt3(d.estimated_error) +
        "; e exact");
  }

  void linearized_closed_form() {
    c.law = "linearized closed form (paper eqs 22-25)";
    c.integrator = "none";
    if (req.law == LawKind::linearized) {
      say("the linearized law has an exact closed form (paper eqs 22-25, "
          "closed_forms/linear_model.h); no integration");
      return;
    }
    say("elastoplastic law with a dashpot at rtol " + fmt3(req.options.rtol) +
        ": the linearized closed form's estimated error " + fmt3(d.estimated_error) +
        " = 2 (1 + 10 zeta) D0 with D0 = " + fmt3(d.linear_difference) +
        " (the exact undamped difference of the two laws in e, z_m, F_max, t_f) is within "
        "rtol; its unloading damping ratio zeta1 <= " +
        fmt3(kLinearMaxUnloadingDamping) + " (far from capture)");
  }

  // Why no closed form served the law.
  std::string why_integrated() const {
    const std::string law(to_string(req.law));
    if (req.law == LawKind::expression) return "an expression law has no closed form: integrated";
    if (req.law == LawKind::linearized)
      return "the linearized law is undefined here (z_m < 2.25 z_y): run so that the "
             "integrator names the failure";
    if (req.law != LawKind::elastoplastic)
      return law + " with a dashpot: no exact closed form; integrated";
    std::string why = "elastoplastic with a dashpot: no exact closed form; ";
    if (d.linear_difference >= 0)
      return why + "the linearized closed form's estimated error 2 (1 + 10 zeta) D0 = " +
             fmt3(kLinearSafety * (1 + kLinearZetaGrowth * p.zeta) * d.linear_difference) +
             " (D0 = " + fmt3(d.linear_difference) + ") exceeds rtol " + fmt3(req.options.rtol) +
             " or its unloading is near capture";
    return why + "the linearized closed form is not within rtol " + fmt3(req.options.rtol) +
           " (its undamped difference in e alone exceeds it) or is undefined here";
  }

  void integrated() {
    c.law = std::string(to_string(req.law)) + " (full model, integrated)";
    c.integrator = std::string(to_string(d.integrator));
    say(why_integrated());
    integrator_words();
    say("capture, if any, by the driver's criterion: the rebound still attainable from the "
        "remaining energy, sqrt(w^2 + 2U), below capture_cor = " +
        fmt3(req.options.capture_cor));
    if (!req.auto_integrator)  // choose_integrator's reasons state it otherwise
      say("estimated relative error of e, F_max, t_f: " + fmt3(d.estimated_error) +
          " (the integrator's global error)");
  }
};

ModelChoice explain(const ValidatedRequest& v, const ModelDecision& d, const ImpactResult& r) {
  ModelChoice c;
  c.decision = d;
  c.estimated_error = d.estimated_error;
  Explanation words{v.request(), v.derived(), d, r, c};
  switch (d.route) {
    case ModelRoute::closed_form_elastoplastic:
      words.closed_form_elastoplastic();
      break;
    case ModelRoute::closed_form_hertz:
      words.closed_form_hertz();
      break;
    case ModelRoute::hunt_crossley_lambert_w:
      words.hunt_crossley_lambert_w();
      break;
    case ModelRoute::linearized_closed_form:
      words.linearized_closed_form();
      break;
    case ModelRoute::integrated:
      words.integrated();
      break;
  }
  return c;
}

ModelChoice integrated_choice(const SimulationRequest& req, const IntegratorChoice& chosen) {
  ModelChoice c;
  c.decision.route = ModelRoute::integrated;
  c.decision.integrator = chosen.integrator;
  c.decision.estimated_error = chosen.estimated_error;
  c.law = std::string(to_string(req.law)) + " (full model, integrated)";
  c.integrator = std::string(to_string(chosen.integrator));
  c.reasons = chosen.reasons;
  c.estimated_error = chosen.estimated_error;
  return c;
}

std::string ModelChoice::brief() const {
  std::ostringstream os;
  os << law << " (integrator " << integrator << ", estimated error " << estimated_error << ")";
  return os.str();
}

std::string ModelChoice::full() const {
  std::string out = brief() + "\n";
  for (const std::string& why : reasons) out += "  - " + why + "\n";
  return out;
}

}  // namespace ivv
