#pragma once
/// Isotropic *ELASTIC and *EXPANSION given at several temperatures, evaluated as Abaqus does
/// ("Material data as functions of temperature"): linear between the rows, the end rows held
/// outside their range (temperature_bracket.hpp). Each rule lives here once; IsotropicElastic
/// and the element kernels call these functions, nothing else interpolates E, ν or α.
#include <vector>

#include "element_kernel.hpp"
#include "model/material.hpp"

namespace inpact::solver::elements {

/// E(T), ν(T): one entry per row, temperatures strictly increasing.
struct ElasticTable {
  std::vector<double> temperatures, youngs_modulus, poissons_ratio;
};

/// α(T), the secant coefficient from the reference temperature `zero` (*EXPANSION, ZERO=).
struct ExpansionTable {
  std::vector<double> temperatures, alpha;
  double zero = 0.0;
};

/// The tables of a material's *ELASTIC (ISOTROPIC) and *EXPANSION rows.
ElasticTable elastic_table(const model::Elastic& elastic);
ExpansionTable expansion_table(const model::Expansion& expansion);

/// E and ν at `temperature`; the other members (α) copied from `base`.
ElasticConstants elastic_constants_at(const ElasticTable& table, double temperature, ElasticConstants base);

/// α at `temperature`.
double expansion_at(const ExpansionTable& table, double temperature);

/// The isotropic thermal strain at a point whose temperature went from Tᴵ (its initial
/// condition) to T: ε_th = α(T)(T − T⁰) − α(Tᴵ)(Tᴵ − T⁰), T⁰ = ZERO. The second term makes ε_th
/// zero at the initial temperature; with a constant α it is α (T − Tᴵ).
double thermal_strain(const ExpansionTable& table, double temperature, double initial_temperature);

}  // namespace inpact::solver::elements
