/// The one table of keywords inpact understands, built from the keyword groups in order.
#include <algorithm>
#include <iterator>

#include "handlers.hpp"
#include "text.hpp"

namespace inpact::parser {

std::span<const KeywordSpec> keyword_table() {
  static const std::vector<KeywordSpec> table = [] {
    std::vector<KeywordSpec> t;
    add_mesh_keywords(t);
    add_assembly_keywords(t);
    add_material_keywords(t);
    add_orientation_keywords(t);
    add_load_keywords(t);
    add_step_keywords(t);
    add_output_keywords(t);
    add_job_control_keywords(t);
    add_contact_keywords(t);
    add_step_contact_keywords(t);
    add_tie_keywords(t);
    add_combined_hardening_keywords(t);
    add_pretension_keywords(t);
    add_spring_keywords(t);
    add_rigid_body_keywords(t);
    add_transform_keywords(t);
    add_coupling_keywords(t);
    add_beam_section_keywords(t);
    add_shell_section_keywords(t);
    return t;
  }();
  return table;
}

bool is_unsupported_abaqus_keyword(std::string_view normalized_name) {
  // Abaqus keywords a deck may well contain that inpact cannot honour yet: saying so beats
  // "unknown keyword" (and beats silently ignoring them, which would change the answer).
  static constexpr std::string_view kUnsupported[] = {
      "DYNAMIC", "FREQUENCY", "BUCKLE", "HEATTRANSFER", "COUPLEDTEMPERATURE-DISPLACEMENT",
      "VISCO", "MODALDYNAMIC", "STEADYSTATEDYNAMICS", "EXPLICIT", "SOILS",
      "MEMBRANESECTION", "COHESIVESECTION", "HYPERFOAM", "VISCOELASTIC", "CREEP",
      "DAMAGEINITIATION", "USERMATERIAL", "DEPVAR", "CONDUCTIVITY", "SPECIFICHEAT",
      "MASS", "DASHPOT", "CONNECTORSECTION",
      "IMPORT", "SUBMODEL", "SFILM", "FILM", "CFLUX", "DFLUX", "GAP"};
  return std::find(std::begin(kUnsupported), std::end(kUnsupported), normalized_name) != std::end(kUnsupported);
}

}  // namespace inpact::parser
