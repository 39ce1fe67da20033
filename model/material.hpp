#pragma once
/// *MATERIAL and its options.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "source_loc.hpp"

namespace inpact::model {

/// *ELASTIC. ISOTROPIC: E, ν, and with several data lines `temperature_table` (E and ν at each
/// temperature; Abaqus interpolates linearly between the rows and holds the end rows outside).
/// The other types, one temperature, keep their constants as written, in Abaqus's order:
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
  struct IsotropicRow {
    double youngs_modulus = 0.0;
    double poissons_ratio = 0.0;
    double temperature = 0.0;
  };
  /// ISOTROPIC: every data line, temperatures strictly increasing; youngs_modulus and
  /// poissons_ratio above hold the first line's. One line (or none, when built by hand): the
  /// constants do not depend on temperature.
  std::vector<IsotropicRow> temperature_table = {};
  /// Whether E or ν changes with temperature (rows that all hold the same E and ν do not).
  bool temperature_dependent() const {
    for (const IsotropicRow& row : temperature_table)
      if (row.youngs_modulus != youngs_modulus || row.poissons_ratio != poissons_ratio) return true;
    return false;
  }
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
  /// Whether the second data line was given: for shells it names the axis nearest the normal
  /// (Abaqus requires it there; CalculiX decks leave it out).
  bool rotation_given = false;
  SourceLoc loc;
};

/// *EXPANSION, TYPE=ISO: α, the secant coefficient measured from the reference temperature ZERO
/// (Abaqus default 0), with several data lines a function of temperature: the thermal strain is
/// then α(T)(T − ZERO) − α(Tᴵ)(Tᴵ − ZERO), Tᴵ the initial temperature (Abaqus).
struct Expansion {
  double alpha = 0.0;  ///< the first line's α
  double zero = 0.0;
  SourceLoc loc;
  struct Row {
    double alpha = 0.0;
    double temperature = 0.0;
  };
  /// Every data line, temperatures strictly increasing (one line: no temperature dependence).
  std::vector<Row> temperature_table = {};
  /// Whether α changes with temperature (equal α on every row is today's α (T − Tᴵ)).
  bool temperature_dependent() const {
    for (const Row& row : temperature_table)
      if (row.alpha != alpha) return true;
    return false;
  }
};

/// *PLASTIC (Mises yield): yield stress against equivalent plastic strain, the first point at
/// zero plastic strain. ISOTROPIC: piecewise linear between the points, constant beyond the
/// last (one point: perfectly plastic), as Abaqus. KINEMATIC: linear Ziegler/Prager hardening
/// with σ⁰ = the first yield stress and C from the first two points (one point: perfectly
/// plastic). COMBINED: nonlinear kinematic hardening (Chaboche); the size of the yield surface
/// comes from *CYCLIC HARDENING (Material::cyclic_hardening), constant σ|0 without it.
///  - DATATYPE=HALF CYCLE (the default): `table` holds the test's (σ, ε̄ᵖ) rows, from which the
///    analysis fits one backstress (solver/elements/half_cycle_fit.hpp);
///  - DATATYPE=PARAMETERS: one row (σ|0, 0, T) per temperature in `table`, and `backstresses`
///    holds NUMBER BACKSTRESSES pairs (C_k, γ_k) per row, in the rows' order.
/// Temperature: the rows come in blocks, one per temperature (temperatures increasing, each
/// block from zero plastic strain); every value is interpolated linearly in temperature (a
/// table at equal plastic strain), constant outside the range (Abaqus).
struct Plastic {
  enum class Hardening : std::uint8_t { Isotropic, Kinematic, Combined };
  enum class CombinedData : std::uint8_t { HalfCycle, Parameters };
  struct Point {
    double yield_stress = 0.0;
    double plastic_strain = 0.0;
    double temperature = 0.0;  ///< the row's temperature (0 without a temperature column)
  };
  struct Backstress {
    double modulus = 0.0;   ///< C_k
    double recovery = 0.0;  ///< γ_k (0: linear)
  };
  Hardening hardening = Hardening::Isotropic;
  CombinedData combined_data = CombinedData::HalfCycle;
  std::vector<Point> table;  ///< every row, in blocks of equal temperature
  std::vector<Backstress> backstresses;
  SourceLoc loc;
  /// Whether the rows hold several temperatures.
  bool several_temperatures() const {
    for (const Point& row : table)
      if (row.temperature != table.front().temperature) return true;
    return false;
  }
};

/// *CYCLIC HARDENING: the size σ⁰(ε̄ᵖ) of the yield surface of combined hardening, as a table
/// (piecewise linear, constant beyond the last point, as *PLASTIC's; blocks per temperature)
/// or, with PARAMETERS, the exponential law σ⁰ = σ|0 + Q∞ (1 − exp(−b ε̄ᵖ)), one set per
/// temperature.
struct CyclicHardening {
  struct Exponential {
    double initial = 0.0, saturation = 0.0, rate = 0.0;  ///< σ|0, Q∞, b
    double temperature = 0.0;
  };
  std::vector<Plastic::Point> table;  ///< empty with PARAMETERS
  std::vector<Exponential> parameters;  ///< PARAMETERS, temperatures increasing
  SourceLoc loc;
};

/// *HYPERELASTIC (isotropic, coefficients given directly, one temperature): the strain energy
/// W = W_iso(Ī1, Ī2 | λ̄) + U(J) of Abaqus. `coefficients` in the order of Abaqus's data lines
/// without the D's: POLYNOMIAL C10 C01 [C20 C11 C02]; REDUCED POLYNOMIAL C10 [C20 [C30]] (NEO
/// HOOKE: C10; YEOH: C10 C20 C30); MOONEY-RIVLIN C10 C01; ARRUDA-BOYCE μ, λm; OGDEN μ1 α1 [μ2 α2
/// [μ3 α3]]. `d`: D1 .. DN (all zero: incompressible).
struct Hyperelastic {
  enum class Form : std::uint8_t { Polynomial, ReducedPolynomial, ArrudaBoyce, Ogden };
  Form form = Form::Polynomial;
  int order = 1;  ///< N
  std::string name;  ///< the form as written in messages: "NEO HOOKE", "POLYNOMIAL, N=2", ...
  std::vector<double> coefficients;
  std::vector<double> d;
  SourceLoc loc;
  bool incompressible() const {
    for (double v : d)
      if (v != 0.0) return false;
    return true;
  }
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
  std::optional<CyclicHardening> cyclic_hardening;
  std::optional<Hyperelastic> hyperelastic;
  std::optional<double> density;  ///< kept for later procedures; static steps ignore it
  std::optional<Expansion> expansion;
  SourceLoc loc;
};

}  // namespace inpact::model
