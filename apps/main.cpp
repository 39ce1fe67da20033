#include <cstdio>
#include "parser/read_deck.hpp"
int main(int argc, char** argv) {
  auto r = inpact::parser::read_deck(argv[1]);
  std::fputs(r.report().c_str(), stderr);
  return r.ok() ? 0 : 3;
}
