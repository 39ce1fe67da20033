#pragma once
/// The typed error every io/ writer throws on a failed write: the file and what failed.
/// `apps/` maps it to exit code 5 (shared/DESIGN.md, "Command line").
#include <filesystem>
#include <stdexcept>
#include <string>

namespace inpact::io {

class IoError : public std::runtime_error {
 public:
  IoError(std::filesystem::path path, const std::string& what)
      : std::runtime_error(path.string() + ": " + what), path_(std::move(path)) {}
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace inpact::io
