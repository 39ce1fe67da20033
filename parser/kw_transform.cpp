/// *TRANSFORM, NSET=, TYPE=R | C: a local coordinate system at nodes [K16 *TRANSFORM],
/// [CCX *TRANSFORM] (model/transform.hpp). Which of its nodes get local DOFs, and the checks
/// against the whole deck: transforms.cpp.
#include <fmt/format.h>

#include "handlers.hpp"

namespace inpact::parser {

namespace {

void transform(KeywordContext& ctx) {
  model::NodalTransform t;
  t.loc = ctx.keyword.loc;
  t.type = ctx.choice_value("TYPE") == "C" ? model::NodalTransform::Type::Cylindrical : model::NodalTransform::Type::Rectangular;
  const KeywordParam* nset = ctx.param("NSET");
  auto rows = ctx.nodes(Field{*nset->value, nset->value_loc});
  if (!rows) return;
  t.nset = *nset->value;
  t.nodes = std::move(*rows);
  std::vector<Field> f;
  split_fields(ctx.data.front(), f);
  if (!ctx.check_count(f, ctx.data.front(), 6, 6, "x, y, z of point a, x, y, z of point b")) return;
  for (int i = 0; i < 6; ++i) {
    const auto v = ctx.real(f[static_cast<std::size_t>(i)], "coordinate");
    if (!v) return;
    (i < 3 ? t.a : t.b)[static_cast<std::size_t>(i % 3)] = *v;
  }
  ctx.model().transforms.push_back(std::move(t));
}

}  // namespace

void add_transform_keywords(std::vector<KeywordSpec>& t) {
  t.push_back({"*TRANSFORM", kModelDataScopes,
               {{"NSET", ValueKind::Required, ValueType::Text, {}, true},
                {"TYPE", ValueKind::Required, ValueType::Choice, {"R", "C"}}},
               DataLines::Required, transform});
}

}  // namespace inpact::parser
