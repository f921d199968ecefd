// Shared machinery of the verification cases: scene grids, one run, the memoised 50-digit
// reference, and the bookkeeping of "largest error over a set of runs".
#pragma once

#include "solver/format.h"

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "solver/simulate.h"
#include "verification/registry.h"

namespace ivv::verification {

// A labelled scene for a grid.
struct GridScene {
  std::string label;  // e.g. "paper v0=1 zeta=0.1"
  Scene scene;
};

Scene with(Scene s, double v0, double zeta);  // zeta 0: no dashpot

// The paper scene at 0.1, 1, 5 m/s with zeta in {0, 0.05, 0.1, 0.3} (12 scenes).
std::vector<GridScene> paper_grid();
// Other material pairs and masses from 1e-3 to 10 kg (elastic and plastic impacts).
std::vector<GridScene> extended_grid();
// Steel ball on aluminium, steel on steel: other E*, z_y.
Scene steel_on_aluminium();
Scene steel_on_steel();

// A request with the defaults of the integrator.
SimulationRequest request(const Scene& s, LawKind law, IntegratorKind integrator,
                          double hc_mu = 0.0);

// The mp50 result for a request (integrator ignored), computed once per process and shared
// between cases and threads. Throws if the reference itself fails.
const ImpactResult& reference(const SimulationRequest& req);

// Relative error, with the reference's scale; both zero counts as exact.
double relative_error(double value, double reference);

// Keeps the largest relative error over a set of comparisons and where it happened.
class WorstError {
 public:
  void add(double value, double reference, const std::string& where);
  // For the COR: e is a velocity ratio and the integrators control the rebound velocity
  // relative to v0 (the scale of the velocity state), so its error is |e - e_ref|, which is
  // also a relative error in units of v0. A relative error of a near-capture e ~ 1e-5 would
  // magnify the same velocity error 1e5 times.
  void add_cor(double value, double reference, const std::string& where);
  void fail(const std::string& why);  // a run that failed outright poisons the case
  double value() const { return failed_ ? std::numeric_limits<double>::infinity() : worst_; }
  std::string where() const { return failed_ ? failure_ : where_; }
  int count() const { return count_; }

 private:
  double worst_ = 0.0;
  std::string where_ = "no comparison";
  bool failed_ = false;
  std::string failure_;
  int count_ = 0;
};

// Outcome "largest relative error <= tolerance" with a standard detail sentence.
Outcome worst_case(const WorstError& w, double tolerance, const std::string& what);

// Numbers in sentences: ivv::fmt(v, precision) of solver/format.h, the one formatter.
using ivv::fmt;

}  // namespace ivv::verification
