#pragma once
/// SHA-256, for the results file's `deck_sha256` attribute (which deck produced it).
#include <array>
#include <filesystem>
#include <string>
#include <string_view>

namespace inpact::io {

/// Incremental SHA-256: the deck and its included files, one after the other.
class Sha256 {
 public:
  Sha256();
  void update(std::string_view bytes);
  /// The file's bytes, read in 64 kB blocks; throws IoError when it cannot be read.
  void update_file(const std::filesystem::path& path);
  /// Lower-case hex digest of everything given so far (the hash cannot be updated after).
  std::string hex();

 private:
  alignas(8) std::array<unsigned char, 112> state_;  ///< OpenSSL's SHA256_CTX (static_assert in the .cpp)
};

/// Lower-case hex digest; throws IoError when the file cannot be read.
std::string sha256_of_file(const std::filesystem::path& path);
/// Lower-case hex digest of a byte string.
std::string sha256(std::string_view bytes);

}  // namespace inpact::io
