#pragma once
/// `inpact study`: the cases of a study and its manifest, plain data and text, no processes.
///
/// A study is a deck with *PARAMETER definitions and a set of cases, each a list of
/// `-P name=value` overrides: the Cartesian product of the `--grid name=v1,v2,...` options
/// (the first grid varies slowest) and, with `--samples FILE`, of the sample rows (a CSV file
/// whose header names the parameters). Cases are numbered c0001, c0002, ... in that order, so
/// the same command gives the same ids.
///
/// The manifest, DIR/manifest.csv, is what `inpact study run-case ID`, a Slurm array or GNU
/// parallel read:
///   # inpact study manifest 1
///   # deck: /abs/path/deck.inp
///   # collect: max:CPRESS max:-COPEN sum:RF2@TOP
///   id,deck,results,LOAD,MU
///   c0001,/abs/path/deck.inp,cases/c0001/c0001.h5,10,0.1
/// (results paths relative to DIR).
#include <cstddef>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace inpact::app::study {

using Parameters = std::vector<std::pair<std::string, std::string>>;

struct Case {
  std::string id;
  Parameters parameters;
};

/// One `--grid name=v1,v2,...`: throws std::invalid_argument when malformed.
std::pair<std::string, std::vector<std::string>> parse_grid(const std::string& text);
/// Rows of a samples CSV file (header: parameter names); throws std::invalid_argument.
std::vector<Parameters> parse_samples(const std::string& text, const std::string& name);
std::vector<Parameters> read_samples(const std::filesystem::path& path);
/// The cases: grids × samples, numbered c0001... (at least 4 digits).
std::vector<Case> expand_cases(const std::vector<std::pair<std::string, std::vector<std::string>>>& grids,
                               const std::vector<Parameters>& samples);

/// `--shard i/n`: this process runs cases k (0-based) with k mod n = i − 1.
struct Shard {
  int index = 1;
  int count = 1;
  bool contains(std::size_t k) const { return static_cast<int>(k % static_cast<std::size_t>(count)) == index - 1; }
};
Shard parse_shard(const std::string& text);  ///< "i/n", 1 ≤ i ≤ n; throws std::invalid_argument

/// A value to collect per case: `OP:VAR[@NSET]`, OP one of max, min, maxabs, sum; VAR a field
/// key (every component: CPRESS, U) or a component label (U2, RF2, S11), negated with a
/// leading '-' (max:-COPEN is the largest penetration); @NSET keeps the nodes of a node set.
/// Evaluated on the last frame of the last step that has frames.
struct CollectSpec {
  std::string text;  ///< as given: the CSV column name
  std::string op, var, nset;
  bool negate = false;
};
CollectSpec parse_collect(const std::string& text);  ///< throws std::invalid_argument

struct Manifest {
  std::string deck;  ///< absolute path
  std::vector<std::string> parameter_names;
  std::vector<std::string> collect;  ///< CollectSpec texts
  std::vector<Case> cases;

  /// Results file of a case, relative to the study folder: cases/<id>/<id>.h5.
  static std::filesystem::path results_path(const std::string& id);
  const Case* find(const std::string& id) const;
};

std::string format_manifest(const Manifest& m);
Manifest parse_manifest(const std::string& text, const std::string& name);  ///< throws std::invalid_argument

/// CSV helpers (RFC 4180 quoting: fields with , " or newlines are quoted).
std::string csv_field(const std::string& s);
std::vector<std::string> split_csv_line(const std::string& line);

/// Writes `text` to `path` through a temporary file in the same folder and a rename, so a
/// reader (or a killed writer) never sees half a file. Throws std::runtime_error.
void write_atomically(const std::filesystem::path& path, const std::string& text);
std::string read_text(const std::filesystem::path& path);  ///< throws std::runtime_error

}  // namespace inpact::app::study
