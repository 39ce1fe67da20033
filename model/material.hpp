#pragma once
/// *MATERIAL and its options.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "source_loc.hpp"

namespace inpact::model {

/// *ELASTIC (temperature dependence not yet supported: one set of constants).
/// ISOTROPIC: E, ν. The other types keep their constants as written, in Abaqus's order:
///  - ENGINEERING CONSTANTS: E1, E2, E3, ν12, ν13, ν23, G12, G13, G23;
///  - ORTHOTROPIC: D1111, D1122, D2222, D1133, D2233, D3333, D1212, D1313, D2323;
///  - ANISOTROPIC: the upper triangle of D column by column in the Voigt order 11 22 33 12 13 23
///    (D1111, D1122, D2222, D1133, D2233, D3333, D1112, D2212, D3312, D1212, D1113, …, D2323);
///  - LAMINA (plane stress only): E1, E2, ν12, G12, G13, G23.
/// model/elastic_stiffness.hpp turns them into the stiffness in the material axes.
struct Elastic {
  enum class Type : std::uint8_t { Isotropic, EngineeringConstants, Orthotropic, Anisotropic, Lamina };
  double youngs_modulus = 0.0;  ///< ISOTROPIC only
  double poissons_ratio = 0.0;  ///< ISOTROPIC only
  SourceLoc loc;
  Type type = Type::Isotropic;    // after the isotropic fields: Elastic{E, ν, loc} stays valid
  std::vector<double> constants = {};  ///< the other types: the values above, in that order
};

/// *ORIENTATION, SYSTEM=RECTANGULAR | CYLINDRICAL, DEFINITION=COORDINATES: the local material
/// axes. Rectangular: axis 1 from c to a, axis 3 normal to the plane of c, a and b, axis 2 = 3 × 1.
/// Cylindrical: a and b on the axis (axis 3 from a to b), axis 1 radial through the point,
/// axis 2 tangential. Then a rotation by `angle` degrees about local axis `axis` (1, 2 or 3).
struct Orientation {
  enum class System : std::uint8_t { Rectangular, Cylindrical };
  std::string name;  ///< as written
  System system = System::Rectangular;
  double a[3] = {0, 0, 0};
  double b[3] = {0, 0, 0};
  double c[3] = {0, 0, 0};  ///< rectangular: the origin (default the global origin)
  int axis = 1;
  double angle = 0.0;  ///< degrees
  SourceLoc loc;
};

/// *EXPANSION, TYPE=ISO: α, measured from the reference temperature ZERO (Abaqus default 0).
struct Expansion {
  double alpha = 0.0;
  double zero = 0.0;
  SourceLoc loc;
};

/// *PLASTIC (Mises yield): yield stress against equivalent plastic strain, the first point at
/// zero plastic strain. ISOTROPIC: piecewise linear between the points, constant beyond the
/// last (one point: perfectly plastic), as Abaqus. KINEMATIC: linear Ziegler/Prager hardening
/// with σ⁰ = the first yield stress and C from the first two points (one point: perfectly
/// plastic). One temperature only (a temperature column with one value is accepted).
struct Plastic {
  enum class Hardening : std::uint8_t { Isotropic, Kinematic };
  struct Point {
    double yield_stress = 0.0;
    double plastic_strain = 0.0;
  };
  Hardening hardening = Hardening::Isotropic;
  std::vector<Point> table;
  SourceLoc loc;
};

/// *INITIAL CONDITIONS, TYPE=PLASTIC STRAIN: the plastic strain of integration points before
/// the first increment (Voigt 11 22 33 12 13 23, engineering shear; 2D lines give 11 22 33 12).
/// The equivalent plastic strain (hardening) is not set by it, as in Abaqus (TYPE=HARDENING).
struct InitialPlasticStrain {
  std::string target;                 ///< element label or element set, as written
  std::vector<std::int32_t> elements;  ///< element rows
  int point = 0;                      ///< 1-based integration point; 0 (empty field): every point
  double components[6] = {0, 0, 0, 0, 0, 0};
  SourceLoc loc;
};

struct Material {
  std::string name;  ///< as written
  std::optional<Elastic> elastic;
  std::optional<Plastic> plastic;
  std::optional<double> density;  ///< kept for later procedures; static steps ignore it
  std::optional<Expansion> expansion;
  SourceLoc loc;
};

}  // namespace inpact::model
