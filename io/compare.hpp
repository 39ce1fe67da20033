#pragma once
/// `inpact compare A.h5 B.h5` (shared/DESIGN.md, "`compare` semantics"): structure first
/// (steps, frames, fields, locations matched by node/element label and instance, never by
/// row), then values field by field.
///
/// A value pair (a, b) of a field passes when
///   - both are NaN (a frame without the field in both files), or both are the same infinity;
///   - |a| ≤ floor and |b| ≤ floor (both "zero" for this field); or
///   - |a − b| ≤ max(atol, rtol · max(|a|, |b|)).
/// NaN against a number never passes. With `scale = frame-max`, atol and floor are fractions
/// of the frame's largest magnitude of the field (over both files, every location and
/// component): for fields full of near-zeros, such as S away from a load or CPRESS at open
/// nodes. The lengths COPEN and CSLIP1/2 scale by at least the frame's largest |U|, the moment
/// RM and section force SF by at least its largest |RF|: a closed contact's COPEN and a symmetric load's RM are
/// round-off of the coordinates and forces, whose own maximum is no scale. An `exact` field (CSTATUS) passes only on a == b, and the field as a whole passes
/// with up to `allowed_mismatches` failing values.
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "results_reader.hpp"

namespace inpact::io {

struct FieldTolerance {
  double rtol = 1e-6;
  double atol = 1e-12;
  double floor = 1e-12;
  bool scale_by_frame_max = false;  ///< atol and floor relative to the frame's largest |value|
  bool exact = false;               ///< a == b only (CSTATUS)
  std::int64_t allowed_mismatches = 0;  ///< failing values the field may have and still pass
};

/// Tolerances by field key (U, S, CPRESS, ...), with a default for every other field.
struct Tolerances {
  FieldTolerance fallback;
  std::map<std::string, FieldTolerance> fields;
  const FieldTolerance& of(const std::string& key) const;
};

/// The defaults, chosen for reruns in double precision (another machine, thread count or BLAS:
/// the same Newton path, round-off apart): rtol 1e-6, atol and floor 1e-12 (absolute);
/// S, E, RF, CPRESS, COPEN, CSHEAR1/2, CSLIP1/2, CFN, CNAREA scaled by the frame's largest
/// value (atol 1e-9, floor 1e-10 of it); CSTATUS exact, 0 mismatches allowed.
Tolerances default_tolerances();

/// Reads per-field tolerances over the defaults from a TOML or YAML file (by extension: .toml;
/// .yaml/.yml), a subset of either: one table per field (or `default`) holding
/// rtol, atol, floor (numbers), scale ("frame-max" | "none"), exact (true|false),
/// allowed_mismatches (integer). Throws IoError (missing file) or std::invalid_argument
/// ("file:line: ...") on anything else.
Tolerances read_tolerances(const std::filesystem::path& path);
/// The same from text; `format` "toml" or "yaml"; `name` for messages.
Tolerances parse_tolerances(const std::string& text, const std::string& format, const std::string& name);

/// The worst value pair of one field (over every step and frame), and where.
struct FieldDifference {
  std::string key;
  std::int64_t n_compared = 0;
  std::int64_t n_failed = 0;
  bool pass = true;
  bool has_worst = false;
  std::string step;
  std::size_t frame = 0;  ///< 0-based within the step
  std::string location;   ///< "node 12", "element 7 ip 3", ...
  std::string component;  ///< U2, S11, ...
  double a = 0, b = 0;
  double abs_diff = 0;
  double allowed = 0;  ///< max(atol, rtol·max|a|,|b|) at the worst pair (after scaling)
  double ratio = 0;    ///< abs_diff / allowed (> 1: fails); the worst is the largest
};

struct CompareResult {
  std::filesystem::path a, b;
  std::vector<std::string> structure;  ///< one message per structural mismatch
  std::vector<FieldDifference> fields;  ///< one per field key, in first-seen order
  bool same() const;
};

CompareResult compare_results(const ResultsFile& a, const ResultsFile& b, const Tolerances& tolerances);

/// A few lines for a person: the verdict, each structural mismatch, the worst difference
/// per field with step, frame, location and component.
std::string format_summary(const CompareResult& result);
/// The same as JSON (the `--report` file), with the tolerances used.
std::string format_json(const CompareResult& result, const Tolerances& tolerances);

}  // namespace inpact::io
