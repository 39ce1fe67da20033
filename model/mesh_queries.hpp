#pragma once
/// Questions asked of a mesh by more than one folder: its dimension, face nodes and exterior faces.
#include <cstdint>
#include <span>
#include <vector>

#include "mesh.hpp"

namespace inpact::model {

/// 3 when any element is a 3D one, else 2 (plane and axisymmetric models).
int spatial_dimension(const Elements& elements);

/// The element that sets a model's kind (its dimension, and whether it is axisymmetric): the first
/// one that is neither a spring nor a rigid element, which take the model's kind; the last one
/// when all are. (elements must not be empty)
std::size_t kind_element(const Elements& elements);

/// The dimension of the model's displacements: kind_element's, 3 in a model of springs.
int model_dimension(const Elements& elements);

/// Node rows of one face (corners first, then midside nodes).
std::vector<std::int32_t> face_nodes(const Elements& elements, Face face);

/// Node rows of one shell edge (its two corners, then its midside node).
std::vector<std::int32_t> edge_nodes(const Elements& elements, Face edge);

/// Faces of `subset` (element rows) not shared with any element of the whole mesh, matched by
/// their corner nodes: the free surface Abaqus builds for a surface defined by an element set
/// without face identifiers, and for ALL EXTERIOR general contact.
std::vector<Face> exterior_faces(const Elements& elements, std::span<const std::int32_t> subset);

/// A shell element's thickness: its section's, or with NODAL THICKNESS the mean of its nodes'
/// *NODAL THICKNESS (the contact offsets and the drilling spring take this one; the kernel
/// interpolates the nodes' own).
double shell_thickness(const Mesh& mesh, const ShellSection& section, std::size_t element);

}  // namespace inpact::model
