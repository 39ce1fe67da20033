// SHA-256 against the FIPS 180-2 example vectors (one block, padding into a second block, and
// a million bytes), whole, in pieces and from a file.
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include <gtest/gtest.h>

#include "io/sha256.hpp"

TEST(Sha256, FipsExampleVectors) {
  EXPECT_EQ(inpact::io::sha256(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(inpact::io::sha256("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(inpact::io::sha256("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(inpact::io::sha256(std::string(1'000'000, 'a')),
            "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

// The million 'a's given in uneven pieces, and read from a file in 64 kB blocks, hash the same.
TEST(Sha256, IncrementalAndFileDigestsMatchTheVector) {
  const std::string million(1'000'000, 'a');
  inpact::io::Sha256 h;
  for (std::size_t at = 0, piece = 1; at < million.size(); at += piece, piece = piece * 3 % 70'001 + 1)
    h.update(std::string_view(million).substr(at, piece));
  EXPECT_EQ(h.hex(), "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");

  const auto path = std::filesystem::temp_directory_path() / "inpact_test_sha256.txt";
  std::ofstream(path, std::ios::binary) << million;
  EXPECT_EQ(inpact::io::sha256_of_file(path), "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
  std::filesystem::remove(path);
}
