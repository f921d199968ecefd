// Where the infinite plate's dashpot stops describing the struck plate, said beside the answer.
//
// A [structure] plate given without its size is the paper's idealisation (after its eq. 4): an
// infinite thin plate, whose flexural waves never return, acting on the contact as the dashpot
// c = 8 sqrt(rho h D*). The dashpot's end moves with the plate under the ball, by y (a maximum
// y_final, the last value: y only grows, since c dy/dt = F >= 0). Two outcomes say that the
// idealisation has been left, and the run's answer is then reported with a warning:
//
//   deflection   y_final > h: the plate under the ball moved more than its own thickness. The
//                dashpot is derived from Kirchhoff's small-deflection theory (bending only),
//                which needs deflections well below the thickness; beyond it membrane
//                stretching stiffens the plate (S. Timoshenko, S. Woinowsky-Krieger, Theory of
//                Plates and Shells, 2nd ed., McGraw-Hill 1959, ch. 1 and §96 on large
//                deflections), and a plate that bends that far under a heavy impactor is
//                usually a plate whose edges reflect the waves back during the contact.
//   capture      e = 0 on a plate: the infinite plate carries the impactor's momentum away for
//                ever, so the ball can sink with it; a plate of any finite size stores that
//                energy in its modes and gives part of it back (a rebound, or repeated
//                contacts), which only the finite plate (structure.length_x, length_y) models.
//
// Example: a 5.5 kg striker at 2 m/s on a 4 mm carbon/epoxy laminate given without its size is
// captured with y_final = 32 mm = 8 h; a drop-weight test on such a coupon rebounds.
#pragma once

#include <string>
#include <vector>

#include "scene/scene.h"
#include "solver/result.h"

namespace ivv {

// The warnings of the header for a run of `scene` (none when the scene has no plate dashpot, its
// plate is finite, or the run failed). Each is one sentence with the measured values and what to
// do.
std::vector<std::string> infinite_plate_warnings(const Scene& scene, const ImpactResult& result);

}  // namespace ivv
