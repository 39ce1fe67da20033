// The .sta status file: Abaqus's header and column layout, a U on cut-back attempts.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "io/status_log.hpp"
#include "io_fixture.hpp"
#include "sample_jobs.hpp"

using namespace inpact;


TEST(StatusLog, RowsHaveAbaqusColumnWidthsAndSignificantDigits) {
  // Abaqus:  "   1     1   1     3     3     6  0.500      0.500      0.5000    "
  EXPECT_EQ(io::format_status_row(test::status_row(1, 1, false, 3, 3, 0.5, 0.5, 0)),
            "   1     1   1     3     3     6  0.500      0.500      0.5000          0");
  EXPECT_EQ(io::format_status_row(test::status_row(12, 2, false, 0, 4, 1.0, 0.025, 3)),
            "   1    12   2     0     4     4  1.00       1.00       0.02500         3");
  EXPECT_EQ(io::format_status_row(test::status_row(1, 1, true, 16, 0, 0.0, 1.0, 0)),
            "   1     1   1U   16     0    16  0.00       0.00       1.000           0");  // zero as Abaqus prints it
  EXPECT_EQ(io::format_status_row(test::status_row(3, 1, false, 1, 1, 2.5e-6, 1e-6, 0)),
            "   1     3   1     1     1     2  2.50e-06   2.50e-06   1.000e-06       0");
}

TEST(StatusLog, FileHasTheHeaderEveryRowAndTheClosingLine) {
  test::TempDir dir;
  const auto path = dir / "job.sta";
  {
    io::StatusLog log(path, "0.1.0");
    log.write(test::status_row(1, 1, true, 12, 0, 0.0, 1.0, 0));
    // Flushed per row: readable while the log is still open.
    std::ifstream in(path);
    std::stringstream ss;
    ss << in.rdbuf();
    EXPECT_NE(ss.str().find("   1     1   1U   12"), std::string::npos) << ss.str();
    log.write(test::status_row(1, 2, false, 2, 3, 0.25, 0.25, 1));
    log.finish(true);
  }
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  EXPECT_EQ(text.rfind("inpact 0.1.0", 0), 0u) << text;
  EXPECT_NE(text.find(" SUMMARY OF JOB INFORMATION:\n"
                      " STEP  INC ATT SEVERE EQUIL TOTAL  TOTAL      STEP       INC OF   AUGMEN-\n"
                      "               DISCON ITERS ITERS  TIME/    TIME/LPF    TIME/LPF  TATIONS\n"
                      "               ITERS               FREQ\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("   1     1   2     2     3     5  0.250      0.250      0.2500          1\n"), std::string::npos);
  EXPECT_NE(text.find(" THE ANALYSIS HAS COMPLETED SUCCESSFULLY\n"), std::string::npos);
}

TEST(StatusLog, UnwritablePathThrowsIoError) {
  test::TempDir dir;
  EXPECT_THROW(io::StatusLog(dir / "missing" / "job.sta", "0.1.0"), io::IoError);
}
