#include "abaqus_args.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <stdexcept>

namespace inpact::app {

namespace {
std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}
}  // namespace

std::optional<std::vector<std::string>> translate_abaqus_args(const std::vector<std::string>& args) {
  if (args.empty()) return std::nullopt;
  const std::string first = lower(args[0]);
  if (!first.starts_with("job=") && !first.starts_with("input=")) return std::nullopt;

  std::string job, input, cpus;
  bool datacheck = false;
  for (const std::string& a : args) {
    const std::string l = lower(a);
    const auto eq = a.find('=');
    const std::string value = eq == std::string::npos ? std::string() : a.substr(eq + 1);
    if (l.starts_with("job=")) job = value;
    else if (l.starts_with("input=")) input = value;
    else if (l.starts_with("cpus=")) cpus = value;
    else if (l == "datacheck") datacheck = true;
    else if (l == "interactive" || l == "ask_delete=off" || l == "background") continue;  // no meaning here
    else throw std::invalid_argument("'" + a + "' is not understood (expected job=, input=, cpus=, datacheck, interactive)");
  }
  // Abaqus: the input defaults to JOB.inp, and ".inp" may be left off.
  if (input.empty()) input = job;
  if (input.empty()) throw std::invalid_argument("job= or input= needs a value");
  if (!std::filesystem::exists(input) && std::filesystem::exists(input + ".inp")) input += ".inp";
  if (job.empty()) job = std::filesystem::path(input).stem().string();

  std::vector<std::string> out{datacheck ? "check" : "run", input};
  if (!datacheck) {
    out.insert(out.end(), {"-j", job});
    if (!cpus.empty()) out.insert(out.end(), {"--threads", cpus});
  }
  return out;
}

}  // namespace inpact::app
