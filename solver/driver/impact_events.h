// The events of one impact as data: a root function g(x) of the normalised state
// (impact_system.h), a direction, and what the event means to the driver (docs/design.md §1). The
// driver (impact_driver.h) hands the active roots to the shared locator (event_locator.h:
// locate_earliest), which knows roots and directions only, and acts on the rows' meanings.
//
//   event             root g(x)                              direction  meaning
//   yield             z - z_end (z_end = law_segment_end)     rising     next loading segment
//   max_compression   dz/dtau                                 falling    begin unloading at z_m
//   max_displacement  w = dalpha/dtau                         falling    record alpha_c
//   peak_force        dF/dtau (rate-dependent laws)           falling    record F_max
//   separation        F, or z for a law that allows tension,  falling    end of contact
//                     or z - z_perm for a law that declares
//                     separates_at_z_perm (law.h)
//
// A law declares its own events, its kinks, through segment_end(h) (law.h): every loading
// segment that ends is a yield row whose root is z minus that end, and next_segment(h) enters
// the next piece. Onset is the initial state (alpha = 0, w = 1) and capture is not a root but
// one of the criteria of capture.h, checked after each unloading step.
//
// The separation root z - z_perm vanishes where F does and has its sign (the law declares so),
// but it is smooth in tau where F is not: at an elastic end (z_perm = 0) F ~ (tau_f - tau)^{3/2}
// on one side and its continuation -(tau - tau_f)^{3/2} on the other, on which the secant
// iterations of the root finder converged slowly (paper map, 60 x 60, rtol 1e-8: 12.1 root
// evaluations per separation, up to 41, against 4.6-6.1 for the other events); z - z_perm is
// also cheaper to evaluate than the law's force.
//
// When each row is active, and whether its root is monotone over a step (the signs at the
// step's ends then decide whether it crossed):
//   yield             loading, while the law has a segment end; monotone on a step with
//                     dz/dtau > 0 at both ends (while z' > 0, z'' = -F - 2 zeta F_z z' < 0, so
//                     z' cannot dip below 0 and come back), probed otherwise (the spring may
//                     pass z_y and come back within one step near maximum compression)
//   max_compression   loading; monotone (z'' < 0 while z' > 0, and z' = w without dashpot)
//   max_displacement  until found; monotone (w' = -F <= 0 during contact)
//   peak_force        rate-dependent laws, until found; not monotone, probed
//   separation        unloading; monotone for rate-independent laws without tension (F falls
//                     with z and z' < 0 on unloading: no reloading during one contact, SPEC
//                     §1), probed otherwise (Hunt-Crossley, tension laws)
#pragma once

#include <array>
#include <cstddef>
#include <string_view>

#include "solver/driver/event_locator.h"
#include "solver/laws/law.h"
#include "solver/result.h"

