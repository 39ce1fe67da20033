/// The contact keywords' specs: which parameters each takes, where it may appear, which parent it
/// follows. Parameters are the Abaqus 2016 Keywords Reference lists (parser/KEYWORDS.md Part A)
/// plus the CalculiX extras; MAIN/SECONDARY are the 2022+ spellings of MASTER/SLAVE.
/// The handlers are in kw_surface_interaction.cpp, kw_contact_pair.cpp, kw_general_contact.cpp.
#include <fmt/format.h>

#include "handlers.hpp"
#include "kw_contact.hpp"

namespace inpact::parser {

namespace contact_kw {

bool optional_real(KeywordContext& ctx, const std::vector<Field>& f, std::size_t i, std::string_view what,
                   std::optional<double>& out) {
  if (i >= f.size() || f[i].empty()) return true;
  out = ctx.real(f[i], what);
  return out.has_value();
}

std::string aliased_name(KeywordContext& ctx, std::string_view name, std::string_view alias) {
  if (ctx.has(name) && ctx.has(alias))
    ctx.error_param(alias, fmt::format("{} and {} are the same parameter; give only one", name, alias));
  return ctx.has(name) ? ctx.name_value(name) : ctx.name_value(alias);
}

model::SourceLoc line_start(const Line& line) {
  std::size_t lead = 0;
  while (lead < line.text.size() && (line.text[lead] == ' ' || line.text[lead] == '\t')) ++lead;
  return {line.loc.file, line.loc.line, static_cast<std::uint32_t>(lead + 1)};
}

void warn_ignored(KeywordContext& ctx, std::string_view param, std::string_view why) {
  if (const KeywordParam* p = ctx.param(param))
    ctx.warning(p->loc, fmt::format("{} is ignored: {}", param, why));
}

void reject_param(KeywordContext& ctx, std::string_view param, std::string_view what) {
  if (const KeywordParam* p = ctx.param(param))
    ctx.error(p->loc, fmt::format("{} is not supported by inpact yet ({})", param, what));
}

}  // namespace contact_kw

void add_contact_keywords(std::vector<KeywordSpec>& t) {
  using namespace contact_kw;
  using VK = ValueKind;
  using VT = ValueType;
  const std::vector<std::string_view> yes_no{"YES", "NO"};
  // In a step they follow *CHANGE SURFACE BEHAVIOR / *CHANGE FRICTION (kw_step_contact.cpp).
  const std::vector<std::string_view> behavior_parents{kSurfaceInteraction, kChangeSurfaceBehavior};
  const std::vector<std::string_view> friction_parents{kSurfaceInteraction, kChangeFriction};
  const std::vector<std::string_view> contact_parent{kContact};

  // Model data in Abaqus/Standard [K16 §18.50]; part-level interactions are not supported.
  t.push_back({"*SURFACE INTERACTION", kModelDataScopes,
               {{"NAME", VK::Required, VT::Text, {}, true},
                {"TRACKING THICKNESS", VK::Required, VT::Real},
                {"PAD THICKNESS", VK::Required, VT::Real},
                {"USER", VK::Optional, VT::Choice, {"INTERACTION"}},
                {"DEPVAR", VK::Required, VT::Int},
                {"PROPERTIES", VK::Required, VT::Int},
                {"UNSYMM", VK::None}},
               DataLines::Optional, surface_interaction});
  t.back().numbers_from = 0;

  // [K16 §18.48], [K17]; TIED is CalculiX's; HERTZ/JKR/LKM are newer discrete-element laws and
  // SCALE FACTOR is Abaqus/Explicit's: listed so that they get "not supported", not "unknown".
  t.push_back({"*SURFACE BEHAVIOR", kModelDataScopes | kStepScope,
               {{"PRESSURE-OVERCLOSURE", VK::Required, VT::Choice,
                 {"HARD", "EXPONENTIAL", "LINEAR", "TABULAR", "TIED", "SCALE FACTOR", "HERTZ", "JKR", "LKM"}},
                {"AUGMENTED LAGRANGE", VK::None},
                {"DIRECT", VK::None},
                {"PENALTY", VK::Optional, VT::Choice, {"LINEAR", "NONLINEAR"}},
                {"NO SEPARATION", VK::None}},
               DataLines::Optional, surface_behavior, behavior_parents});
  t.back().numbers_from = 0;

  // [K16 §6.36], [IG ctc_friction]; CalculiX takes no parameters.
  t.push_back({"*FRICTION", kModelDataScopes | kStepScope,
               {{"ROUGH", VK::None},
                {"LAGRANGE", VK::None},
                {"ELASTIC SLIP", VK::Required, VT::Real},
                {"SLIP TOLERANCE", VK::Required, VT::Real},
                {"USER", VK::Optional, VT::Choice, {"FRIC", "COEFFICIENT", "FRICTION"}},
                {"ANISOTROPIC", VK::None},
                {"ANISOTROPIC BEHAVIOR", VK::Required, VT::Text},
                {"DEPENDENCIES", VK::Required, VT::Int},
                {"DEPVAR", VK::Required, VT::Int},
                {"PROPERTIES", VK::Required, VT::Int},
                {"EXPONENTIAL DECAY", VK::None},
                {"TEST DATA", VK::None},
                {"TAUMAX", VK::Required, VT::Real},
                {"SHEAR TRACTION SLOPE", VK::Required, VT::Text}},
               DataLines::Optional, friction, friction_parents});
  t.back().numbers_from = 0;

  // Model data [K16 §3.68]; the brief lets a step add pairs too (they go to Step::contact_pairs).
  // TYPE: MORTAR/LINMORTAR/PGLINMORTAR/MASSLESS are CalculiX's, listed to be refused clearly.
  t.push_back({"*CONTACT PAIR", kModelDataScopes | kStepScope,
               {{"INTERACTION", VK::Required, VT::Text, {}, true},
                {"TYPE", VK::Required, VT::Choice,
                 {"NODE TO SURFACE", "SURFACE TO SURFACE", "MORTAR", "LINMORTAR", "PGLINMORTAR", "MASSLESS"}},
                {"SMALL SLIDING", VK::None},
                {"ADJUST", VK::Required, VT::Text},
                {"POSITION TOLERANCE", VK::Required, VT::Real},
                {"TIED", VK::None},
                {"EXTENSION ZONE", VK::Required, VT::Real},
                {"GEOMETRIC CORRECTION", VK::Required, VT::Text},
                {"HCRIT", VK::Required, VT::Real},
                {"SMOOTH", VK::Required, VT::Real},
                {"SUPPLEMENTARY CONSTRAINTS", VK::Required, VT::Choice, {"SELECTIVE", "YES", "NO"}},
                {"MIDFACE NODES", VK::Required, VT::Choice, yes_no},
                {"MINIMUM DISTANCE", VK::Required, VT::Choice, yes_no},
                {"NO THICKNESS", VK::None},
                {"SLIDING TRANSITION", VK::Required, VT::Choice,
                 {"ELEMENT ORDER SMOOTHING", "LINEAR SMOOTHING", "QUADRATIC SMOOTHING"}},
                {"TRACKING", VK::Required, VT::Choice, {"PATH", "STATE"}},
                {"LINEAR", VK::None},
                {"CPSET", VK::Required, VT::Text},
                {"MECHANICAL CONSTRAINT", VK::Required, VT::Choice, {"KINEMATIC", "PENALTY"}},
                {"OP", VK::Required, VT::Choice, {"ADD", "DELETE"}},
                {"WEIGHT", VK::Required, VT::Real}},
               DataLines::Required, contact_pair});

  // General contact [K16 §3.54]: model data; in a step it (de)activates contact, which inpact
  // refuses in the handler rather than with a misleading scope error.
  t.push_back({"*CONTACT", kModelDataScopes | kStepScope,
               {{"OP", VK::Required, VT::Choice, {"MOD", "NEW"}}}, DataLines::None, contact});
  t.push_back({"*CONTACT INCLUSIONS", kModelDataScopes | kStepScope, {{"ALL EXTERIOR", VK::None}},
               DataLines::Optional, contact_inclusions, contact_parent});
  t.push_back({"*CONTACT EXCLUSIONS", kModelDataScopes | kStepScope, {}, DataLines::Required,
               contact_exclusions, contact_parent});
  t.push_back({"*CONTACT PROPERTY ASSIGNMENT", kModelDataScopes | kStepScope, {}, DataLines::Required,
               contact_property_assignment, contact_parent});
  t.push_back({"*SURFACE PROPERTY ASSIGNMENT", kModelDataScopes | kStepScope,
               {{"PROPERTY", VK::Required, VT::Choice,
                 {"GEOMETRIC CORRECTION", "BEAM SMOOTHING", "FEATURE EDGE CRITERIA", "OFFSET FRACTION", "THICKNESS"},
                 true}},
               DataLines::Required, surface_property_assignment, contact_parent});
  t.back().numbers_from = 2;  // surface, method, then coordinates

  t.push_back({"*SURFACE SMOOTHING", kModelDataScopes, {{"NAME", VK::Required, VT::Text, {}, true}},
               DataLines::Required, surface_smoothing});
  t.back().numbers_from = 2;  // surface, method, then coordinates

  // History data only [K16 §3.57]: it belongs to a step.
  t.push_back({"*CONTACT CONTROLS", kStepScope,
               {{"ABSOLUTE PENETRATION TOLERANCE", VK::Required, VT::Real},
                {"RELATIVE PENETRATION TOLERANCE", VK::Required, VT::Real},
                {"STIFFNESS SCALE FACTOR", VK::Required, VT::RealOrChoice, {"USER ADAPTIVE"}},
                {"MASTER", VK::Required, VT::Text},
                {"SLAVE", VK::Required, VT::Text},
                {"MAIN", VK::Required, VT::Text},
                {"SECONDARY", VK::Required, VT::Text},
                {"RESET", VK::None},
                {"STABILIZE", VK::Optional, VT::RealOrChoice, {"USER ADAPTIVE"}},
                {"TANGENT FRACTION", VK::Required, VT::Real},
                {"PERTURBATION TANGENT SCALE FACTOR", VK::Required, VT::Real},
                {"PRESSURE DEPENDENT PERTURBATION", VK::Required, VT::Real},
                {"CPSET", VK::Required, VT::Text},
                {"FASTLOCALTRK", VK::Required, VT::Text},
                {"GLOBTRKINC", VK::Required, VT::Int},
                {"SCALE PENALTY", VK::Required, VT::Real},
                {"WARP CHECK PERIOD", VK::Required, VT::Int},
                {"WARP CUT OFF", VK::Required, VT::Real}},
               DataLines::Optional, contact_controls});
  t.back().numbers_from = 0;

  // History data [K16 *CONTACT STABILIZATION]: data lines name surfaces.
  t.push_back({"*CONTACT STABILIZATION", kStepScope,
               {{"AMPLITUDE", VK::Required, VT::Text},
                {"RANGE", VK::Required, VT::Real},
                {"REDUCTION PER INCREMENT", VK::Required, VT::Real},
                {"RESET", VK::None},
                {"SCALE FACTOR", VK::Required, VT::RealOrChoice, {"USER ADAPTIVE"}},
                {"TANGENT FRACTION", VK::Required, VT::Real}},
               DataLines::Optional, contact_stabilization});

  // Model data [K16 §3.21]; INPUT= may hold the TABULAR lines.
  t.push_back({"*CLEARANCE", kModelDataScopes,
               {{"MASTER", VK::Required, VT::Text},
                {"SLAVE", VK::Required, VT::Text},
                {"MAIN", VK::Required, VT::Text},
                {"SECONDARY", VK::Required, VT::Text},
                {"VALUE", VK::Required, VT::Real},
                {"TABULAR", VK::None},
                {"BOLT", VK::None}},
               DataLines::Optional, clearance, {}, true});
  t.back().numbers_from = 1;  // node or node set, then numbers
}

}  // namespace inpact::parser
