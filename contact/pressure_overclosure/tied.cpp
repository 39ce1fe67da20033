#include "contact/pressure_overclosure/tied.hpp"

#include <fmt/format.h>

namespace inpact::contact {

std::string TiedLaw::describe() const { return fmt::format("tied (CalculiX), k = {:.4g}, tension included", k_); }

}  // namespace inpact::contact
