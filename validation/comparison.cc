#include "validation/comparison.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace ivv::validation {
namespace {

// -2 ln L up to the shared constant: chi^2, or n ln(RSS/n) when every sigma was estimated.
double deviance(const CalibrationResult& fit) {
  if (fit.p_value || fit.estimated_noise.size() != 1) return fit.chi2;
  double rss = 0;
  for (const auto& r : fit.residuals) rss += std::pow(r.model - r.measured, 2);
  const double n = static_cast<double>(fit.residuals.size());
  return n * std::log(rss / n);
}

}  // namespace

const RankedModel* ModelRanking::best() const {
  return !models.empty() && models.front().rank == 1 ? &models.front() : nullptr;
}

ModelRanking compare(std::vector<std::string> names, std::vector<CalibrationResult> fits) {
  if (names.size() != fits.size()) throw std::invalid_argument("compare: one name per fit");
  ModelRanking c;
  for (std::size_t i = 0; i < fits.size(); ++i) {
    RankedModel m;
    m.name = names[i];
    m.fit = std::move(fits[i]);
    if (m.fit.ok) {
      if (!c.models.empty() && c.models.front().fit.ok &&
          c.models.front().fit.points != m.fit.points)
        throw std::invalid_argument("compare: the fits are not of the same data");
      m.k = m.fit.determined;
      const double n = m.fit.points, dev = deviance(m.fit);
      m.aic = dev + 2.0 * m.k;
      m.bic = dev + m.k * std::log(n);
    }
    c.models.push_back(std::move(m));
  }
  std::stable_sort(c.models.begin(), c.models.end(),
                   [](const RankedModel& a, const RankedModel& b) {
                     if (a.fit.ok != b.fit.ok) return a.fit.ok;
                     return a.fit.ok && a.aic < b.aic;
                   });
  int rank = 0;
  for (auto& m : c.models)
    if (m.fit.ok) {
      m.rank = ++rank;
      m.delta_aic = m.aic - c.models.front().aic;
    }
  return c;
}

std::string ModelRanking::table() const {
  std::ostringstream os;
  os.precision(5);
  os << "rank  model                      k   chi^2/dof     AIC   dAIC     BIC\n";
  for (const auto& m : models) {
    if (!m.fit.ok) {
      os << "  -   " << m.name << ": fit failed: " << m.fit.failure << '\n';
      continue;
    }
    char line[256];
    std::snprintf(line, sizeof line, "%4d  %-25.25s %2d  %10.4g  %7.2f %6.2f  %7.2f%s\n", m.rank,
                  m.name.c_str(), m.k, m.fit.chi2_per_dof(), m.aic, m.delta_aic, m.bic,
                  m.delta_aic > kNoSupport ? "  (no support against the best)" : "");
    os << line;
  }
  return os.str();
}

}  // namespace ivv::validation
