#include "pretension.hpp"

namespace inpact::solver {

double pretension_force(const AnalysisModel& am, const model::PretensionSection& s, std::span<const double> f_int,
                        std::span<const double> f_ext) {
  double n_force = 0.0;
  for (const auto& pair : s.node_pairs)
    for (int c = 0; c < am.dim; ++c) {
      const std::size_t d = static_cast<std::size_t>(pair[1]) * am.dim + c;
      n_force += s.normal[c] * (f_int[d] - f_ext[d]);
    }
  return n_force;
}

void report_pretension_forces(const AnalysisModel& am, std::span<const double> f_int, std::span<const double> f_ext,
                              std::vector<double>& rf) {
  for (const model::PretensionSection& s : am.model->pretension_sections)
    rf[static_cast<std::size_t>(s.node) * am.dim] = pretension_force(am, s, f_int, f_ext);
}

}  // namespace inpact::solver
