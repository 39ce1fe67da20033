// The HDF5 helpers the results writer stands on, where their own logic could go wrong.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "io/hdf5_util.hpp"
#include "io_fixture.hpp"

using namespace inpact;
using inpact::test::TempDir;

namespace {

std::vector<double> read_all(hid_t dataset, std::size_t n) {
  std::vector<double> out(n);
  EXPECT_GE(H5Dread(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()), 0);
  return out;
}

}  // namespace

// Frames written chunk by chunk (H5Dwrite_chunk) read back exactly through the ordinary
// H5Dread, when a frame spans several chunks and its last chunk is partial (padded); a frame
// nobody wrote reads as the fill value.
TEST(Hdf5Util, FrameChunksReadBackExactlyWithAPartialLastChunkAndUnwrittenFramesAsFill) {
  TempDir dir;
  const auto path = dir / "chunks.h5";
  io::h5::Context ctx(path);
  io::h5::Id file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT));
  ASSERT_TRUE(file.valid());
  const double nan = std::nan("");
  constexpr hsize_t kRows = 10, kComp = 3, kChunkRows = 4;  // chunks of 4, 4 and 2 (+2 padding) rows
  io::h5::Id ds =
      ctx.create_extendable(file, "data", H5T_NATIVE_DOUBLE, {0, kRows, kComp}, {1, kChunkRows, kComp}, &nan);

  auto frame = [&](int k) {
    std::vector<double> v(kRows * kComp);
    for (std::size_t i = 0; i < v.size(); ++i) v[i] = 100.0 * k + 0.5 * static_cast<double>(i);
    return v;
  };
  ctx.write_frame_chunks(ds, 0, kRows, kChunkRows, kComp, frame(0).data(), nan);
  ctx.write_frame_chunks(ds, 2, kRows, kChunkRows, kComp, frame(2).data(), nan);  // frame 1 skipped
  EXPECT_EQ(ctx.n_rows(ds), 3u);

  const auto all = read_all(ds, 3 * kRows * kComp);
  const auto f0 = frame(0), f2 = frame(2);
  for (std::size_t i = 0; i < kRows * kComp; ++i) {
    EXPECT_EQ(all[i], f0[i]) << "frame 0, value " << i;
    EXPECT_TRUE(std::isnan(all[kRows * kComp + i])) << "frame 1, value " << i;
    EXPECT_EQ(all[2 * kRows * kComp + i], f2[i]) << "frame 2, value " << i;
  }
}
