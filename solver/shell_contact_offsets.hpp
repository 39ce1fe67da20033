#pragma once
/// Contact on shells (Abaqus's default, [K16 *CONTACT PAIR], NO THICKNESS): a surface on shell
/// faces makes contact on the shell's face, not at its nodes. The face lies along its outward
/// normal from the nodes by (½ − o)·t for SPOS and (½ + o)·t for SNEG, with t the element's
/// thickness and o the section's OFFSET (model::ShellSection::offset). Both surfaces' distances
/// come off the pair's measured gap; the gap's gradient does not change (a constant shift along
/// the normal, as the shell's own rotation of the offset is left out: small rotations).
#include <vector>

#include "contact/pair_kinematics.hpp"
#include "model/model.hpp"

namespace inpact::solver {

/// Throws AnalysisError (the pair's line) when the pair's master lies on shell faces at different
/// distances from their nodes: one distance per master is what inpact supports yet. Nothing to
/// check with NO THICKNESS.
void check_shell_master(const model::Model& model, const model::ContactPair& pair, const model::Surface& master);

/// Per slave node (slave().nodes() order), what is added to the gap: −(the slave's face distance
/// at the node, the mean over its shell facets, + the master's). Empty when neither surface is on
/// shells or the pair has NO THICKNESS. The master passed check_shell_master.
std::vector<double> shell_thickness_offsets(const model::Model& model, const model::ContactPair& pair,
                                            const contact::PairKinematics& geometry);

}  // namespace inpact::solver
