// Model comparison: several laws fitted to the same data, ranked by the
// information criteria of their least-squares fits.
//
// With stated standard uncertainties the Gaussian log-likelihood is -chi^2/2 up to a constant
// shared by every model of the same data, so (Akaike 1974; Schwarz 1978)
//     AIC = chi^2 + 2k,      BIC = chi^2 + k ln n,
// k the number of directions in parameter space the data determine (the rank of the fit's
// Jacobian: p minus the unidentifiable directions, so a parameter without effect costs nothing
// and two parameters only whose product is determined count once), n the number of residuals. When
// the noise was estimated from the residuals (no u_ columns), chi^2 is not a likelihood; the
// criteria use the residual sum of squares of the unweighted residuals instead (Burnham & Anderson
// 2002, eq. 2.2): AIC = n ln(RSS/n) + 2k, BIC = n ln(RSS/n) + k ln n (and a mixture of stated and
// estimated noise uses the stated-uncertainty form with the estimated sigmas).
// Ranking: by AIC, lowest first; Delta = AIC - AIC_min. A model with Delta > 10 has
// "essentially no support" against the best (Burnham & Anderson 2002, §2.6). A fit that failed
// is listed last with its reason, never ranked.
#pragma once

#include <string>
#include <vector>

#include "validation/calibration.h"

namespace ivv::validation {

inline constexpr double kNoSupport = 10.0;  // Delta AIC beyond which a model has no support

struct RankedModel {
  std::string name;  // e.g. "elastoplastic", or the expression
  CalibrationResult fit;
  int k = 0;  // determined directions (CalibrationResult::determined)
  double aic = 0.0, bic = 0.0;
  double delta_aic = 0.0;
  int rank = 0;  // 1 = best; 0 for a failed fit
};

struct ModelRanking {
  std::vector<RankedModel> models;  // ranked, failed fits last
  const RankedModel* best() const;
  std::string table() const;  // plain text for the terminal
};

// Ranks already-fitted models of the same data (same residual count; otherwise
// std::invalid_argument). `names` label the fits.
ModelRanking compare(std::vector<std::string> names, std::vector<CalibrationResult> fits);

}  // namespace ivv::validation
