// GSL odeiv2 steppers (GSL Reference Manual, "Ordinary Differential Equations"):
//   gsl-rk8pd  explicit embedded Runge-Kutta Prince-Dormand (8, 9)
//   gsl-msbdf  variable-coefficient linear multistep BDF in Nordsieck form, orders 1-5, with
//              the analytic Jacobian (stiff scenes)
// One adaptive step at a time through gsl_odeiv2_evolve_apply with the standard y-control
// (atol + rtol |y|). GSL exposes no dense output, so the interpolant is cubic Hermite from the
// step's end points and the event locator refines its estimate by re-stepping exactly to the
// event: one rk8pd step of the shorter length, or (msbdf, whose multistep history cannot be
// rewound) a fresh driver integration from the step's start.
#pragma once

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include <cmath>
#include <memory>
#include <string>

#include "solver/driver/hermite.h"
#include "solver/steppers/integrator_options.h"
#include "solver/steppers/step_result.h"

namespace ivv {

namespace gsl_detail {

// GSL's default error handler aborts; ivv reports GSL status codes instead.
void disable_abort_on_error();

template <class System>
int rhs(double t, const double y[], double f[], void* params) {
  const auto& sys = *static_cast<const System*>(params);
  typename System::state_type x, d;
  for (std::size_t i = 0; i < System::N; ++i) x[i] = y[i];
  sys(x, d, t);
  for (std::size_t i = 0; i < System::N; ++i) {
    if (!std::isfinite(d[i])) return GSL_EBADFUNC;
    f[i] = d[i];
  }
  return GSL_SUCCESS;
}

template <class System>
int jacobian(double, const double y[], double* dfdy, double dfdt[], void* params) {
  const auto& sys = *static_cast<const System*>(params);
  typename System::state_type x;
  for (std::size_t i = 0; i < System::N; ++i) x[i] = y[i];
  struct RowMajor {
    double* p;
    double& operator()(std::size_t i, std::size_t j) { return p[i * System::N + j]; }
  } view{dfdy};
  sys.jacobian(x, view);
  for (std::size_t i = 0; i < System::N; ++i) dfdt[i] = 0.0;
  return GSL_SUCCESS;
}

struct DriverDeleter {
  void operator()(gsl_odeiv2_driver* d) const { gsl_odeiv2_driver_free(d); }
};
using DriverPtr = std::unique_ptr<gsl_odeiv2_driver, DriverDeleter>;

}  // namespace gsl_detail

enum class GslMethod { rk8pd, msbdf };

template <class System, GslMethod Method>
class GslStepper : public HermiteSteps<System> {
 public:
  using state_type = typename System::state_type;
  using T = typename System::value_type;
  static constexpr std::string_view name = Method == GslMethod::rk8pd ? "gsl-rk8pd" : "gsl-msbdf";
  static constexpr int order = Method == GslMethod::rk8pd ? 8 : 5;
  static constexpr bool implicit = Method == GslMethod::msbdf;
  static constexpr bool fixed_step = false;
  static constexpr bool fixed_step_mode = Method == GslMethod::rk8pd;
  static constexpr bool reference = false;
  // the paper scene at default settings, relative error of e against mp50: rk8pd 3.8e-12,
  // msbdf 3.0e-9 (BDF's error estimate is the least strict)
  static constexpr double measured_relative_error = Method == GslMethod::rk8pd ? 1e-11 : 1e-8;
  static constexpr std::string_view description =
      Method == GslMethod::rk8pd
          ? "GSL odeiv2 Runge-Kutta Prince-Dormand 8(9), Hermite interpolant"
          : "GSL odeiv2 multistep BDF (orders 1-5) with Jacobian: stiff scenes";
  static constexpr std::size_t N = System::N;

  explicit GslStepper(const IntegratorOptions& opt)
      : opt_(opt), system_(std::make_unique<gsl_odeiv2_system>()), h_(opt.initial_dt) {
    gsl_detail::disable_abort_on_error();
    *system_ = {&gsl_detail::rhs<System>, &gsl_detail::jacobian<System>, N, nullptr};
    driver_.reset(
        gsl_odeiv2_driver_alloc_y_new(system_.get(), type(), opt.initial_dt, opt.atol, opt.rtol));
  }