namespace ivv {

// What an event means to the driver. The driver acts on this, never on the event's name.
enum class EventAction {
  next_segment,       // the law's loading segment ends at a kink: enter the next segment
  begin_unloading,    // maximum compression: record z_m (and F_max when rate-independent),
                      // switch the law to its unloading branch
  record_alpha_max,   // record alpha_c and the state there (compression/restitution split)
  record_peak_force,  // record F_max and its time (rate-dependent laws)
  end_contact,        // the contact ends (separation)
};

// True when the law's branch changes at the event: the step cannot go on past it.
constexpr bool changes_branch(EventAction a) {
  return a == EventAction::next_segment || a == EventAction::begin_unloading;
}

struct ImpactEventRow {
  EventKind kind;
  Direction direction;
  EventAction action;
};

// The table above, in the order of EventKind from yield to separation.
inline constexpr std::array<ImpactEventRow, 5> kImpactEvents = {{
    {EventKind::yield, Direction::rising, EventAction::next_segment},
    {EventKind::max_compression, Direction::falling, EventAction::begin_unloading},
    {EventKind::max_displacement, Direction::falling, EventAction::record_alpha_max},
    {EventKind::peak_force, Direction::falling, EventAction::record_peak_force},
    {EventKind::separation, Direction::falling, EventAction::end_contact},
}};

constexpr const ImpactEventRow& event_row(EventKind k) {
  return kImpactEvents[static_cast<std::size_t>(k) - static_cast<std::size_t>(EventKind::yield)];
}
static_assert(event_row(EventKind::yield).kind == EventKind::yield &&
                  event_row(EventKind::separation).kind == EventKind::separation,
              "kImpactEvents follows the order of EventKind");

// The root function of event `k` at normalised state s, on the system's current branch. It
// reads only System::event_components of s (z and w), which is all the locator interpolates.
template <class System>
typename System::value_type event_root(EventKind k, const System& sys,
                                       const typename System::state_type& s) {
  using T = typename System::value_type;
  switch (k) {
    case EventKind::yield:
      return sys.z(s) - T(*law_segment_end(sys.law, sys.branch) / sys.length);
    case EventKind::max_compression:
      return sys.z_rate(s);
    case EventKind::max_displacement:
      return s[System::W];
    case EventKind::peak_force:
      return sys.force_rate(s);
    default:  // separation: F = 0, or z = 0 for a law that allows tension
      if (sys.tension) return sys.z(s);
      if constexpr (law_separates_at_z_perm<typename System::law_type>())
        return sys.z(s) - T(sys.branch.z_perm / sys.length);
      return sys.force(s);
  }
}

// The same root at a state s whose derivative f = ds/dtau on the current branch the stepper has
// already computed (a step's end, the first stage of the next step): maximum compression's
// dz/dtau and separation's F are components of f (ImpactSystem::operator(): f[Z] = w - 2 zeta
// F, f[J] = F; without a dashpot z' = f[A] = w), the same expressions event_root evaluates,
// bit for bit, without evaluating the law again. The other roots (and separation's z - z_perm)
// as event_root.
template <class System>
typename System::value_type event_root_at(EventKind k, const System& sys,
                                          const typename System::state_type& s,
                                          const typename System::state_type& f) {
  if (k == EventKind::max_compression) return f[System::has_dashpot ? System::Z : System::A];
  if constexpr (!law_separates_at_z_perm<typename System::law_type>())
    if (k == EventKind::separation && !sys.tension) return f[System::J];
  return event_root(k, sys, s);
}

// The events active on one step, at most four (loading: yield, max_compression,
// max_displacement, peak_force; unloading: max_displacement, peak_force, separation).
struct ActiveEvents {
  static constexpr std::size_t capacity = 4;
  RootSet<capacity> roots;
  std::array<EventKind, capacity> kinds{};
  int size() const { return roots.size; }
  void add(EventKind k, bool monotone) {
    kinds[roots.size] = k;
    roots.add({event_row(k).direction, monotone});
  }
};

// What the driver has already found in this impact (events that fire once).
struct EventsFound {
  bool max_displacement = false;
  bool peak_force = false;
};

// The events active on a step from state x0 to x1 on the system's current branch (table above).
template <class System>
ActiveEvents active_events(const System& sys, const EventsFound& found,
                           const typename System::state_type& x0,
                           const typename System::state_type& x1) {
  ActiveEvents a;
  const bool loading = sys.branch.phase == Phase::loading;
  if (loading && law_segment_end(sys.law, sys.branch)) {
    const bool z_rising = sys.z_rate(x0) > 0 && sys.z_rate(x1) > 0;
    a.add(EventKind::yield, z_rising);
  }
  if (loading) a.add(EventKind::max_compression, true);
  if (!found.max_displacement) a.add(EventKind::max_displacement, true);
  if (System::rate_dependent && !found.peak_force) a.add(EventKind::peak_force, false);
  if (!loading) a.add(EventKind::separation, !System::rate_dependent && !sys.tension);
  return a;
}

}  // namespace ivv
