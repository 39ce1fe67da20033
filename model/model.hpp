#pragma once
/// The model database: plain data filled by parser/ once, then read-only (const Model&).
/// Everything that changes during an analysis lives in the solver's own state.
#include <map>
#include <string>
#include <vector>

#include "analytical_surface.hpp"
#include "contact.hpp"
#include "coupling.hpp"
#include "element_types.hpp"
#include "loads.hpp"
#include "material.hpp"
#include "mesh.hpp"
#include "rigid_body.hpp"
#include "source_loc.hpp"
#include "step.hpp"
#include "transform.hpp"

namespace inpact::model {

/// A beam or shell node and the node inpact added to hold its rotations θ1..θ3 (a rigid body's
/// or coupling's reference node keeps the rotation node it has).
struct NodeRotation {
  std::int32_t node = -1;
  std::int32_t rot_node = -1;
};

struct Model {
  SourceTable sources;
  std::string heading;

  /// Abaqus instance names; instances[0] is "" (the deck without parts, or the assembly's own
  /// nodes). Node and element rows carry their instance index.
  std::vector<std::string> instances{""};
  Mesh mesh;

  std::map<std::string, Material> materials;  ///< key: upper-case name
  std::map<std::string, Orientation> orientations;  ///< *ORIENTATION; key: upper-case name
  std::map<std::string, Amplitude> amplitudes;
  std::vector<Equation> equations;
  std::vector<MpcTie> mpc_ties;  ///< *MPC TIE node pairs, for their rotations
  std::vector<Tie> ties;  ///< *TIE, one per data line, in deck order
  std::vector<PretensionSection> pretension_sections;  ///< in deck order
  std::vector<RigidBody> rigid_bodies;                 ///< *RIGID BODY, in deck order
  std::vector<Coupling> couplings;                     ///< *COUPLING, in deck order
  std::vector<NodalTransform> transforms;         ///< *TRANSFORM, in deck order
  std::vector<TransformedNode> transformed_nodes;  ///< the nodes whose DOFs are local, by node row
  /// Every node of a beam or shell element with its rotation node, by node row
  /// (parser/beam_nodes.cpp).
  std::vector<NodeRotation> node_rotations;
  /// *SURFACE, TYPE=SEGMENTS | CYLINDER | REVOLUTION, in deck order (Surface::analytical).
  std::vector<AnalyticalSurface> analytical_surfaces;

  // Initial (model-level) conditions, in force from the first step on.
  std::vector<BoundaryBlock> boundaries;
  std::vector<TemperatureEntry> initial_temperatures;
  std::vector<InitialPlasticStrain> initial_plastic_strains;

  // Contact.
  std::map<std::string, SurfaceInteraction> interactions;
  std::vector<ContactPair> contact_pairs;
  GeneralContact general_contact;
  std::map<std::string, SurfaceSmoothing> surface_smoothings;
  std::vector<Clearance> clearances;
  /// ADJUST applied: the slave nodes it moves sit on their masters in mesh.nodes.coords
  /// (contact::apply_adjust, run after reading: the one change to the model after the parser).
  bool adjusted = false;
  /// What that preprocessing did, for `inpact check` and the analysis messages.
  std::vector<std::string> preprocessing_notes;

  std::vector<Step> steps;
};

}  // namespace inpact::model
