#include "handlers.hpp"

namespace inpact::parser {

void add_contact_keywords(std::vector<KeywordSpec>& t) { (void)t; }

}  // namespace inpact::parser
