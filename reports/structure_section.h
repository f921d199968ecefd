// The report's section "Damping from the structure" (docs/design.md §1), drawn from the structure
// study (verification/study_structure.h), the data the structure.* cases judge. Nothing here
// simulates: it formats.
//
//   * e against Zener's lambda for the Hertz law (simulated curve), with the small-lambda
//     asymptote 1 - a lambda (a by quadrature, oracles/zener.h), the similarity scenes and the
//     three quoted values as points: cases structure.zener.*.
//   * e against the plate thickness for the paper's impactor (elastoplastic law, T300/934
//     plate dashpot) at 1 and 5 m/s, the plate's properties stated beside the plot: cases
//     structure.laminate.*.
#pragma once

#include <string>
#include <vector>

#include "reports/figure.h"

namespace ivv::reports {

struct StructureSection {
  std::vector<Figure> figures;  // [0]: e(lambda), [1]: e(h)
  std::string intro_html;       // what the section shows and the answer for zeta = 0.1
  std::string similarity_table_html;
  std::string plate_properties_html;
};

// Throws verification::StudyError if the structure study failed.
StructureSection structure_section(const SectionOptions& options);

}  // namespace ivv::reports
