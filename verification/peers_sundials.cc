// The SUNDIALS peers (verification/peers.h): CVODE (Adams, BDF) and ARKODE's ERKStep, each
// locating both events with its own root finding (CVodeRootInit / ERKStepRootInit on the
// problem of verification/peer_problem.h), set up as their user guides advise; what each
// setting is and why is written beside it. SUNDIALS 6.4 (Debian libsundials-dev).
#include <arkode/arkode_erkstep.h>
#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include <string>

#include "verification/peer_problem.h"

namespace ivv::verification::peer_detail {
namespace {

// Steps allowed between two returns (the guides' default, 500, is for one output interval;
// an impact at rtol 1e-12 takes a few hundred). Reaching it is reported as a failure.
constexpr long kMaxSteps = 100000;
// Dormand-Prince 7-4-5, the ERK table: on this problem it beats ERKStep's higher-order tables at
// every tolerance from 1e-6 to 1e-12 (one session, rtol 1e-8: 72 us and |de|/e 1.7e-8, against
// Fehlberg 13-7-8 at 203 us and 1.3e-7 and Verner 8-5-6 at 165 us and 3.2e-6), since the
// Hermite interpolant that places the roots stops at degree 5 whatever the method's order.
constexpr ARKODE_ERKTableID kErkTable = ARKODE_DORMAND_PRINCE_7_4_5;
constexpr int kErkOrder = 5;

State state_of(N_Vector y) {
  const double* p = N_VGetArrayPointer(y);
  return {p[0], p[1], p[2]};
}

void set_state(N_Vector y, const State& x) {
  double* p = N_VGetArrayPointer(y);
  for (int i = 0; i < 3; ++i) p[i] = x[i];
}

int rhs(realtype, N_Vector y, N_Vector ydot, void* data) {
  State d;
  (*static_cast<const Problem*>(data))(state_of(y), d, 0.0);
  set_state(ydot, d);
  return 0;
}

int root(realtype, N_Vector y, realtype* gout, void* data) {
  gout[0] = static_cast<const Problem*>(data)->event(state_of(y));
  return 0;
}

// The analytic Jacobian of (w, -F, w - 2 zeta F) in (a, w, z), for CVODE's Newton iteration.
int jacobian(realtype, N_Vector y, N_Vector, SUNMatrix J, void* data, N_Vector, N_Vector,
             N_Vector) {
  const auto* pb = static_cast<const Problem*>(data);
  const double k = pb->stiffness(state_of(y)[2]);
  SUNMatZero(J);
  SM_ELEMENT_D(J, 0, 1) = 1.0;
  SM_ELEMENT_D(J, 1, 2) = -k;
  SM_ELEMENT_D(J, 2, 1) = 1.0;
  SM_ELEMENT_D(J, 2, 2) = -pb->two_zeta * k;
  return 0;
}

// SUNDIALS reports errors through a handler: keep the message for PeerResult::reason instead of
// printing it.
void keep_message(int, const char* module, const char* function, char* msg, void* data) {
  *static_cast<std::string*>(data) = std::string(module) + " " + function + ": " + msg;
}

// The SUNDIALS objects of one solver, created once per thread and reused for every impact
// through CVodeReInit / ERKStepReInit (the guides' way to solve a sequence of problems of one
// size): their creation is not part of an impact's cost, as ivv's own setup is not.
class Solver {
 public:
  enum class Kind { cvode_adams, cvode_bdf, arkode_erk };
  explicit Solver(Kind kind);
  ~Solver();
  Solver(const Solver&) = delete;
  Solver& operator=(const Solver&) = delete;

  PeerResult run(const Scene& scene, double tol);

 private:
  bool configure_erk();
  bool configure_cvode();
  bool restart(double tau, const State& x, double tol, bool first);
  int advance(double* tau);  // to the next root; the SUNDIALS return flag
  PeerResult failure(const std::string& what) const;

