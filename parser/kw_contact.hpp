#pragma once
/// The contact keyword handlers, shared between the files that implement them and the spec
/// table in kw_contact.cpp, plus the small field helpers they have in common.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "keyword_spec.hpp"

namespace inpact::parser::contact_kw {

inline constexpr std::string_view kSurfaceInteraction = "*SURFACE INTERACTION";
inline constexpr std::string_view kContact = "*CONTACT";
inline constexpr std::string_view kChangeFriction = "*CHANGE FRICTION";
inline constexpr std::string_view kChangeSurfaceBehavior = "*CHANGE SURFACE BEHAVIOR";

// kw_surface_interaction.cpp
void surface_interaction(KeywordContext& ctx);
void surface_behavior(KeywordContext& ctx);
void friction(KeywordContext& ctx);

// kw_contact_pair.cpp
void contact_pair(KeywordContext& ctx);
void clearance(KeywordContext& ctx);
void contact_controls(KeywordContext& ctx);

// kw_contact_stabilization.cpp
void contact_stabilization(KeywordContext& ctx);
/// STABILIZE, TANGENT FRACTION and the STABILIZE data line of *CONTACT CONTROLS into `c`.
void contact_controls_stabilize(KeywordContext& ctx, model::ContactControls& c);

// kw_step_contact.cpp (history data: the step-wise changes of contact)
void change_friction(KeywordContext& ctx);
void change_surface_behavior(KeywordContext& ctx);
void model_change(KeywordContext& ctx);

// kw_general_contact.cpp
void contact(KeywordContext& ctx);
void contact_inclusions(KeywordContext& ctx);
void contact_exclusions(KeywordContext& ctx);
void contact_property_assignment(KeywordContext& ctx);
void surface_property_assignment(KeywordContext& ctx);
void surface_smoothing(KeywordContext& ctx);

/// Field `i` of a data line as a number. A blank or absent field leaves `out` unset and is fine;
/// false (after reporting) when the text is not a number.
bool optional_real(KeywordContext& ctx, const std::vector<Field>& f, std::size_t i, std::string_view what,
                   std::optional<double>& out);

/// The value of whichever of two spellings is present (`MASTER` or `MAIN`), upper case; an error
/// when both are. "" when neither is.
std::string aliased_name(KeywordContext& ctx, std::string_view name, std::string_view alias);

/// Where a data line's text starts (its first field): data-line errors cite a column too.
model::SourceLoc line_start(const Line& line);

/// Warns that a parameter, when present, has no effect in inpact (and says why).
void warn_ignored(KeywordContext& ctx, std::string_view param, std::string_view why);

/// Reports a parameter, when present, as not supported (it would change the answer).
void reject_param(KeywordContext& ctx, std::string_view param, std::string_view what);

}  // namespace inpact::parser::contact_kw
