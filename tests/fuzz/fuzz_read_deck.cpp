/// libFuzzer target for the deck reader: the input is written to a deck file and read with
/// read_deck, as `inpact check` would. Built only with INPACT_FUZZ=ON (clang); run it with
/// bench/fuzz_parser.sh.
///
/// The input may carry a second file: everything after a line `**FILE2` goes to `inc.inp`
/// next to the deck (a comment line, so seeds stay valid decks), which the deck can pull in
/// with `*INCLUDE, INPUT=inc.inp` — and which may include the deck back.
///
/// Besides crashes, hangs and sanitizer reports, the target checks what a clean read promises:
/// every element node and every set row points at an existing row.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string_view>

#include "parser/read_deck.hpp"

namespace fs = std::filesystem;

namespace {

const fs::path& work_dir() {
  static const fs::path dir = [] {
    const fs::path base = fs::exists("/dev/shm") ? fs::path("/dev/shm") : fs::temp_directory_path();
    fs::path d = base / ("inpact-fuzz-" + std::to_string(getpid()));
    fs::create_directories(d);
    std::atexit([] {
      std::error_code ec;
      fs::remove_all(work_dir(), ec);
    });
    return d;
  }();
  return dir;
}

void write_file(const fs::path& p, std::string_view text) {
  std::ofstream out(p, std::ios::binary | std::ios::trunc);
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
}

[[noreturn]] void broken(const char* what) {
  std::fprintf(stderr, "invariant broken after a clean read: %s\n", what);
  std::abort();
}

/// What a deck without errors guarantees to the solver.
void check_clean_model(const inpact::model::Model& m) {
  const auto& nodes = m.mesh.nodes;
  const auto& el = m.mesh.elements;
  const auto n_nodes = static_cast<std::int64_t>(nodes.size());
  const auto n_elements = static_cast<std::int64_t>(el.size());
  if (nodes.coords.size() != nodes.size() || nodes.instance.size() != nodes.size()) broken("node arrays");
  if (el.offsets.size() != el.size() + 1 || el.type.size() != el.size() || el.loc.size() != el.size())
    broken("element arrays");
  if (static_cast<std::size_t>(el.offsets.back()) != el.conn.size()) broken("element offsets");
  for (auto r : el.conn)
    if (r < 0 || r >= n_nodes) broken("element node row");
  for (const auto& [name, s] : m.mesh.nsets)
    for (auto r : s.rows)
      if (r < 0 || r >= n_nodes) broken("node set row");
  for (const auto& [name, s] : m.mesh.elsets)
    for (auto r : s.rows)
      if (r < 0 || r >= n_elements) broken("element set row");
  for (const auto& [name, s] : m.mesh.surfaces) {
    for (const auto& f : s.faces)
      if (f.element < 0 || f.element >= n_elements) broken("surface face element");
    for (auto r : s.nodes)
      if (r < 0 || r >= n_nodes) broken("surface node row");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  constexpr std::string_view kMarker = "\n**FILE2\n";
  const std::size_t split = input.find(kMarker);
  const fs::path deck = work_dir() / "deck.inp";
  const fs::path inc = work_dir() / "inc.inp";
  write_file(deck, input.substr(0, split));
  if (split != std::string_view::npos) {
    write_file(inc, input.substr(split + kMarker.size()));
  } else {
    std::error_code ec;
    fs::remove(inc, ec);  // a missing include is a case too
  }

  inpact::parser::ReadOptions options;
  options.parameters["FUZZ"] = "1";
  options.max_errors = 20;
  const auto result = inpact::parser::read_deck(deck.string(), options);
  const std::string report = result.report();  // formatting must cope with whatever was collected
  if (result.ok()) check_clean_model(result.model);
  else if (report.empty()) broken("errors but an empty report");
  return 0;
}
