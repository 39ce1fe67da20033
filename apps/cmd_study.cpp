/// `inpact study`: expand the cases, write the manifest, run the cases on worker processes and
/// write the results table; `study run-case ID` runs one case of an existing manifest (for a
/// Slurm array or GNU parallel); `study collect` rewrites the table from the case results.
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include <fmt/format.h>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "study_cases.hpp"
#include "study_runner.hpp"

namespace inpact::app {

namespace fs = std::filesystem;

namespace {

study::Manifest load_manifest(const fs::path& dir) {
  const fs::path p = dir / "manifest.csv";
  std::error_code ec;
  if (!fs::exists(p, ec)) throw std::runtime_error(p.string() + ": no study manifest here (run `inpact study DECK ...` first, or give -o DIR)");
  return study::parse_manifest(study::read_text(p), p.string());
}

void print_counts(const std::vector<study::CaseOutcome>& outcomes, const fs::path& dir) {
  std::size_t done = 0, failed = 0, pending = 0;
  for (const auto& o : outcomes) {
    if (o.status == "completed") ++done;
    else if (o.status == "failed") ++failed;
    else ++pending;
  }
  std::printf("study: %zu completed, %zu failed, %zu pending; table %s\n", done, failed, pending,
              (dir / "results.csv").string().c_str());
}

int study_main(const StudyOptions& options) {
  study::RunnerOptions runner;
  runner.executable = options.executable;
  runner.jobs = options.jobs;
  runner.threads = options.threads;
  runner.ranks_per_case = options.ranks_per_case;
  runner.quiet = options.quiet;
  runner.shard = study::parse_shard(options.shard);

  if (!options.run_case.empty() || options.collect_only) {
    runner.dir = options.dir.empty() ? fs::path(".") : fs::path(options.dir);
    const study::Manifest m = load_manifest(runner.dir);
    if (options.collect_only) {
      print_counts(study::write_table(m, runner.dir), runner.dir);
      return kOk;
    }
    const study::Case* c = m.find(options.run_case);
    if (!c) {
      std::fprintf(stderr, "inpact study run-case: no case '%s' in %s/manifest.csv\n", options.run_case.c_str(),
                   runner.dir.string().c_str());
      return kUsage;
    }
    const int rc = study::run_one_case(m, *c, runner);
    return rc >= 0 && rc <= kIoError ? rc : kAnalysisFailed;
  }

  if (options.deck.empty()) {
    std::fprintf(stderr, "inpact study: a deck is required (inpact study DECK.inp --grid name=v1,v2 ...)\n");
    return kUsage;
  }
  if (options.grids.empty() && options.samples.empty()) {
    std::fprintf(stderr, "inpact study: nothing to vary: give --grid name=v1,v2,... or --samples FILE\n");
    return kUsage;
  }
  std::vector<std::pair<std::string, std::vector<std::string>>> grids;
  for (const auto& g : options.grids) grids.push_back(study::parse_grid(g));
  const auto samples = options.samples.empty() ? std::vector<study::Parameters>{} : study::read_samples(options.samples);
  study::Manifest m;
  m.deck = fs::absolute(options.deck).lexically_normal().string();
  m.cases = study::expand_cases(grids, samples);
  for (const auto& [name, value] : m.cases.front().parameters) m.parameter_names.push_back(name);
  for (const auto& c : options.collect) m.collect.push_back(study::parse_collect(c).text);

  runner.dir = options.dir.empty() ? fs::path(fs::path(options.deck).stem().string() + ".study") : fs::path(options.dir);
  fs::create_directories(runner.dir);
  const fs::path manifest_path = runner.dir / "manifest.csv";
  const std::string text = study::format_manifest(m);
  std::error_code ec;
  if (fs::exists(manifest_path, ec) && study::read_text(manifest_path) != text) {
    std::fprintf(stderr,
                 "inpact study: %s holds the manifest of another study (other deck, cases or collected values); "
                 "use another -o DIR or delete it\n",
                 manifest_path.string().c_str());
    return kUsage;
  }
  study::write_atomically(manifest_path, text);
  if (!options.quiet) std::printf("study: %zu case(s), manifest %s\n", m.cases.size(), manifest_path.string().c_str());
  if (options.manifest_only) return kOk;
  const int n_failed = study::run_cases(m, runner);
  if (!options.quiet) print_counts(study::write_table(m, runner.dir), runner.dir);
  return n_failed ? kAnalysisFailed : kOk;
}

}  // namespace

int run_study(const StudyOptions& options) {
  try {
    return study_main(options);
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "inpact study: %s\n", e.what());
    return kUsage;
  } catch (const fs::filesystem_error& e) {
    std::fprintf(stderr, "inpact study: I/O error: %s\n", e.what());
    return kIoError;
  } catch (const std::runtime_error& e) {
    std::fprintf(stderr, "inpact study: I/O error: %s\n", e.what());
    return kIoError;
  }
}

}  // namespace inpact::app
