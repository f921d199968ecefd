// Options shared by every integrator. Tolerances apply to the normalised state of
// impact_system.h (velocities in units of v0, displacements in v0/omega, time in 1/omega, with
// the law's own omega: omega0 = sqrt(K_y/m*) for laws with yield, v0/z_mH for Hertz and
// Hunt-Crossley; Scene ScaleBasis), so a tolerance means the same thing for a 1 mg bead at
// 1e-6 m/s and a 1 t mass at 100 m/s, and for every law. In either basis a contact lasts
// tau = O(1) (Hertz: 2.94; elastoplastic at v0 = v_y: 4.0), which tau_max, initial_dt and dt
// below assume.
#pragma once

#include <optional>
#include <string>

#include "solver/driver/event_locator.h"
#include "solver/steppers/machine_code.h"

namespace ivv {

struct IntegratorOptions {
  double rtol = 1e-10;         // relative error per step (adaptive integrators)
  double atol = 1e-12;         // absolute error per step, normalised units
  double dt = 0.0;             // fixed step in tau: rk4, and dp45 with fixed_step (0 = default)
  bool fixed_step = false;     // steppers with traits().fixed_step_mode: no error control
  double initial_dt = 1e-4;    // first trial step in tau (adaptive integrators)
  long max_steps = 2'000'000;  // accepted steps per impact before giving up
  double tau_max = 1e8;        // normalised time limit before giving up
  bool locate_events = true;   // false: events detected only at step ends (demonstrations)
  // Start dop853, dp45 and rodas4 past contact onset from the series of
  // solver/driver/onset_series.h (laws with a Hertzian onset), where it is accurate to rtol: the
  // steps that leave the z^{3/2} onset are not taken; and end an elastic contact (a Hertzian
  // unloading branch with no permanent set) by the same series run backwards from the
  // separation (solver/driver/end_series.h): the steps into the (tau_f - tau)^{5/2} end are not
  // taken either; and cross a loading segment linear in z in closed form
  // (solver/driver/linear_phase.h: the elastoplastic law's region II). false: integrate from
  // tau = 0 to the located separation (the speed study's "before").
  bool onset_series = true;
  // Post-run check that the three CORs and the energy ledger agree within what rtol/atol
  // allow (solver/consistency.h); a run that does not is a failure with the reason. Off only
  // for studies that measure the error of deliberately coarse runs (convergence order).
  bool check_consistency = true;
  // Declare capture (no rebound, e = 0) once the rebound COR still attainable from the
  // remaining energy, sqrt(w^2 + 2 U), is below this.
  double capture_cor = 1e-9;
  // Also declare capture, with e = 0 exactly, as soon as the state is inside the invariant
  // region of ImpactSystem::capture_margin (where the impactor provably never turns back), so
  // the creep towards the permanent set is not integrated. false: capture by capture_cor only
  // (the verification case that checks the region integrates on with it).
  bool exact_capture = true;
  // rtol = atol of the 50-digit reference (mp50); errors of double-precision integrators
  // (>= 1e-16) are measured against it, so 1e-26 leaves ten digits to spare.
  double reference_tolerance = 1e-26;
  LocatorOptions locator;
  // The machine code of the run (solver/steppers/machine_code.h): fastest takes the AVX2 + FMA
  // copy where the CPU has it and the run has one (dop853 with the elastoplastic or Hertz law),
  // whose last bits differ from the baseline's within the stated error; baseline reproduces the
  // x86-64 baseline bit for bit (as does IVV_MACHINE_CODE=baseline for the whole process).
  MachineCode machine_code = MachineCode::fastest;

  // Default fixed step in tau for rk4: its global error ~ C h^4 with C = O(1) in the
  // normalised variables on the smooth phases, plus O(h^{5/2}) from the step at onset, where
  // F ~ z^{3/2} is not smooth (measured 1.2e-10 to 3.9e-10 in F_max at h = 1e-3).
  static constexpr double default_fixed_dt = 1e-3;
  double fixed_dt() const { return dt > 0 ? dt : default_fixed_dt; }

  // What is wrong with one option: the flag the user types and the accepted range.
  struct Invalid {
    std::string field;    // e.g. "--rtol"
    std::string message;  // e.g. "must lie in [1e-15, 1e-2] (got 1)"
  };
  bool operator==(const IntegratorOptions&) const = default;

  // nullopt when valid; else the first invalid option.
  std::optional<Invalid> invalid() const;
  // "" when valid; else "<field> <message>".
  std::string invalid_reason() const;
};

}  // namespace ivv
