#pragma once
/// Boundary conditions, loads, amplitudes, constraints and initial conditions.
/// Targets are resolved to rows by the parser; `target` keeps the text as written for reports.
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "source_loc.hpp"

namespace inpact::model {

/// OP= on history keywords: MOD keeps earlier definitions and changes the named ones,
/// NEW removes every earlier definition of this kind first.
enum class Op : std::uint8_t { Mod, New };

/// One data line of *BOUNDARY: DOFs first..last of the nodes set to `value`
/// (type names such as ENCASTRE are expanded by the parser into DOF ranges with value 0; see
/// parser/kw_loads.cpp). DOFs 4-6 are rotations: recorded as given, but the solid and plane
/// elements inpact supports have only DOFs 1-3, so they constrain nothing.
struct BoundaryEntry {
  std::string target;
  std::vector<std::int32_t> nodes;
  int first_dof = 1;
  int last_dof = 1;
  double value = 0.0;
  SourceLoc loc;
};

struct BoundaryBlock {
  Op op = Op::Mod;
  std::string amplitude;  ///< upper-case name; empty = the step's default
  bool fixed = false;     ///< FIXED: hold the displacement at the start of the step
  std::vector<BoundaryEntry> entries;
  SourceLoc loc;
};

/// *CLOAD: a concentrated force (DOF 1..3) or moment on nodes.
struct CloadEntry {
  std::string target;
  std::vector<std::int32_t> nodes;
  int dof = 1;
  double magnitude = 0.0;
  SourceLoc loc;
};

struct CloadBlock {
  Op op = Op::Mod;
  std::string amplitude;
  std::vector<CloadEntry> entries;
  SourceLoc loc;
};

/// The direction of a traction on a shell edge, force per unit length (Abaqus's EDNORn, EDSHRn,
/// EDTn on edge n; EDNOR, EDSHR, EDT on an edge-based surface): positive NORMAL pushes into the
/// element in its plane, positive SHEAR runs along the edge in the element's node order, positive
/// TRANSVERSE acts against the shell's positive normal.
enum class EdgeTraction : std::uint8_t { Normal, Shear, Transverse };

/// The load slot (dload_slot) of a traction on shell edge `edge` (0 = E1): 10 + 3 × edge + direction,
/// below 100 as the face pressures are, since both follow the deformed element.
inline int edge_load_slot(int edge, EdgeTraction traction) { return 10 + 3 * edge + static_cast<int>(traction); }
inline bool is_edge_load_slot(int slot) { return slot >= 10 && slot < 100; }
inline int slot_edge(int slot) { return (slot - 10) / 3; }
inline EdgeTraction slot_edge_traction(int slot) { return static_cast<EdgeTraction>((slot - 10) % 3); }

/// *DLOAD / *DSLOAD: pressure on element faces, traction on shell edges, or a body force per
/// volume on elements.
struct DloadEntry {
  enum class Kind : std::uint8_t {
    Pressure,  ///< P (2D: on the element's faces given by `face`) / Pn on face n
    EdgeLoad,  ///< EDNORn, EDSHRn, EDTn: on the shell edges given by `faces` (0 = E1)
    Gravity,     ///< GRAV: magnitude × direction × density
    BodyForce,   ///< BX, BY, BZ: force per unit volume in one direction
    Centrifugal,  ///< CENTRIF: density × ω² (the magnitude) × the distance vector from the axis
    RotaryAcceleration  ///< ROTA: the d'Alembert force −density × α n × r of a rotary acceleration α about n
  };
  Kind kind = Kind::Pressure;
  std::string target;
  std::vector<std::int32_t> elements;  ///< rows
  std::vector<std::uint8_t> faces;     ///< Pressure: face per element (0 = S1); EdgeLoad: edge (0 = E1)
  EdgeTraction edge_traction = EdgeTraction::Normal;  ///< EdgeLoad
  double magnitude = 0.0;
  /// Gravity; BodyForce (unit axis); CENTRIF, ROTA: the rotation axis (unit)
  std::array<double, 3> direction{0, 0, 0};
  std::array<double, 3> point{0, 0, 0};      ///< CENTRIF, ROTA: a point on the rotation axis
  SourceLoc loc;
};

/// GRAV, CENTRIF and ROTA are accelerations: their force is the magnitude times the density.
inline bool scales_with_density(DloadEntry::Kind kind) {
  return kind == DloadEntry::Kind::Gravity || kind == DloadEntry::Kind::Centrifugal ||
         kind == DloadEntry::Kind::RotaryAcceleration;
}

/// Which load of element i of `e` a definition is, so that a later one of the same replaces it
/// (another step) or adds to it (the same step): the face for pressure (0 = S1), edge_load_slot
/// for an edge traction, 100 + the axis
/// for a body force, 200 gravity, 300 CENTRIF, 400 ROTA.
inline int dload_slot(const DloadEntry& e, std::size_t i) {
  switch (e.kind) {
    case DloadEntry::Kind::Pressure: return e.faces[i];
    case DloadEntry::Kind::EdgeLoad: return edge_load_slot(e.faces[i], e.edge_traction);
    case DloadEntry::Kind::BodyForce: {
      int axis = 0;
      for (int c = 1; c < 3; ++c)
        if (std::abs(e.direction[static_cast<std::size_t>(c)]) > std::abs(e.direction[static_cast<std::size_t>(axis)]))
          axis = c;
      return 100 + axis;
    }
    case DloadEntry::Kind::Gravity: return 200;
    case DloadEntry::Kind::Centrifugal: return 300;
    case DloadEntry::Kind::RotaryAcceleration: return 400;
  }
  return 0;
}

struct DloadBlock {
  Op op = Op::Mod;
  /// From *DSLOAD (loads on a named surface). OP=NEW of *DLOAD removes earlier *DLOAD blocks and
  /// OP=NEW of *DSLOAD earlier *DSLOAD blocks: Abaqus keeps the two kinds apart.
  bool surface_load = false;
  std::string amplitude;
  std::vector<DloadEntry> entries;
  SourceLoc loc;
};

/// *TEMPERATURE in a step, or *INITIAL CONDITIONS, TYPE=TEMPERATURE: nodal temperatures.
struct TemperatureEntry {
  std::string target;
  std::vector<std::int32_t> nodes;
  double value = 0.0;
  /// The third field: the temperature's gradient ∂T/∂n through the thickness of the shells at
  /// the nodes (value is the temperature on their reference surface); absent: none given.
  std::optional<double> gradient;
  SourceLoc loc;
};

struct TemperatureBlock {
  Op op = Op::Mod;
  std::string amplitude;
  std::vector<TemperatureEntry> entries;
  SourceLoc loc;
};

/// *AMPLITUDE: a multiplier of the load magnitudes as a function of step or total time.
/// SCALEX/SCALEY/SHIFTX/SHIFTY are already applied to `points` by the parser.
struct Amplitude {
  enum class Definition : std::uint8_t {
    /// Piecewise linear between the points; constant (first / last value) outside them. Two
    /// points at the same time make a jump.
    Tabular,
    /// Abaqus "smooth step": between points i and i+1, with ξ = (t − t_i)/(t_{i+1} − t_i),
    /// a = a_i + (a_{i+1} − a_i)·ξ³(10 − 15ξ + 6ξ²) (zero first and second derivatives at each
    /// point); constant outside the points. Times strictly increasing.
    SmoothStep
  };
  std::string name;
  Definition definition = Definition::Tabular;
  enum class Time : std::uint8_t { Step, Total } time = Time::Step;
  std::vector<std::array<double, 2>> points;  ///< (time, value), times non-decreasing
  SourceLoc loc;
};

/// *EQUATION: Σ coefficient · u(node, dof) = 0; the first term's DOF is the one eliminated.
struct Equation {
  struct Term {
    std::int32_t node;
    int dof;
    double coefficient;
  };
  std::vector<Term> terms;
  SourceLoc loc;
};

/// *MPC TIE between two nodes. Their translations are *EQUATIONs from the start; their
/// rotations are tied too where both nodes have them (beam and shell nodes), which is known only
/// once the rotation nodes exist (parser/finalize.cpp adds those equations).
struct MpcTie {
  std::int32_t dependent = -1;
  std::int32_t independent = -1;
  SourceLoc loc;
};

/// One data line of *TIE (model data): every node of the slave surface that lies within the
/// position tolerance of the master surface moves with the master point it projects onto,
/// u_s = Σ N_m(ξ) u_m (its translations eliminated like an *EQUATION's first DOF). The geometry
/// is resolved by contact::resolve_ties (contact/tie.hpp).
struct Tie {
  enum class Type : std::uint8_t { SurfaceToSurface, NodeToSurface };
  std::string name;    ///< NAME=, as written
  std::string slave;   ///< upper-case surface names
  std::string master;
  Type type = Type::SurfaceToSurface;  ///< Abaqus/Standard's default for *TIE
  /// POSITION TOLERANCE=; unset = inpact's default (5 % of the typical master facet diagonal).
  std::optional<double> position_tolerance;
  std::string tied_nset;  ///< TIED NSET=: only these slave nodes, at any distance
  bool adjust = true;     ///< ADJUST=YES (Abaqus's default): tied slave nodes moved onto the master
  bool no_rotation = false;
  /// What ADJUST did (contact::apply_adjust, before the analysis): nodes moved, largest move.
  std::size_t n_adjusted = 0;
  double largest_adjustment = 0.0;
  SourceLoc loc;          ///< the *TIE keyword line
  SourceLoc line_loc;     ///< the data line (its slave field)
  SourceLoc master_loc;   ///< its master field
};

/// *PRE-TENSION SECTION, SURFACE=, NODE= (model data): the surface cuts a fastener in two. The
/// parser (parser/pretension_split.cpp) gives the elements on the surface's side (its underlying
/// elements) a copy of each section node, and the DOF map ties every copy to its original,
///   u_copy = u_original + n · u_P1,
/// so DOF 1 of the pre-tension node P is the relative displacement of the two sides along the
/// normal n (the tightening) and its conjugate force is the force carried across the section
/// (positive = tension) [K16 *PRE-TENSION SECTION], [IG Prescribed assembly loads].
struct PretensionSection {
  std::string surface;  ///< upper-case surface name (empty for an ELEMENT= section)
  std::int32_t element = -1;  ///< ELEMENT=: the truss that is the section (its row), else −1
  std::int32_t node = -1;  ///< the pre-tension node's row
  std::optional<std::array<double, 3>> given_normal;  ///< the data line, as written
  /// Resolved by the split: the unit normal (pointing out of the underlying elements, as the
  /// given one is taken), the section area normal to it, and (original, copy) node rows.
  std::array<double, 3> normal{0, 0, 0};
  double area = 0.0;
  std::vector<std::array<std::int32_t, 2>> node_pairs;
  std::size_t n_rewired_elements = 0;  ///< elements that now use the copies
  SourceLoc loc;          ///< the keyword line
  SourceLoc surface_loc;  ///< SURFACE='s value (ELEMENT='s)
  SourceLoc node_loc;     ///< NODE='s value
  SourceLoc normal_loc;   ///< the data line
};

}  // namespace inpact::model
