/// *TIE: surface-based tie constraints [K16 §3.247 *TIE], [IG Mesh tie constraints 35.3.1], [CCX].
#include <fmt/format.h>

#include "handlers.hpp"
#include "kw_contact.hpp"
#include "text.hpp"

namespace inpact::parser {

namespace {

using contact_kw::reject_param;
using contact_kw::warn_ignored;

/// The keyword line's parameters, shared by every data line of the *TIE.
bool read_tie_parameters(KeywordContext& ctx, model::Tie& tie) {
  tie.name = ctx.name_value("NAME");
  tie.loc = ctx.keyword.loc;
  if (const auto t = ctx.real_value("POSITION TOLERANCE")) {
    if (*t < 0) {
      ctx.error_param("POSITION TOLERANCE", fmt::format("POSITION TOLERANCE must not be negative, found {}", *t));
      return false;
    }
    tie.position_tolerance = *t;
  }
  tie.tied_nset = ctx.name_value("TIED NSET");  // checked when the deck is complete
  if (tie.position_tolerance && !tie.tied_nset.empty()) {
    ctx.error_param("TIED NSET", "POSITION TOLERANCE and TIED NSET are mutually exclusive");
    return false;
  }
  tie.adjust = ctx.choice_value("ADJUST") != "NO";
  if (ctx.choice_value("TYPE") == "NODETOSURFACE") tie.type = model::Tie::Type::NodeToSurface;
  // inpact's solids have translations only: there is no rotation to tie, so NO ROTATION holds
  // already and CONSTRAINT RATIO (a rotation-offset setting) has nothing to act on.
  tie.no_rotation = ctx.has("NO ROTATION");
  warn_ignored(ctx, "CONSTRAINT RATIO", "it applies to rotational degrees of freedom, which inpact's solid elements do not have");
  warn_ignored(ctx, "NO THICKNESS", "it applies to shell surfaces, which inpact does not have");
  for (std::string_view p : {"NO ELECTRIC POTENTIAL", "NO FLUID ELECTRIC POTENTIAL", "NO ION CONCENTRATION", "NO PORE",
                             "NO TEMPERATURE", "NO ACOUSTIC PRESSURE"})
    warn_ignored(ctx, p, "inpact's solid elements have displacement degrees of freedom only");
  reject_param(ctx, "CYCLIC SYMMETRY", "cyclic symmetry models");
  reject_param(ctx, "MULTISTAGE", "CalculiX's multistage cyclic symmetry");
  reject_param(ctx, "FLUID CYCLIC", "CalculiX's fluid cyclic symmetry");
  reject_param(ctx, "FLUID CHANNEL", "CalculiX's fluid channels");
  reject_param(ctx, "MPC", "CalculiX's MPC-based ties");
  return !ctx.has("CYCLIC SYMMETRY") && !ctx.has("MULTISTAGE") && !ctx.has("FLUID CYCLIC") &&
         !ctx.has("FLUID CHANNEL") && !ctx.has("MPC");
}

// *TIE, NAME= (required in Abaqus, optional in CalculiX), POSITION TOLERANCE | TIED NSET,
// ADJUST=YES (default) | NO, TYPE=SURFACE TO SURFACE (default) | NODE TO SURFACE, NO ROTATION.
// Data lines `slave surface, master surface`, one tie each.
void tie(KeywordContext& ctx) {
  model::Tie base;
  if (!read_tie_parameters(ctx, base)) return;
  std::vector<Field> f;
  for (const Line& line : ctx.data) {
    split_fields(line, f);
    if (!ctx.check_count(f, line, 2, 2, "slave surface, master surface")) continue;
    if (f[0].empty() || f[1].empty()) {
      ctx.error(f[f[0].empty() ? 0 : 1].loc, "a *TIE data line names the slave surface and the master surface");
      continue;
    }
    model::Tie t = base;
    t.slave = normalize_label(f[0].text);
    t.master = normalize_label(f[1].text);
    t.line_loc = f[0].loc;
    t.master_loc = f[1].loc;
    if (t.name.empty()) t.name = fmt::format("TIE-{}", ctx.model().ties.size() + 1);
    if (t.slave == t.master) {
      ctx.error(f[1].loc, "the slave and the master surface of a tie must differ");
      continue;
    }
    ctx.model().ties.push_back(std::move(t));
  }
}

}  // namespace

void add_tie_keywords(std::vector<KeywordSpec>& t) {
  using VK = ValueKind;
  using VT = ValueType;
  t.push_back({"*TIE", kModelDataScopes,
               {{"NAME", VK::Required, VT::Text},
                {"POSITION TOLERANCE", VK::Required, VT::Real},
                {"TIED NSET", VK::Required, VT::Text},
                {"ADJUST", VK::Required, VT::Choice, {"YES", "NO"}},
                {"TYPE", VK::Required, VT::Choice, {"SURFACE TO SURFACE", "NODE TO SURFACE"}},
                {"NO ROTATION", VK::None},
                {"CONSTRAINT RATIO", VK::Required, VT::Real},
                {"NO THICKNESS", VK::None},
                {"NO ELECTRIC POTENTIAL", VK::None},
                {"NO FLUID ELECTRIC POTENTIAL", VK::None},
                {"NO ION CONCENTRATION", VK::None},
                {"NO PORE", VK::None},
                {"NO TEMPERATURE", VK::None},
                {"NO ACOUSTIC PRESSURE", VK::None},
                {"CYCLIC SYMMETRY", VK::None},
                {"MULTISTAGE", VK::None},
                {"FLUID CYCLIC", VK::None},
                {"FLUID CHANNEL", VK::None},
                {"MPC", VK::None}},
               DataLines::Required, tie});
}

}  // namespace inpact::parser
