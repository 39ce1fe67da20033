#pragma once
/// *MATERIAL and its options.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "source_loc.hpp"

namespace inpact::model {

/// *ELASTIC, TYPE=ISOTROPIC: E, ν (temperature dependence not yet supported).
struct Elastic {
  double youngs_modulus = 0.0;
  double poissons_ratio = 0.0;
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
/// plastic). COMBINED (DATATYPE=PARAMETERS): nonlinear kinematic hardening (Chaboche), the
/// first point is σ|0 and `backstresses` holds (C_k, γ_k); the size of the yield surface comes
/// from *CYCLIC HARDENING (Material::cyclic_hardening), constant σ|0 without it. One temperature
/// only (a temperature column with one value is accepted).
struct Plastic {
  enum class Hardening : std::uint8_t { Isotropic, Kinematic, Combined };
  struct Point {
    double yield_stress = 0.0;
    double plastic_strain = 0.0;
  };
  struct Backstress {
    double modulus = 0.0;   ///< C_k
    double recovery = 0.0;  ///< γ_k (0: linear)
  };
  Hardening hardening = Hardening::Isotropic;
  std::vector<Point> table;
  std::vector<Backstress> backstresses;
  SourceLoc loc;
};

/// *CYCLIC HARDENING: the size σ⁰(ε̄ᵖ) of the yield surface of combined hardening, as a table
/// (piecewise linear, constant beyond the last point, as *PLASTIC's) or, with PARAMETERS, the
/// exponential law σ⁰ = σ|0 + Q∞ (1 − exp(−b ε̄ᵖ)).
struct CyclicHardening {
  std::vector<Plastic::Point> table;  ///< empty with PARAMETERS
  double initial = 0.0, saturation = 0.0, rate = 0.0;  ///< σ|0, Q∞, b (PARAMETERS)
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
