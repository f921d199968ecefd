#include "solver/infinite_plate_check.h"

#include <sstream>

namespace ivv {

std::vector<std::string> infinite_plate_warnings(const Scene& scene, const ImpactResult& r) {
  std::vector<std::string> out;
  const Structure& st = scene.damping.structure;
  // a finite plate is modelled as one (solver/plate/): its answer needs no such warning
  if (scene.damping.kind != Damping::Kind::structure || !st.has_plate() || st.finite_plate() ||
      !r.ok())
    return out;
  const double h = st.thickness;
  const std::string advice =
      "; give the plate's size (structure.length_x, structure.length_y, edges) to model the "
      "finite plate";
  if (r.y_final > h) {
    std::ostringstream os;
    os.precision(3);
    os << "the infinite plate under the ball moved y = " << r.y_final * 1e3 << " mm, "
       << r.y_final / h << " times its thickness h = " << h * 1e3
       << " mm: the plate dashpot c = 8 sqrt(rho h D) assumes deflections well below h (thin-plate "
          "bending, no membrane stretching, no wave returning from an edge)"
       << advice;
    out.push_back(os.str());
  }
  if (r.status == ImpactStatus::captured) {
    out.push_back(
        "captured by an infinite plate, which carries the impactor's momentum away for ever: a "
        "plate of finite size keeps that energy in its modes and gives part of it back (a "
        "rebound or repeated contacts)" +
        advice);
  }
  return out;
}

}  // namespace ivv
