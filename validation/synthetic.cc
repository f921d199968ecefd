#include "validation/synthetic.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "validation/model_runs.h"
#include "validation/normal.h"

namespace ivv::validation {

std::vector<double> log_velocities(double lo, double hi, int n) {
  std::vector<double> v;
  for (int i = 0; i < n; ++i)
    v.push_back(n == 1 ? lo : lo * std::pow(hi / lo, static_cast<double>(i) / (n - 1)));
  return v;
}

MeasuredData synthetic_data(const SimulationRequest& request, const SyntheticSpec& spec) {
  SimulationRequest r = request;
  r.options.rtol = kSyntheticRtol;
  const auto points = run_model_points(r, {}, {}, spec.velocities, 0);
  MeasuredData d;
  d.source = "<synthetic>";
  std::ostringstream os;
  os.precision(6);
  os << "SYNTHETIC data (not a measurement): " << spec.description << "; e by ivv --model auto at "
     << "rtol " << kSyntheticRtol
     << (spec.noise ? " plus Gaussian noise of standard deviation "
                    : " without noise; stated u_e = ")
     << spec.u_e << (spec.noise ? ", seed " + std::to_string(spec.seed) : "");
  d.provenance.push_back(os.str());
  d.has_quantity[0] = true;
  d.has_uncertainty[0] = spec.state_uncertainty;
  StandardNormal normal(spec.seed);
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!points[i].result.ok())
      throw std::runtime_error(
          "synthetic data: the impact at v0 = " + std::to_string(spec.velocities[i]) +
          " m/s failed: " + points[i].result.reason);
    Measurement m;
    m.v0 = spec.velocities[i];
    const double noise = spec.noise ? spec.u_e * normal() : 0.0;
    m.value[0] = std::max(0.0, points[i].result.e + noise);
    if (spec.state_uncertainty) m.uncertainty[0] = spec.u_e;
    m.line = static_cast<int>(i) + 2;
    d.points.push_back(m);
  }
  return d;
}

}  // namespace ivv::validation
