#include "solution_controls.hpp"

namespace inpact::solver {

namespace {
template <class T>
void take(const model::ControlFields& fields, std::size_t index, T& target) {
  if (index < fields.size() && fields[index]) target = static_cast<T>(*fields[index]);
}
}  // namespace

SolutionControls solution_controls(const model::Step& step) {
  SolutionControls c;
  if (const auto& f = step.controls.field) {
    take(f->values, 0, c.residual_tolerance);
    take(f->values, 1, c.correction_tolerance);
    take(f->values, 5, c.zero_force);
    take(f->values, 7, c.linear_tolerance);
  }
  if (const auto& t = step.controls.time_incrementation) {
    take(t->line1, 0, c.divergence_check_after);
    take(t->line1, 3, c.max_iterations);
    take(t->line1, 5, c.easy_iterations);
    take(t->line1, 7, c.max_cutbacks);
    take(t->line1, 12, c.max_augmentations);
    take(t->line2, 0, c.cutback_factor);
    take(t->line2, 6, c.growth_factor);
  }
  return c;
}

}  // namespace inpact::solver
