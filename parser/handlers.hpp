#pragma once
/// The keyword groups; each function appends its keywords' specs to the table.
/// keyword_table.cpp calls them all, in one place.
#include <vector>

#include "keyword_spec.hpp"

namespace inpact::parser {

void add_mesh_keywords(std::vector<KeywordSpec>& table);      // kw_mesh.cpp
/// *SURFACE, TYPE=SEGMENTS | CYLINDER | REVOLUTION into `surf` (kw_analytical_surface.cpp; called by *SURFACE).
void analytical_surface(KeywordContext& ctx, model::Surface& surf, std::string_view type);
void add_assembly_keywords(std::vector<KeywordSpec>& table);  // kw_assembly.cpp
void add_material_keywords(std::vector<KeywordSpec>& table);  // kw_material.cpp, calls the one below
void add_hyperelastic_keyword(std::vector<KeywordSpec>& table);  // kw_hyperelastic.cpp
void add_orientation_keywords(std::vector<KeywordSpec>& table);  // kw_orientation.cpp
void add_load_keywords(std::vector<KeywordSpec>& table);      // kw_loads.cpp, calls the two below
void add_amplitude_keywords(std::vector<KeywordSpec>& table);  // kw_amplitude.cpp
void add_equation_keywords(std::vector<KeywordSpec>& table);   // kw_equation.cpp
void add_step_keywords(std::vector<KeywordSpec>& table);      // kw_step.cpp
void add_output_keywords(std::vector<KeywordSpec>& table);    // kw_output.cpp
void add_job_control_keywords(std::vector<KeywordSpec>& table);  // kw_job_control.cpp
void add_contact_keywords(std::vector<KeywordSpec>& table);   // kw_contact.cpp
void add_step_contact_keywords(std::vector<KeywordSpec>& table);  // kw_step_contact.cpp
void add_tie_keywords(std::vector<KeywordSpec>& table);       // kw_tie.cpp
void add_combined_hardening_keywords(std::vector<KeywordSpec>& table);  // kw_combined_hardening.cpp

/// *PLASTIC, HARDENING=COMBINED's data into `p` (kw_combined_hardening.cpp; called by *PLASTIC).
void combined_plastic(KeywordContext& ctx, model::Plastic& p);
/// *PLASTIC's rows (σ, ε̄ᵖ[, T]) into p.table, in blocks of one temperature; false on an error.
bool plastic_table(KeywordContext& ctx, model::Plastic& p);
void add_pretension_keywords(std::vector<KeywordSpec>& table);  // kw_pretension.cpp
void add_spring_keywords(std::vector<KeywordSpec>& table);    // kw_spring.cpp
void add_rigid_body_keywords(std::vector<KeywordSpec>& table);  // kw_rigid_body.cpp
void add_transform_keywords(std::vector<KeywordSpec>& table);   // kw_transform.cpp
void add_coupling_keywords(std::vector<KeywordSpec>& table);    // kw_coupling.cpp
void add_beam_section_keywords(std::vector<KeywordSpec>& table);  // kw_beam_section.cpp
void add_shell_section_keywords(std::vector<KeywordSpec>& table);  // kw_shell_section.cpp
/// *TRANSVERSE SHEAR STIFFNESS under a shell section (kw_shell_section.cpp; called by the
/// keyword's handler in kw_beam_section.cpp, which owns it).
void shell_transverse_shear_stiffness(KeywordContext& ctx);

}  // namespace inpact::parser
