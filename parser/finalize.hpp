#pragma once
/// After the last line: resolve what could refer forward (element nodes, materials,
/// interactions, surfaces), check the deck is complete, and hand the mesh to the model.
#include "build_state.hpp"
#include "diagnostics.hpp"

namespace inpact::parser {

/// Resolves element node labels that were not yet defined when the element was read.
void resolve_pending_nodes(MeshBuild& build, Diagnostics& diags);

/// Truss and spring sections against the mesh (check_line_elements.cpp); marks the elements a
/// *SPRING covers in `has_section` (element rows).
void check_line_element_sections(const model::Model& m, Diagnostics& diags, std::vector<std::uint8_t>& has_section);

/// Beam sections against the mesh (beam_nodes.cpp); marks their elements in `has_section`.
void check_beam_sections(const model::Model& m, Diagnostics& diags, std::vector<std::uint8_t>& has_section);

/// Shell sections against the mesh, and each element's thickness from *NODAL THICKNESS where
/// the section asks for it (shell_sections.cpp); marks their elements in `has_section`.
void check_shell_sections(const model::Model& m, Diagnostics& diags, std::vector<std::uint8_t>& has_section);

/// Gives every beam and shell node a rotation node (model::Model::node_rotations), after rigid
/// bodies and couplings have theirs (a reference node on a beam or shell keeps its own)
/// (rotation_nodes.cpp).
void add_rotation_nodes(model::Model& m);

/// *MPC TIE: the rotations of each pair whose two nodes both have them (beam and shell nodes),
/// as *EQUATIONs θ_dep − θ_ind = 0 on DOFs 4–6 (DOF 6 in 2D). After add_rotation_nodes
/// (rotation_nodes.cpp).
void tie_mpc_rotations(model::Model& m);

void finalize_model(BuildState& state, Diagnostics& diags);

}  // namespace inpact::parser
