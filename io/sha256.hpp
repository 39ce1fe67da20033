#pragma once
/// SHA-256 of a file, for the results file's `deck_sha256` attribute (which deck produced it).
#include <filesystem>
#include <string>

namespace inpact::io {

/// Lower-case hex digest; throws IoError when the file cannot be read.
std::string sha256_of_file(const std::filesystem::path& path);
/// Lower-case hex digest of a byte string.
std::string sha256(std::string_view bytes);

}  // namespace inpact::io
