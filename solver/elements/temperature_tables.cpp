#include "temperature_tables.hpp"

#include "temperature_bracket.hpp"

namespace inpact::solver::elements {

ElasticTable elastic_table(const model::Elastic& elastic) {
  ElasticTable t;
  for (const model::Elastic::IsotropicRow& row : elastic.temperature_table) {
    t.temperatures.push_back(row.temperature);
    t.youngs_modulus.push_back(row.youngs_modulus);
    t.poissons_ratio.push_back(row.poissons_ratio);
  }
  if (t.temperatures.empty()) {  // built without its rows: the one set of constants
    t.temperatures.push_back(0.0);
    t.youngs_modulus.push_back(elastic.youngs_modulus);
    t.poissons_ratio.push_back(elastic.poissons_ratio);
  }
  return t;
}

ExpansionTable expansion_table(const model::Expansion& expansion) {
  ExpansionTable t;
  for (const model::Expansion::Row& row : expansion.temperature_table) {
    t.temperatures.push_back(row.temperature);
    t.alpha.push_back(row.alpha);
  }
  if (t.temperatures.empty()) {
    t.temperatures.push_back(0.0);
    t.alpha.push_back(expansion.alpha);
  }
  t.zero = expansion.zero;
  return t;
}

ElasticConstants elastic_constants_at(const ElasticTable& table, double temperature, ElasticConstants base) {
  const TemperatureBracket b = bracket(table.temperatures, temperature);
  base.youngs_modulus = b.blend(table.youngs_modulus[b.lower], table.youngs_modulus[b.upper]);
  base.poissons_ratio = b.blend(table.poissons_ratio[b.lower], table.poissons_ratio[b.upper]);
  return base;
}

double expansion_at(const ExpansionTable& table, double temperature) {
  const TemperatureBracket b = bracket(table.temperatures, temperature);
  return b.blend(table.alpha[b.lower], table.alpha[b.upper]);
}

double thermal_strain(const ExpansionTable& table, double temperature, double initial_temperature) {
  return expansion_at(table, temperature) * (temperature - table.zero) -
         expansion_at(table, initial_temperature) * (initial_temperature - table.zero);
}

}  // namespace inpact::solver::elements
