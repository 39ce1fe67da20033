#pragma once
/// The isotropic linear elastic law of a section (elements/material.hpp, IsotropicElastic), with
/// the temperature tables of its material's *ELASTIC and *EXPANSION, and the check that stops
/// those tables where they are not analysed yet.
#include <memory>
#include <string_view>

#include "elements/material.hpp"
#include "model/model.hpp"

namespace inpact::solver {

/// IsotropicElastic for `family` with the constants `c`; when `mat` (null: no section) has a
/// temperature-dependent isotropic *ELASTIC or *EXPANSION, with its tables.
std::shared_ptr<elements::Material> isotropic_elastic_law(const model::Material* mat, model::ElementFamily family,
                                                          const elements::ElasticConstants& c);

/// Throws AnalysisError at the *ELASTIC (else the *EXPANSION) data when `mat` has
/// temperature-dependent elastic constants or expansion, which `with` ("*PLASTIC", "beam
/// elements", ...) does not take yet. Returns quietly otherwise.
void refuse_temperature_tables(const model::Model& m, const model::Material& mat, std::string_view with);

}  // namespace inpact::solver