  Kind kind_;
  SUNContext ctx_ = nullptr;
  N_Vector y_ = nullptr;
  SUNMatrix A_ = nullptr;
  SUNLinearSolver LS_ = nullptr;
  SUNNonlinearSolver NLS_ = nullptr;
  void* mem_ = nullptr;
  bool ready_ = false;
  Problem pb_{};
  std::string error_;
};

Solver::Solver(Kind kind) : kind_(kind) {
  if (SUNContext_Create(nullptr, &ctx_) != 0 || !(y_ = N_VNew_Serial(3, ctx_))) return;
  set_state(y_, {0.0, 1.0, 0.0});
  ready_ = kind_ == Kind::arkode_erk ? configure_erk() : configure_cvode();
}

bool Solver::configure_erk() {
  if (!(mem_ = ERKStepCreate(rhs, 0.0, y_, ctx_))) return false;
  // The guide: a Hermite interpolant for non-stiff problems (the default), here of the highest
  // degree ERKStep allows for the method, its order - 1 = 4: root finding and the state at a
  // root come from this interpolant.
  return ERKStepSetErrHandlerFn(mem_, keep_message, &error_) == ARK_SUCCESS &&
         ERKStepSetTableNum(mem_, kErkTable) == ARK_SUCCESS &&
         ERKStepSetInterpolantType(mem_, ARK_INTERP_HERMITE) == ARK_SUCCESS &&
         ERKStepSetInterpolantDegree(mem_, kErkOrder - 1) == ARK_SUCCESS &&
         ERKStepSetMaxNumSteps(mem_, kMaxSteps) == ARK_SUCCESS;
}

bool Solver::configure_cvode() {
  const bool bdf = kind_ == Kind::cvode_bdf;
  if (!(mem_ = CVodeCreate(bdf ? CV_BDF : CV_ADAMS, ctx_))) return false;
  if (CVodeSetErrHandlerFn(mem_, keep_message, &error_) != CV_SUCCESS ||
      CVodeInit(mem_, rhs, 0.0, y_) != CV_SUCCESS ||
      CVodeSetMaxNumSteps(mem_, kMaxSteps) != CV_SUCCESS)
    return false;
  if (bdf) {
    // The guide's pairing for stiff problems: BDF with Newton iteration and a dense direct
    // linear solver, here with the analytic Jacobian (no difference quotients).
    A_ = SUNDenseMatrix(3, 3, ctx_);
    LS_ = SUNLinSol_Dense(y_, A_, ctx_);
    return A_ && LS_ && CVodeSetLinearSolver(mem_, LS_, A_) == CV_SUCCESS &&
           CVodeSetJacFn(mem_, jacobian) == CV_SUCCESS;
  }
  // The guide's pairing for non-stiff problems: Adams-Moulton with fixed-point iteration (no
  // Jacobian, no linear solves).
  NLS_ = SUNNonlinSol_FixedPoint(y_, 0, ctx_);
  return NLS_ && CVodeSetNonlinearSolver(mem_, NLS_) == CV_SUCCESS;
}

Solver::~Solver() {
  if (kind_ == Kind::arkode_erk) {
    if (mem_) ERKStepFree(&mem_);
  } else if (mem_) {
    CVodeFree(&mem_);
  }
  if (NLS_) SUNNonlinSolFree(NLS_);
  if (LS_) SUNLinSolFree(LS_);
  if (A_) SUNMatDestroy(A_);
  if (y_) N_VDestroy(y_);
  if (ctx_) SUNContext_Free(&ctx_);
}

// Starts (first) or restarts the integration at (tau, x): a new impact, or the phase switch at
// maximum compression, where the law changes branch and its slope jumps, so the guides'
// advice for a discontinuity applies: re-initialise there rather than step across it. The
// root function reads the problem's phase, so re-arming it with direction -1 (falling through
// zero) selects the next event.
bool Solver::restart(double tau, const State& x, double tol, bool first) {
  set_state(y_, x);
  int dir = -1;
  if (kind_ == Kind::arkode_erk) {
    const int reinit = first ? ERKStepReInit(mem_, rhs, tau, y_) : ERKStepReset(mem_, tau, y_);
    return reinit == ARK_SUCCESS && ERKStepSStolerances(mem_, tol, tol) == ARK_SUCCESS &&
           ERKStepSetUserData(mem_, &pb_) == ARK_SUCCESS &&
           ERKStepRootInit(mem_, 1, root) == ARK_SUCCESS &&
           ERKStepSetRootDirection(mem_, &dir) == ARK_SUCCESS;
  }
  return CVodeReInit(mem_, tau, y_) == CV_SUCCESS &&
         CVodeSStolerances(mem_, tol, tol) == CV_SUCCESS &&
         CVodeSetUserData(mem_, &pb_) == CV_SUCCESS && CVodeRootInit(mem_, 1, root) == CV_SUCCESS &&
         CVodeSetRootDirection(mem_, &dir) == CV_SUCCESS;
}

int Solver::advance(double* tau) {
  if (kind_ == Kind::arkode_erk) {
    const int flag = ERKStepEvolve(mem_, kTauLimit, y_, tau, ARK_NORMAL);
    return flag == ARK_ROOT_RETURN ? 1 : flag < 0 ? -1 : 0;
  }
  const int flag = CVode(mem_, kTauLimit, y_, tau, CV_NORMAL);
  return flag == CV_ROOT_RETURN ? 1 : flag < 0 ? -1 : 0;
}

PeerResult Solver::failure(const std::string& what) const {
  PeerResult r;
  r.reason = what + (error_.empty() ? "" : ": " + error_);
  r.rhs_evaluations = pb_.evals;
  return r;
}

PeerResult Solver::run(const Scene& scene, double tol) {
  pb_ = make_problem(scene);
  error_.clear();
  if (!ready_) return failure("SUNDIALS refused the solver's configuration");
  double tau = 0.0, F_max = 0.0;
  State x{0.0, 1.0, 0.0};
  for (int phase = 0; phase < 2; ++phase) {
    if (!restart(tau, x, tol, phase == 0)) return failure("SUNDIALS refused the setup");
    const int flag = advance(&tau);
    if (flag < 0) return failure("SUNDIALS failed");
    if (flag == 0) return failure("no event before tau = 1e3");
    x = state_of(y_);
    if (phase == 0) F_max = pb_.switch_to_unloading(x);
  }
  return finish(pb_, scene, x, tau, F_max);
}

}  // namespace

PeerResult cvode_peer(const Scene& scene, double tol, CvodeMethod method) {
  thread_local Solver adams(Solver::Kind::cvode_adams), bdf_solver(Solver::Kind::cvode_bdf);
  return (method == CvodeMethod::bdf ? bdf_solver : adams).run(scene, tol);
}

PeerResult arkode_erk_peer(const Scene& scene, double tol) {
  thread_local Solver erk(Solver::Kind::arkode_erk);
  return erk.run(scene, tol);
}

}  // namespace ivv::verification::peer_detail
