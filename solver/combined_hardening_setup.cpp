#include "combined_hardening_setup.hpp"

#include <algorithm>
#include <span>

#include <fmt/format.h>

#include "analysis_error.hpp"
#include "elements/half_cycle_fit.hpp"
#include "elements/mises_plasticity.hpp"
#include "elements/temperature_bracket.hpp"

namespace inpact::solver {

namespace {

using Rows = std::span<const model::Plastic::Point>;
using elements::CombinedHardening;

/// *PLASTIC's rows split into their temperature blocks.
std::vector<Rows> blocks_of(const std::vector<model::Plastic::Point>& table) {
  std::vector<Rows> blocks;
  for (std::size_t first = 0; first < table.size();) {
    std::size_t last = first + 1;
    while (last < table.size() && table[last].temperature == table[first].temperature) ++last;
    blocks.push_back(Rows(table).subspan(first, last - first));
    first = last;
  }
  return blocks;
}

/// Every temperature a datum is given at, increasing.
std::vector<double> all_temperatures(const model::Plastic& p, const model::CyclicHardening* cyc) {
  std::vector<double> t;
  for (const auto& row : p.table) t.push_back(row.temperature);
  if (cyc) {
    for (const auto& row : cyc->table) t.push_back(row.temperature);
    for (const auto& set : cyc->parameters) t.push_back(set.temperature);
  }
  std::ranges::sort(t);
  t.erase(std::unique(t.begin(), t.end()), t.end());
  return t;
}

/// σ⁰(ε̄ᵖ) at `temperature` into `set`: the *CYCLIC HARDENING table or law, or constant σ|0
/// (each block's first row) without it.
void yield_surface_at(const model::Plastic& p, const model::CyclicHardening* cyc, double temperature,
                      CombinedHardening& set) {
  if (cyc && !cyc->parameters.empty()) {
    std::vector<double> t;
    for (const auto& s : cyc->parameters) t.push_back(s.temperature);
    const elements::TemperatureBracket b = elements::bracket(t, temperature);
    const auto &lo = cyc->parameters[b.lower], &hi = cyc->parameters[b.upper];
    set.initial = b.blend(lo.initial, hi.initial);
    set.saturation = b.blend(lo.saturation, hi.saturation);
    set.rate = b.blend(lo.rate, hi.rate);
    return;
  }
  std::vector<model::Plastic::Point> first_rows;
  if (!cyc)
    for (Rows block : blocks_of(p.table)) first_rows.push_back(block.front());
  const elements::MisesHardening h = elements::isotropic_hardening(cyc ? Rows(cyc->table) : Rows(first_rows));
  const std::size_t m = h.plastic_strain.size();
  const elements::TemperatureBracket b = elements::bracket(h.temperatures, temperature);
  set.table_strain = h.plastic_strain;
  set.table_stress.resize(m);
  for (std::size_t k = 0; k < m; ++k) set.table_stress[k] = b.blend(h.yield_stress[b.lower * m + k], h.yield_stress[b.upper * m + k]);
}

/// (C_k, γ_k) of one temperature block.
struct BlockBackstresses {
  double temperature = 0.0;
  std::vector<CombinedHardening::Backstress> backstresses;
};

/// Half-cycle rows: α_i = σ_i − σ⁰(ε̄ᵖ_i) at the block's temperature, fitted.
BlockBackstresses fit_block(const model::Model& m, const model::Material& mat, Rows block,
                            const CombinedHardening& surface, std::vector<std::string>& notes) {
  CombinedHardening probe = surface;
  probe.backstresses = {{0.0, 0.0}};
  const elements::CombinedPlasticity size(elements::ElasticConstants{1.0, 0.0, 0.0}, probe);
  std::vector<double> eq, alpha;
  for (const auto& row : block) {
    eq.push_back(row.plastic_strain);
    alpha.push_back(row.yield_stress - size.yield_size(row.plastic_strain));
  }
  elements::HalfCycleFit fit;
  if (block.size() > 1) fit = elements::fit_half_cycle(eq, alpha);
  if (fit.modulus < 0)
    throw AnalysisError(fmt::format("{}: error: *PLASTIC: the half-cycle data of material '{}'{} do not harden "
                                    "(the fitted C is {:.6g}); combined hardening needs a rising curve",
                                    m.sources.describe(mat.plastic->loc), mat.name,
                                    block.front().temperature != 0 ? fmt::format(" at temperature {}", block.front().temperature) : "",
                                    fit.modulus));
  notes.push_back(fmt::format("material '{}': C = {:.6g}, gamma = {:.6g} fitted to the half-cycle data of *PLASTIC, "
                              "HARDENING=COMBINED{} (rms {:.3g}); CalculiX reads these rows as a linear kinematic "
                              "hardening table instead", mat.name, fit.modulus, fit.recovery,
                              block.front().temperature != 0 ? fmt::format(" at temperature {}", block.front().temperature) : "",
                              fit.rms));
  return {block.front().temperature, {{fit.modulus, fit.recovery}}};
}

/// The backstresses of each *PLASTIC block: given (PARAMETERS), from the first two rows
/// (KINEMATIC), or fitted (HALF CYCLE).
std::vector<BlockBackstresses> block_backstresses(const model::Model& m, const model::Material& mat,
                                                  std::vector<std::string>& notes) {
  const model::Plastic& p = *mat.plastic;
  const model::CyclicHardening* cyc = mat.cyclic_hardening ? &*mat.cyclic_hardening : nullptr;
  std::vector<BlockBackstresses> out;
  const std::vector<Rows> blocks = blocks_of(p.table);
  const std::size_t per_row = p.backstresses.size() / std::max<std::size_t>(1, p.table.size());
  for (std::size_t j = 0; j < blocks.size(); ++j) {
    const Rows block = blocks[j];
    if (p.hardening == model::Plastic::Hardening::Kinematic) {
      const double C = block.size() > 1 ? (block[1].yield_stress - block[0].yield_stress) / block[1].plastic_strain : 0.0;
      out.push_back({block.front().temperature, {{C, 0.0}}});
    } else if (p.combined_data == model::Plastic::CombinedData::Parameters) {
      const auto first = p.backstresses.begin() + static_cast<std::ptrdiff_t>(j * per_row);
      BlockBackstresses b{block.front().temperature, {}};
      for (auto it = first; it != first + static_cast<std::ptrdiff_t>(per_row); ++it) b.backstresses.push_back({it->modulus, it->recovery});
      out.push_back(std::move(b));
    } else {
      CombinedHardening surface;
      yield_surface_at(p, cyc, block.front().temperature, surface);
      out.push_back(fit_block(m, mat, block, surface, notes));
    }
  }
  return out;
}

}  // namespace

CombinedLawData combined_law_data(const model::Model& m, const model::Material& mat) {
  const model::Plastic& p = *mat.plastic;
  const model::CyclicHardening* cyc = mat.cyclic_hardening ? &*mat.cyclic_hardening : nullptr;
  CombinedLawData out;
  const std::vector<BlockBackstresses> blocks = block_backstresses(m, mat, out.notes);
  std::vector<double> block_temperatures;
  for (const auto& b : blocks) block_temperatures.push_back(b.temperature);
  out.temperatures = all_temperatures(p, cyc);
  for (double t : out.temperatures) {
    CombinedHardening set;
    yield_surface_at(p, cyc, t, set);
    const elements::TemperatureBracket b = elements::bracket(block_temperatures, t);
    const auto &lo = blocks[b.lower].backstresses, &hi = blocks[b.upper].backstresses;
    for (std::size_t k = 0; k < lo.size(); ++k)
      set.backstresses.push_back({b.blend(lo[k].modulus, hi[k].modulus), b.blend(lo[k].recovery, hi[k].recovery)});
    out.sets.push_back(std::move(set));
  }
  return out;
}

}  // namespace inpact::solver
