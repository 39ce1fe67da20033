#include "handlers.hpp"

namespace inpact::parser {

void add_output_keywords(std::vector<KeywordSpec>& t) { (void)t; }

}  // namespace inpact::parser