  void start(const System& sys, T t, const state_type& x) {
    system_->params = const_cast<System*>(&sys);
    gsl_odeiv2_driver_reset(driver_.get());
    HermiteSteps<System>::start(sys, t, x);
  }

  StepResult step(const System& sys) {
    this->begin_step();
    double y[N];
    for (std::size_t i = 0; i < N; ++i) y[i] = x0_[i];
    double t = t0_;
    gsl_odeiv2_driver* d = driver_.get();
    int status;
    if (Method == GslMethod::rk8pd && opt_.fixed_step) {  // error control off: h = dt
      double yerr[N], f[N];
      for (std::size_t i = 0; i < N; ++i) f[i] = f0_[i];
      status = gsl_odeiv2_step_apply(d->s, t0_, opt_.fixed_dt(), y, yerr, f, nullptr, d->sys);
      t = t0_ + opt_.fixed_dt();
    } else {
      status = gsl_odeiv2_evolve_apply(d->e, d->c, d->s, d->sys, &t, opt_.tau_max, &h_, y);
    }
    if (status == GSL_EBADFUNC) {
      return StepResult::failure(
          StepFailure::non_finite_state,
          std::string(name) +
              ": the right-hand side is not finite near tau = " + std::to_string(t0_) +
              " (the contact force overflowed or is undefined at this state)");
    }
    if (status != GSL_SUCCESS || !(t > t0_)) {
      return StepResult::failure(StepFailure::library_error,
                                 std::string(name) + ": " + gsl_strerror(status) +
                                     " at tau = " + std::to_string(t0_) +
                                     (status == GSL_SUCCESS ? " (the step did not advance)" : ""));
    }
    state_type x1;
    for (std::size_t i = 0; i < N; ++i) x1[i] = y[i];
    this->end_step(sys, t, x1);
    return StepResult::success();
  }

  // The state at t in (t0, t1], integrated from the step's start; a failure carries GSL's
  // status (e.g. a non-finite right-hand side, or the msbdf driver out of steps).
  StepResult restep(const System&, T t, state_type& out) {
    double y[N];
    for (std::size_t i = 0; i < N; ++i) y[i] = x0_[i];
    int status = GSL_SUCCESS;
    if constexpr (Method == GslMethod::rk8pd) {
      double yerr[N], f[N];
      for (std::size_t i = 0; i < N; ++i) f[i] = f0_[i];
      status = gsl_odeiv2_step_apply(driver_->s, t0_, t - t0_, y, yerr, f, nullptr, system_.get());
    } else {
      if (!refine_driver_) {
        refine_driver_.reset(gsl_odeiv2_driver_alloc_y_new(system_.get(), type(), opt_.initial_dt,
                                                           opt_.atol, opt_.rtol));
      }
      gsl_odeiv2_driver_reset_hstart(refine_driver_.get(), std::min(opt_.initial_dt, t - t0_));
      double tt = t0_;
      status = gsl_odeiv2_driver_apply(refine_driver_.get(), &tt, t, y);
    }
    if (status != GSL_SUCCESS) {
      return StepResult::failure(StepFailure::library_error,
                                 std::string(name) + ": " + gsl_strerror(status) +
                                     " re-stepping from tau = " + std::to_string(t0_) +
                                     " to tau = " + std::to_string(t));
    }
    for (std::size_t i = 0; i < N; ++i) out[i] = y[i];
    for (std::size_t i = 0; i < N; ++i) {
      if (!std::isfinite(out[i]))
        return StepResult::failure(
            StepFailure::non_finite_state,
            std::string(name) + ": non-finite state re-stepping to tau = " + std::to_string(t));
    }
    return StepResult::success();
  }

 private:
  using Base = HermiteSteps<System>;
  using Base::f0_;
  using Base::t0_;
  using Base::x0_;

  static const gsl_odeiv2_step_type* type() {
    return Method == GslMethod::rk8pd ? gsl_odeiv2_step_rk8pd : gsl_odeiv2_step_msbdf;
  }
  IntegratorOptions opt_;
  std::unique_ptr<gsl_odeiv2_system> system_;
  gsl_detail::DriverPtr driver_, refine_driver_;
  double h_;
};

}  // namespace ivv
