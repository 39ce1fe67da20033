#pragma once
/// Every contact interaction of a model as rows the analysis enforces and the results file
/// names: the *CONTACT PAIRs (model data first, then each step's), then the pairs general
/// contact (*CONTACT) expands to. One table, so the solver's pair rows, the results file's
/// /model/contact/pairs and the output requests agree.
///
/// General contact (inpact's expansion; Abaqus does not publish its own):
///   - *CONTACT INCLUSIONS, ALL EXTERIOR: the exterior faces of the model are split into bodies
///     (elements connected through shared nodes); every two bodies whose exterior surfaces are
///     named "BODY-k" (k by lowest element label; "<INSTANCE>.EXTERIOR" when a body is all of
///     one named instance) form an interaction. Self-contact within a body is not searched
///     (a note says so).
///   - `surf1, surf2`: an interaction between the two surfaces; `, surf2` (the all-inclusive
///     exterior against surf2): surf2 against every body's exterior that has none of surf2's
///     faces; `surf1,` (self-contact of surf1): one row of weight ½ (each contact is seen from
///     both sides), as a self-contact pair. ALL EXTERIOR does not search a body against itself:
///     a body one element thick would see its own far face as an overclosure.
///   - *CONTACT EXCLUSIONS remove the interactions between the surfaces they name.
///   - Each interaction takes the *SURFACE INTERACTION of the *CONTACT PROPERTY ASSIGNMENT that
///     names its two surfaces (in either order), else of the global assignment (blank surfaces),
///     else none (frictionless hard contact).
///   - Discretisation: surface to surface, finite sliding. Enforcement by penalty (Abaqus's
///     default for general contact) or any method the assigned *SURFACE BEHAVIOR asks for.
///   - Balanced master-slave: each interaction enforced by a penalty law (linear or nonlinear)
///     is two rows, each surface the slave of one, with weight ½ (each row's areas are halved,
///     so the two together carry the load once; CPRESS is reported on both surfaces). A method
///     with a multiplier per node (general_contact_one_row) gets one row, the surface with the
///     smaller facets as the slave (ties: the first named).
#include <cstddef>
#include <deque>
#include <memory>
#include <string>
#include <vector>

#include "model/model.hpp"

namespace inpact::contact {

struct ContactInteraction {
  /// The pair as the deck gives it, or the one general contact makes (slave, master,
  /// interaction, TYPE=SURFACE TO SURFACE, finite sliding, the *CONTACT line as loc).
  model::ContactPair pair;
  const model::Surface* slave = nullptr;   ///< into the model or the table's own surfaces
  const model::Surface* master = nullptr;
  std::size_t first_step = 0;  ///< the step (0-based) it enters; model data: 0
  bool general = false;        ///< made by general contact
  bool step_data = false;      ///< a *CONTACT PAIR of a step (not of the model data)
  double weight = 1.0;         ///< ½ for each row of a balanced (two-row) interaction, and for self-contact
  /// "SLAVE/MASTER", the name in /model/contact/pairs.
  std::string name() const { return pair.slave + "/" + pair.master; }
};

struct InteractionTable {
  std::vector<ContactInteraction> rows;
  std::deque<model::Surface> surfaces;  ///< the body exteriors general contact made
  std::vector<std::string> notes;       ///< what general contact leaves out (for check and run)
};

/// Is a general-contact interaction enforced by `method` one row (else two balanced rows)? Direct
/// enforcement and augmented Lagrange: both hold a multiplier per closed node (augmented
/// Lagrange's λ, raised by each augmentation until the penetration is within its tolerance), so
/// two rows would be two multipliers on one gap, and their split of the load is not determined:
/// direct's system would be singular, and augmented Lagrange's two rows — two springs of
/// 1000 k_e in parallel — share the load by the difference of the gaps the two discretisations
/// measure (k·Δg: 2.2e9 × 5e-8 ≈ 15 % of the pressure on the smoothed interference fit, each
/// row's CPRESS scattering −16 … +12 % while their sum is right). A penalty law is one spring
/// whose stiffness (10 k_e) keeps that split within its own error, and two rows make it
/// symmetric in the two surfaces. Laws stiffer than 1000 k_e go to multipliers after the rows
/// are made: merge_balanced_multiplier_rows in resolved_interaction.cpp.
inline bool general_contact_one_row(model::EnforcementMethod method) {
  return method == model::EnforcementMethod::Direct || method == model::EnforcementMethod::AugmentedLagrange;
}

/// The table of `model`. General contact needs the method of its interactions to choose
/// between one and two rows: resolved here with contact/normal_behavior.
std::shared_ptr<const InteractionTable> interaction_table(const model::Model& model);

}  // namespace inpact::contact
