#include "handlers.hpp"

namespace inpact::parser {

void add_step_keywords(std::vector<KeywordSpec>& t) { (void)t; }

}  // namespace inpact::parser
