// The paper's figures as a study (see verification/study.h): every run behind Figs 2-14 of the
// paper, computed once per process, judged by the trend.paper.* cases (cases_trends.cc) and
// drawn by the report's section 2 (reports/paper_figures.h).
//
// Scene: Table 1 (paper_scene(): m = 0.5 kg, R = 10 mm, steel on T300/934, S_y = 202 MPa),
// elastoplastic law, odeint-dopri5 at rtol 1e-12, atol 1e-14 (kTrendRtol: e, F_max, times to
// ~1e-11 relative). SI units throughout (s, m, N, kg, m/s).
//   Figs 2-7   v0 = 0.1, 1, 5 m/s with the paper's dashpot c = 11440 N s/m (zeta ~ 0.1): the
//              model, the linearized closed form (closed_forms/linear_model.h, undefined at 0.1
//              m/s) and Hunt-Crossley fitted to the model's F_max and e (fit_hunt_crossley).
//   Fig 8      S_y = 50.5, 101, 151.5, 202, 404 MPa at 1 m/s, c held.
//   Fig 9      m = 0.125 ... 2 kg at 1 m/s, c held.
//   Figs 10-11 v0 = 0.1, 0.5, 1, 2, 5 m/s at zeta = 0.1.
//   Figs 12-13 zeta = 0, 0.05, 0.1, 0.2, 0.3, 0.5 at 1 m/s.
//   Fig 14     e on 40 log-spaced v0 in [0.01, 10] m/s x zeta = 0, 0.05, 0.1, 0.2, 0.3, 0.5.
// A run the figures need that fails makes the study fail (StudyError naming it), except the
// Fig 14 grid, whose failed points are kept with their reason for the case to report.
#pragma once

#include <string>
#include <vector>

#include "closed_forms/linear_model.h"
#include "solver/fit_hunt_crossley.h"
#include "solver/simulate.h"

namespace ivv::verification {

// The paper's dashpot of Figs 2-9 [N s/m]; with Table 1 it gives zeta ~ 0.1.
inline constexpr double kPaperDashpot = 11440.0;

// The Table 1 scene at v0 with the paper's dashpot c = 11440 N s/m.
Scene paper_with_dashpot(double v0);

struct PaperRun {
  std::string label;  // for legends, e.g. "S_y = 50.5 MPa"
  Scene scene;
  ImpactResult result;
  std::vector<TrajectoryPoint> trajectory;  // thinned to at most 1500 points
};

// The linearized closed form over its contact, or why it is undefined.
struct LinearizedCurve {
  bool defined = false;
  double z_reached = 0.0;  // undefined: z_m of the loading phase [m]
  double z_needed = 0.0;   // undefined: (K_y/K_h)^2 = 2.25 z_y [m]
  closed_forms::LinearImpact solution;
  std::vector<double> t, alpha, force;  // 601 samples [s, m, N] (to 10 t_m when captured)
};

// Figs 2-7 at one velocity.
struct PaperResponse {
  double v0 = 0.0;
  PaperRun model;          // elastoplastic with c = 11440 N s/m
  HuntCrossleyFit fit;     // Hunt-Crossley (no dashpot) with the model's F_max and e
  PaperRun hunt_crossley;  // the fitted Hunt-Crossley run
  LinearizedCurve linearized;
};

struct PaperStudy {
  std::vector<PaperResponse> responses;  // Figs 2-7: v0 = 0.1, 1, 5 m/s
  std::vector<double> yield_strengths;   // Fig 8 [Pa]
  std::vector<PaperRun> by_yield_strength;
  std::vector<double> masses;  // Fig 9 [kg]
  std::vector<PaperRun> by_mass;
  std::vector<double> velocities;  // Figs 10-11 [m/s], zeta = 0.1
  std::vector<PaperRun> by_velocity;
  std::vector<double> zetas;  // Figs 12-13, v0 = 1 m/s
  std::vector<PaperRun> by_zeta;
  // Fig 14
  std::vector<double> fig14_velocities, fig14_zetas;
  std::vector<std::vector<ImpactResult>> fig14;  // fig14[i_zeta][i_v0]

  // Every run with a dashpot (Figs 2-13), for the claims that hold for all of them.
  std::vector<const PaperRun*> damped_runs() const;
};

const PaperStudy& paper_study();

}  // namespace ivv::verification
