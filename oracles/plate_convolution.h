// A second, independent implementation of the sphere-on-finite-plate impact (plate_impact.h):
// the plate under the impactor by the convolution of the contact force with the plate's
// impulse response at the impact point (a Volterra equation), marched on a fixed grid. No ODE
// integrator, no modal state: the modes enter only through the impulse response.
//
//   w(t) = int_0^t h(t - s) F(s) ds + C_res F(t),   h(t) = sum_k g_k sin(omega_k t)/omega_k  [m/N
//   s] m alpha'' = -F,   z = alpha - w,   F = f(z; history) >= 0
// (h is the displacement at (x0, y0) per unit impulse there, Duhamel's integral of each mode
// u_k'' + omega_k^2 u_k = g_k F; C_res the residual compliance of the modes not kept,
// plate_modes.h). On the grid t_n = n dt:
//   w_n = dt sum_{j<n} c_j h((n - j) dt) F_j + C_res F_n      (trapezoid rule: c_0 = 1/2, else 1;
//                                                            h(0) = 0 drops the j = n term)
//   alpha_{n+1} = alpha_n + dt v_n - (dt^2/2) F_n/m,  v_{n+1} = v_n - (dt/2)(F_n + F_{n+1})/m
// (velocity Verlet: second order, consistent with the trapezoid rule), and F_{n+1} solves
// F = f(alpha_{n+1} - w_mem - C_res F) on the law's branch (one monotone scalar equation,
// bisection-safeguarded Newton). Branches: a maximum of z between grid points begins unloading
// at the vertex of the parabola through the last three z (z_m to O(dt^3)); z above z_m on an
// unloading branch reloads (the loading history saved at z_m); z past a segment end enters the
// next segment; a force that would be negative ends the contact (F = 0, the end time by linear
// interpolation of F). Between contacts the force is zero and the response rings on.
//
// The motion ends when no further contact is possible: the ball receding (v < 0) beyond the
// largest excursion of the ringing plate, alpha + B < z_f, B = sum_k (g_k/omega_k) |int e^{-i
// omega_k s} F(s) ds| (each mode's free amplitude, the Fourier integral by the trapezoid rule),
// computed at every separation.
//
// Error: second order in dt for smooth forces; the kinks of the law (onset, z_y, separation)
// are passed between grid points and cost O(dt^2) each. The caller estimates the error by
// halving dt (Richardson); nothing here picks a tolerance.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "scene/scene.h"
#include "solver/laws/law_registry.h"
#include "solver/plate/plate_modes.h"

namespace ivv {

struct ConvolutionOptions {
  double dt = 0.0;            // grid step [s]
  double t_max = 1.0;         // give up beyond this time [s] (a named failure)
  bool residual = true;       // add C_res F (as PlateImpactOptions::dropped = static_compliance)
  bool record_force = false;  // keep the force at every grid point (ConvolutionResult::force)
};

struct ConvolutionContact {
  double t_start = 0.0, t_end = 0.0;  // [s]
  double peak_force = 0.0;            // [N]
};

struct ConvolutionResult {
  static constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  bool ok = false;
  std::string reason;
  double e = nan, e_first = nan, F_max = nan, t_contact = nan;
  std::vector<ConvolutionContact> contacts;
  long steps = 0;
  std::vector<double> force;  // with options.record_force: F [N] at t = n dt, n = 0, 1, ...
  double dt = nan;            // the grid step [s]
};

// The impact of the scene's impactor on the plate whose kept modes and residual compliance are
// `modes` (plate_modes() of the same plate), with a built-in rate-independent law. Throws
// InputError for what plate_impact.h refuses, std::invalid_argument for dt not > 0.
ConvolutionResult plate_impact_by_convolution(const Scene& scene, LawKind law,
                                              const LawParameters& parameters,
                                              const PlateModes& modes,
                                              const ConvolutionOptions& options);

}  // namespace ivv
