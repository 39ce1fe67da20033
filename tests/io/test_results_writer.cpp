// The results file (shared/DESIGN.md "Results file (contract)"), read back with the HDF5 C API.
#include <gtest/gtest.h>

#include <cmath>
#include <csignal>
#include <fstream>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

#include "h5_read.hpp"
#include "io/results_reader.hpp"
#include "io/results_view.hpp"
#include "io/results_writer.hpp"
#include "io_fixture.hpp"
#include "sample_jobs.hpp"

using namespace inpact;
using inpact::test::H5Reader;
using inpact::test::TempDir;

namespace {

model::Model read_model(const TempDir& dir, const std::string& deck) {
  auto r = dir.read(deck);
  EXPECT_TRUE(r.ok()) << r.report();
  return std::move(r.model);
}

std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace

TEST(ResultsWriter, CompletedRunIsRenamedAndHasRootAttributesAndSidecar) {
  TempDir dir;
  const auto m = read_model(dir, test::kThreeBodyDeck);
  const auto h5 = dir / "job.h5";
  test::write_three_body_job(h5, m);
  EXPECT_TRUE(std::filesystem::exists(h5));
  EXPECT_FALSE(std::filesystem::exists(dir / "job.h5.part"));
  EXPECT_TRUE(std::filesystem::exists(dir / "job.xdmf"));

  H5Reader f(h5.string());
  ASSERT_TRUE(f.ok());
  EXPECT_EQ(f.attr_string("/", "schema"), "inpact-results");
  EXPECT_EQ(f.attr_int("/", "schema_version"), 1);
  EXPECT_EQ(f.attr_string("/", "solver_version"), "0.1.0-test");
  EXPECT_EQ(f.attr_string("/", "deck_sha256"), std::string(64, 'a'));
  EXPECT_EQ(f.attr_string("/", "status"), "COMPLETED");
}

TEST(ResultsWriter, ModelGroupHoldsNodesElementsSetsSurfacesAndPairs) {
  TempDir dir;
  const auto m = read_model(dir, test::kThreeBodyDeck);
  const auto h5 = dir / "job.h5";
  test::write_three_body_job(h5, m);
  H5Reader f(h5.string());

  EXPECT_EQ(f.dims("/model/nodes/coordinates"), (std::vector<hsize_t>{15, 3}));
  const auto labels = f.int64s("/model/nodes/labels");
  ASSERT_EQ(labels.size(), 15u);
  for (std::size_t i = 0; i < 15; ++i) EXPECT_EQ(labels[i], static_cast<std::int64_t>(i + 1));
  const auto xyz = f.doubles("/model/nodes/coordinates");
  EXPECT_EQ(xyz[8 * 3 + 0], 1.0);  // node 9 = (1, 0.5, 2)
  EXPECT_EQ(xyz[8 * 3 + 1], 0.5);
  EXPECT_EQ(xyz[8 * 3 + 2], 2.0);
  EXPECT_EQ(f.int32s("/model/nodes/instance"), std::vector<std::int32_t>(15, 0));
  EXPECT_EQ(f.strings("/model/instances"), std::vector<std::string>{""});

  EXPECT_EQ(f.int64s("/model/elements/C3D8/labels"), std::vector<std::int64_t>{1});
  EXPECT_EQ(f.int64s("/model/elements/C3D8/connectivity"), (std::vector<std::int64_t>{0, 1, 2, 3, 4, 5, 6, 7}));
  EXPECT_EQ(f.dims("/model/elements/C3D8/connectivity"), (std::vector<hsize_t>{1, 8}));
  EXPECT_EQ(f.int64s("/model/elements/C3D4/connectivity"), (std::vector<std::int64_t>{4, 5, 6, 8}));
  EXPECT_EQ(f.int64s("/model/elements/C3D6/labels"), std::vector<std::int64_t>{7});
  EXPECT_EQ(f.int64s("/model/elements/C3D6/rows"), std::vector<std::int64_t>{2});
  EXPECT_EQ(f.int32s("/model/elements/C3D6/instance"), std::vector<std::int32_t>{0});

  EXPECT_EQ(f.int64s("/model/sets/nsets/TIP"), std::vector<std::int64_t>{8});
  EXPECT_EQ(f.int64s("/model/sets/elsets/ALL_E"), (std::vector<std::int64_t>{0, 1, 2}));
  EXPECT_EQ(f.attr_string("/model/sets/elsets/ALL_E", "name"), "ALL_E");
  // Element surfaces: (element row, face) with face 0 = S1; CUBE S4 and WEDGE S5.
  EXPECT_EQ(f.int64s("/model/sets/surfaces/MASTER_S"), (std::vector<std::int64_t>{0, 3}));
  EXPECT_EQ(f.int64s("/model/sets/surfaces/SLAVE_S"), (std::vector<std::int64_t>{2, 4}));
  EXPECT_EQ(f.attr_string("/model/sets/surfaces/SLAVE_S", "kind"), "ELEMENT");
  EXPECT_EQ(f.int64s("/model/sets/surfaces/TIPS"), std::vector<std::int64_t>{8});
  EXPECT_EQ(f.attr_string("/model/sets/surfaces/TIPS", "kind"), "NODE");

  EXPECT_EQ(f.strings("/model/contact/pairs"), std::vector<std::string>{"SLAVE_S/MASTER_S"});
}

TEST(ResultsWriter, StepsHoldFramesAndExactFieldValues) {
  TempDir dir;
  const auto m = read_model(dir, test::kThreeBodyDeck);
  const auto h5 = dir / "job.h5";
  test::write_three_body_job(h5, m);
  H5Reader f(h5.string());

  EXPECT_EQ(f.attr_string("/steps/Load", "procedure"), "STATIC");
  EXPECT_EQ(f.attr_int("/steps/Load", "nlgeom"), 1);
  EXPECT_EQ(f.attr_double("/steps/Load", "time_period"), 1.0);
  EXPECT_EQ(f.attr_int("/steps/Unload", "nlgeom"), 1);  // carried on from Load (Abaqus)
  EXPECT_EQ(f.attr_double("/steps/Unload", "time_period"), 2.0);
  EXPECT_EQ(f.attr_int("/steps/Unload", "number"), 2);

  EXPECT_EQ(f.doubles("/steps/Load/frames/step_time"), (std::vector<double>{0.5, 1.0}));
  EXPECT_EQ(f.doubles("/steps/Unload/frames/total_time"), (std::vector<double>{2.0, 3.0}));
  EXPECT_EQ(f.int32s("/steps/Unload/frames/increment"), (std::vector<std::int32_t>{1, 2}));

  // U: (nf, nloc, ncomp) with every node.
  const std::string u = "/steps/Unload/fieldOutputs/U/";
  EXPECT_EQ(f.dims(u + "data"), (std::vector<hsize_t>{2, 15, 3}));
  const auto ud = f.doubles(u + "data");
  for (int fr = 0; fr < 2; ++fr)
    for (std::size_t n = 0; n < 15; ++n)
      for (int c = 0; c < 3; ++c) EXPECT_EQ(ud[(fr * 15 + n) * 3 + c], test::u_value(2 + fr, n, c));
  EXPECT_EQ(f.attr_string(u, "position"), "NODAL");
  EXPECT_EQ(f.attr_strings(u, "componentLabels"), (std::vector<std::string>{"U1", "U2", "U3"}));
  EXPECT_EQ(f.attr_string(u, "region"), "");
  EXPECT_EQ(f.int64s(u + "nodes").size(), 15u);
  EXPECT_EQ(f.int64s(u + "nodes")[14], 14);

  // RF is missing from the last frame: that row reads NaN.
  const auto rf = f.doubles("/steps/Unload/fieldOutputs/RF/data");
  ASSERT_EQ(rf.size(), 2u * 4 * 3);
  EXPECT_EQ(rf[3 * 3 + 2], test::rf_value(2, 3, 2));
  for (std::size_t i = 12; i < 24; ++i) EXPECT_TRUE(std::isnan(rf[i]));
  EXPECT_EQ(f.int64s("/steps/Unload/fieldOutputs/RF/nodes"), (std::vector<std::int64_t>{0, 1, 2, 3}));
  EXPECT_EQ(f.attr_string("/steps/Unload/fieldOutputs/RF", "region"), "ALL_N");

  const std::string s = "/steps/Load/fieldOutputs/S/";
  EXPECT_EQ(f.dims(s + "data"), (std::vector<hsize_t>{2, 11, 6}));
  const auto sd = f.doubles(s + "data");
  EXPECT_EQ(sd[(1 * 11 + 10) * 6 + 5], test::s_value(1, 10, 5));
  EXPECT_EQ(f.attr_string(s, "position"), "INTEGRATION_POINT");
  EXPECT_EQ(f.int64s(s + "elements"), (std::vector<std::int64_t>{1, 1, 1, 1, 1, 1, 1, 1, 2, 7, 7}));
  EXPECT_EQ(f.int32s(s + "ip"), (std::vector<std::int32_t>{1, 2, 3, 4, 5, 6, 7, 8, 1, 1, 2}));
  EXPECT_FALSE(f.exists(s + "nodes"));

  const std::string cp = "/steps/Load/fieldOutputs/CPRESS/";
  EXPECT_EQ(f.dims(cp + "data"), (std::vector<hsize_t>{2, 4, 1}));
  EXPECT_EQ(f.doubles(cp + "data")[4 + 2], test::cpress_value(1, 2));
  EXPECT_EQ(f.int32s(cp + "pair"), std::vector<std::int32_t>(4, 0));
  EXPECT_EQ(f.int64s(cp + "nodes"), (std::vector<std::int64_t>{9, 11, 12, 14}));
  EXPECT_EQ(f.attr_string(cp, "region"), "SLAVE_S/MASTER_S");
}

TEST(ResultsWriter, StatusTableIsACompoundDataset) {
  TempDir dir;
  const auto m = read_model(dir, test::kThreeBodyDeck);
  const auto h5 = dir / "job.h5";
  test::write_three_body_job(h5, m);
  H5Reader f(h5.string());
  EXPECT_EQ(f.dims("/status"), std::vector<hsize_t>{3});

  struct Row {
    std::int32_t step, increment, attempt;
    std::int8_t cut_back;
    double total_time;
    std::int32_t augmentations;
  };
  hid_t t = H5Tcreate(H5T_COMPOUND, sizeof(Row));
  H5Tinsert(t, "step", HOFFSET(Row, step), H5T_NATIVE_INT32);
  H5Tinsert(t, "increment", HOFFSET(Row, increment), H5T_NATIVE_INT32);
  H5Tinsert(t, "attempt", HOFFSET(Row, attempt), H5T_NATIVE_INT32);
  H5Tinsert(t, "cut_back", HOFFSET(Row, cut_back), H5T_NATIVE_INT8);
  H5Tinsert(t, "total_time", HOFFSET(Row, total_time), H5T_NATIVE_DOUBLE);
  H5Tinsert(t, "augmentations", HOFFSET(Row, augmentations), H5T_NATIVE_INT32);
  const auto rows = f.read<Row>("/status", t);
  H5Tclose(t);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0].cut_back, 1);
  EXPECT_EQ(rows[1].attempt, 2);
  EXPECT_EQ(rows[1].cut_back, 0);
  EXPECT_EQ(rows[2].increment, 2);
  EXPECT_EQ(rows[2].total_time, 1.0);
  EXPECT_EQ(rows[2].augmentations, 2);
}

TEST(ResultsWriter, VtkhdfViewIsAnUnstructuredGridOfTheLastFrame) {
  TempDir dir;
  const auto m = read_model(dir, test::kThreeBodyDeck);
  const auto h5 = dir / "job.h5";
  test::write_three_body_job(h5, m);
  H5Reader f(h5.string());

  EXPECT_EQ(f.attr_values<std::int32_t>("/VTKHDF", "Version", H5T_NATIVE_INT32), (std::vector<std::int32_t>{1, 0}));
  EXPECT_EQ(f.attr_string("/VTKHDF", "Type"), "UnstructuredGrid");
  EXPECT_EQ(f.int64s("/VTKHDF/NumberOfPoints"), std::vector<std::int64_t>{15});
  EXPECT_EQ(f.int64s("/VTKHDF/NumberOfCells"), std::vector<std::int64_t>{3});
  EXPECT_EQ(f.int64s("/VTKHDF/NumberOfConnectivityIds"), std::vector<std::int64_t>{18});
  EXPECT_EQ(f.read<std::uint8_t>("/VTKHDF/Types", H5T_NATIVE_UINT8), (std::vector<std::uint8_t>{12, 10, 13}));
  EXPECT_EQ(f.int64s("/VTKHDF/Offsets"), (std::vector<std::int64_t>{0, 8, 12, 18}));
  EXPECT_EQ(f.doubles("/VTKHDF/Points"), f.doubles("/model/nodes/coordinates"));

  // Point data: U of the last frame (k = 3) at every node; RF absent from it.
  const auto u = f.doubles("/VTKHDF/PointData/U");
  ASSERT_EQ(u.size(), 45u);
  EXPECT_EQ(u[14 * 3 + 1], test::u_value(3, 14, 1));
  EXPECT_FALSE(f.exists("/VTKHDF/PointData/RF"));
  // CPRESS scattered to nodes: NaN off the slave surface.
  const auto cp = f.doubles("/VTKHDF/PointData/CPRESS");
  EXPECT_EQ(cp[11], test::cpress_value(3, 1));
  EXPECT_TRUE(std::isnan(cp[0]));
  // Cell data: S averaged over each element's points, VTK order XX YY ZZ XY YZ XZ.
  const auto s = f.doubles("/VTKHDF/CellData/S");
  ASSERT_EQ(s.size(), 18u);
  double s11_cube = 0;
  for (std::size_t i = 0; i < 8; ++i) s11_cube += test::s_value(3, i, 0) / 8;
  EXPECT_DOUBLE_EQ(s[0], s11_cube);
  EXPECT_DOUBLE_EQ(s[1 * 6 + 4], test::s_value(3, 8, 5));  // tet YZ = S23
  EXPECT_DOUBLE_EQ(s[1 * 6 + 5], test::s_value(3, 8, 4));  // tet XZ = S13
  const auto mises = f.doubles("/VTKHDF/CellData/S_Mises");
  ASSERT_EQ(mises.size(), 3u);
  EXPECT_GT(mises[2], 0.0);

  // The XDMF arrays of every frame.
  // Mixed topology: per cell its XDMF type, then its nodes (the wedge in VTK order).
  EXPECT_EQ(f.int64s("/xdmf/topology"),
            (std::vector<std::int64_t>{9, 0, 1, 2, 3, 4, 5, 6, 7, 6, 4, 5, 6, 8, 8, 9, 11, 10, 12, 14, 13}));
  EXPECT_EQ(f.int64s("/VTKHDF/Connectivity"),
            (std::vector<std::int64_t>{0, 1, 2, 3, 4, 5, 6, 7, 4, 5, 6, 8, 9, 11, 10, 12, 14, 13}));
  EXPECT_EQ(f.doubles("/xdmf/frames/0/U")[2], test::u_value(0, 0, 2));
  EXPECT_EQ(f.doubles("/xdmf/frames/2/RF")[0], test::rf_value(2, 0, 0));
  EXPECT_TRUE(std::isnan(f.doubles("/xdmf/frames/2/RF")[4 * 3]));
  EXPECT_EQ(f.attr_double("/xdmf/frames/3", "total_time"), 3.0);
}

TEST(ResultsWriter, XdmfSidecarHasATemporalCollectionOfEveryFrame) {
  TempDir dir;
  const auto m = read_model(dir, test::kThreeBodyDeck);
  test::write_three_body_job(dir / "job.h5", m);
  const std::string x = read_text(dir / "job.xdmf");
  EXPECT_NE(x.find("<Xdmf Version=\"3.0\">"), std::string::npos);
  EXPECT_NE(x.find("CollectionType=\"Temporal\""), std::string::npos);
  EXPECT_NE(x.find("<Time Value=\"3\"/>"), std::string::npos);
  EXPECT_NE(x.find("job.h5:/xdmf/frames/3/U"), std::string::npos);
  EXPECT_NE(x.find("job.h5:/model/nodes/coordinates"), std::string::npos);
  EXPECT_NE(x.find("TopologyType=\"Mixed\" NumberOfElements=\"3\""), std::string::npos);
  std::size_t grids = 0;
  for (std::size_t p = x.find("GridType=\"Uniform\""); p != std::string::npos; p = x.find("GridType=\"Uniform\"", p + 1))
    ++grids;
  EXPECT_EQ(grids, 4u);
}

TEST(ResultsWriter, KilledRunKeepsEveryFlushedFrameInThePartFile) {
  TempDir dir;
  const auto m = read_model(dir, test::kThreeBodyDeck);
  const auto h5 = dir / "job.h5";
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    // The child writes three frames and dies without closing anything.
    auto w = io::ResultsWriter::create(h5, m, "sha", "v");
    w.begin_step(m.steps[0]);
    for (int k = 0; k < 3; ++k) w.write_frame(test::three_body_frame(m, k));
    kill(getpid(), SIGKILL);
    _exit(0);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status));
  EXPECT_FALSE(std::filesystem::exists(h5));
  const auto part = dir / "job.h5.part";
  ASSERT_TRUE(std::filesystem::exists(part));

  H5Reader f(part.string());
  ASSERT_TRUE(f.ok()) << "a killed run's .part file must open";
  EXPECT_EQ(f.attr_string("/", "status"), "RUNNING");
  EXPECT_EQ(f.doubles("/steps/Load/frames/total_time"), (std::vector<double>{0.5, 1.0, 2.0}));
  const auto ud = f.doubles("/steps/Load/fieldOutputs/U/data");
  ASSERT_EQ(ud.size(), 3u * 15 * 3);
  EXPECT_EQ(ud[(2 * 15 + 7) * 3 + 1], test::u_value(2, 7, 1));
  EXPECT_EQ(f.doubles("/VTKHDF/PointData/U")[7 * 3 + 1], test::u_value(2, 7, 1));
}

TEST(ResultsReader, StatusAloneAndTheNamelessReadOfAStudy) {
  TempDir dir;
  const auto m = read_model(dir, test::kThreeBodyDeck);
  const auto h5 = dir / "job.h5";
  test::write_three_body_job(h5, m);
  EXPECT_EQ(io::results_status(h5), "COMPLETED");
  EXPECT_EQ(io::results_status(dir / "missing.h5"), "");
  {
    std::ofstream(dir / "text.h5") << "not HDF5\n";
  }
  EXPECT_EQ(io::results_status(dir / "text.h5"), "");

  const io::ResultsFile full = io::read_results(h5);
  io::ReadResultsOptions o;
  o.names = false;
  o.data_for = {"U"};
  const io::ResultsFile lean = io::read_results(h5, o);
  EXPECT_TRUE(lean.node_names.empty());
  EXPECT_TRUE(lean.element_names.empty());
  EXPECT_EQ(lean.nsets, full.nsets);
  EXPECT_EQ(lean.totals.iterations, full.totals.iterations);
  EXPECT_EQ(lean.totals.increments, full.totals.increments);
  ASSERT_EQ(lean.steps.size(), full.steps.size());
  for (std::size_t s = 0; s < full.steps.size(); ++s) {
    ASSERT_EQ(lean.steps[s].fields.size(), full.steps[s].fields.size());
    for (std::size_t i = 0; i < full.steps[s].fields.size(); ++i) {
      const auto& a = full.steps[s].fields[i];
      const auto& b = lean.steps[s].fields[i];
      EXPECT_EQ(b.key, a.key);
      EXPECT_EQ(b.components, a.components);
      EXPECT_TRUE(b.locations.empty());
      if (a.key == "U") {
        EXPECT_EQ(b.data, a.data);
        EXPECT_EQ(b.node_rows, a.node_rows);
      } else {
        EXPECT_TRUE(b.data.empty()) << a.key;
      }
    }
  }
}

TEST(ResultsWriter, UnwritablePathThrowsIoErrorWithoutHdf5Noise) {
  TempDir dir;
  const auto m = read_model(dir, test::kThreeBodyDeck);
  const auto h5 = dir / "no-such-folder" / "job.h5";
  testing::internal::CaptureStderr();
  try {
    auto w = io::ResultsWriter::create(h5, m, "sha", "v");
    ADD_FAILURE() << "create() should have thrown";
  } catch (const io::IoError& e) {
    EXPECT_EQ(e.path(), std::filesystem::path(h5.string() + ".part"));
    EXPECT_NE(std::string(e.what()).find("cannot create the results file"), std::string::npos) << e.what();
  }
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
}

// A beam's S carries its section points: written beside ip, and named "element E ip P sp K" when
// read (0: a location without one).
TEST(ResultsWriter, SectionPointsAreWrittenAndNamed) {
  TempDir dir;
  const auto m = read_model(dir, test::kThreeBodyDeck);
  const auto h5 = dir / "job.h5";
  {
    auto w = io::ResultsWriter::create(h5, m, "sha", "v");
    w.begin_step(m.steps[0]);
    io::Frame f = test::three_body_frame(m, 0);
    io::FieldData& s = f.fields[2];
    ASSERT_EQ(s.key, "S");
    s.section_point.assign(s.elements.size(), 0);
    s.section_point[0] = 25;
    w.write_frame(f);
    w.finish(io::RunStatus::Completed);
  }
  H5Reader f(h5.string());
  EXPECT_EQ(f.int32s("/steps/Load/fieldOutputs/S/section_point").front(), 25);
  EXPECT_FALSE(f.exists("/steps/Load/fieldOutputs/U/section_point"));
  const io::ResultsFile r = io::read_results(h5);
  for (const auto& field : r.steps.at(0).fields)
    if (field.key == "S") {
      EXPECT_EQ(field.locations.at(0), "element 1 ip 1 sp 25");
      EXPECT_EQ(field.locations.at(1), "element 1 ip 2");
    }
}

TEST(ResultsWriter, InconsistentFieldIsRejectedBeforeAnythingIsWritten) {
  TempDir dir;
  const auto m = read_model(dir, test::kThreeBodyDeck);
  auto w = io::ResultsWriter::create(dir / "job.h5", m, "sha", "v");
  EXPECT_THROW(w.write_frame(test::three_body_frame(m, 0)), io::IoError);  // no begin_step yet
  w.begin_step(m.steps[0]);
  io::Frame bad = test::three_body_frame(m, 0);
  bad.fields[0].values.pop_back();  // U: 44 values, not a multiple of 3
  try {
    w.write_frame(bad);
    ADD_FAILURE() << "write_frame should have thrown";
  } catch (const io::IoError& e) {
    EXPECT_NE(std::string(e.what()).find("field U: 44 values is not a multiple of 3 components"), std::string::npos)
        << e.what();
  }
  io::Frame unknown = test::three_body_frame(m, 0);
  unknown.fields[2].elements[0] = 99;  // S at an element that does not exist
  EXPECT_THROW(w.write_frame(unknown), io::IoError);
  w.write_frame(test::three_body_frame(m, 0));
  io::Frame fewer = test::three_body_frame(m, 1);
  fewer.fields[1].nodes.pop_back();  // RF at 3 nodes, 4 in the first frame
  fewer.fields[1].values.resize(9);
  EXPECT_THROW(w.write_frame(fewer), io::IoError);
  w.finish(io::RunStatus::Aborted);
  H5Reader f((dir / "job.h5").string());
  EXPECT_EQ(f.attr_string("/", "status"), "ABORTED");
  EXPECT_EQ(f.doubles("/steps/Load/frames/step_time"), std::vector<double>{0.5});
  EXPECT_EQ(f.dims("/steps/Load/fieldOutputs/U/data"), (std::vector<hsize_t>{1, 15, 3}));
  EXPECT_FALSE(f.exists("/xdmf/frames/1"));
}

TEST(ResultsWriter, StaleResultsOfAnEarlierRunAreRemoved) {
  TempDir dir;
  const auto m = read_model(dir, test::kThreeBodyDeck);
  std::ofstream(dir / "job.h5") << "old";
  std::ofstream(dir / "job.xdmf") << "old";
  auto w = io::ResultsWriter::create(dir / "job.h5", m, "sha", "v");
  EXPECT_FALSE(std::filesystem::exists(dir / "job.h5"));
  EXPECT_FALSE(std::filesystem::exists(dir / "job.xdmf"));
  w.finish(io::RunStatus::Completed);
  const std::string x = read_text(dir / "job.xdmf");
  EXPECT_NE(x.find("<Grid Name=\"model\""), std::string::npos);  // no frames: the mesh alone
}

TEST(ResultsWriter, EveryElementTypeHasAVtkAndXdmfCell) {
  for (const auto& t : model::element_types()) {
    EXPECT_NE(io::vtk_cell_type(t), 0) << t.name;
    EXPECT_NE(io::xdmf_cell_type(t), 0) << t.name;
  }
  EXPECT_EQ(io::vtk_cell_type(*model::find_element_type("C3D20R")), 25);
  EXPECT_EQ(io::vtk_cell_type(*model::find_element_type("C3D10")), 24);
  EXPECT_EQ(io::vtk_cell_type(*model::find_element_type("C3D6")), 13);
  EXPECT_EQ(io::vtk_cell_type(*model::find_element_type("CPE8R")), 23);
  EXPECT_EQ(io::vtk_cell_type(*model::find_element_type("CAX6")), 22);
  EXPECT_EQ(io::vtk_cell_type(*model::find_element_type("T3D2")), 3);    // VTK_LINE
  EXPECT_EQ(io::vtk_cell_type(*model::find_element_type("T3D3")), 21);   // VTK_QUADRATIC_EDGE
  EXPECT_EQ(io::vtk_cell_type(*model::find_element_type("SPRING1")), 1); // VTK_VERTEX
  const auto edge = io::vtk_node_order(*model::find_element_type("T3D3"));  // end, middle, end → end, end, middle
  ASSERT_EQ(edge.size(), 3u);
  EXPECT_EQ(edge[1], 2);
  EXPECT_EQ(io::vtk_cell_type(*model::find_element_type("CPS3")), 5);
  EXPECT_EQ(io::xdmf_cell_type(*model::find_element_type("C3D20")), 48);
}

TEST(ResultsWriter, SingleTypeWedgeMeshSidecarPointsAtVtkOrderedTopology) {
  TempDir dir;
  const auto m = read_model(dir, test::all_types_deck({"C3D6"}));
  test::write_all_types_job(dir / "w.h5", m);
  H5Reader f((dir / "w.h5").string());
  EXPECT_EQ(f.int64s("/xdmf/topology"), (std::vector<std::int64_t>{0, 2, 1, 3, 5, 4}));
  EXPECT_EQ(f.dims("/xdmf/topology"), (std::vector<hsize_t>{1, 6}));
  EXPECT_NE(read_text(dir / "w.xdmf").find("w.h5:/xdmf/topology"), std::string::npos);
}

TEST(ResultsWriter, AllElementTypesJobWritesOneCellEach) {
  TempDir dir;
  const auto m = read_model(dir, test::all_types_deck());
  test::write_all_types_job(dir / "all.h5", m);
  H5Reader f((dir / "all.h5").string());
  EXPECT_EQ(f.read<std::uint8_t>("/VTKHDF/Types", H5T_NATIVE_UINT8),
            (std::vector<std::uint8_t>{12, 25, 10, 24, 13, 9, 23, 5, 22}));
  const auto xyz = f.doubles("/model/nodes/coordinates");
  // 2D elements keep 3D coordinates with z = 0.
  EXPECT_EQ(xyz[(8 + 20 + 4 + 10 + 6) * 3 + 2], 0.0);
  EXPECT_TRUE(f.exists("/xdmf/topology"));
}

TEST(ResultsWriter, SingleTypeMeshSidecarPointsAtItsConnectivity) {
  TempDir dir;
  const auto m = read_model(dir, test::all_types_deck({"C3D20"}));
  test::write_all_types_job(dir / "hex20.h5", m);
  H5Reader f((dir / "hex20.h5").string());
  EXPECT_FALSE(f.exists("/xdmf/topology"));
  const std::string x = read_text(dir / "hex20.xdmf");
  EXPECT_NE(x.find("<Topology TopologyType=\"Hexahedron_20\" NumberOfElements=\"1\">"), std::string::npos) << x;
  EXPECT_NE(x.find("Dimensions=\"1 20\" NumberType=\"Int\" Precision=\"8\" Format=\"HDF\">hex20.h5:/model/elements/C3D20/connectivity"),
            std::string::npos) << x;
}

/// Writes the sample jobs the Python reader tests (tests/io/*.py) read, into
/// $INPACT_IO_SAMPLE_DIR; skipped when that is not set.
TEST(PythonSample, WriteJobs) {
  const char* out = std::getenv("INPACT_IO_SAMPLE_DIR");
  if (!out) GTEST_SKIP() << "INPACT_IO_SAMPLE_DIR not set";
  const std::filesystem::path dir(out);
  std::filesystem::create_directories(dir);
  TempDir tmp;
  test::write_three_body_job(dir / "three_body.h5", read_model(tmp, test::kThreeBodyDeck));
  test::write_all_types_job(dir / "all_types.h5", read_model(tmp, test::all_types_deck()));
  test::write_all_types_job(dir / "hex20.h5", read_model(tmp, test::all_types_deck({"C3D20"})));
}

TEST(ResultsWriter, StepHoldsTheContactInteractionsAsTheAnalysisEnforcesThem) {
  TempDir dir;
  const auto m = read_model(dir, test::kThreeBodyDeck);
  const auto h5 = dir / "job.h5";
  auto w = io::ResultsWriter::create(h5, m, std::string(64, 'a'), "0.1.0-test");
  w.begin_step(m.steps.at(0));
  const std::vector<std::string> lines = {"contact pair SLAVE_S/MASTER_S: node to surface, finite sliding; ...",
                                          "second line"};
  w.write_contact_interactions(lines);
  w.write_frame(test::three_body_frame(m, 0));
  w.finish(io::RunStatus::Completed);
  H5Reader f(h5.string());
  EXPECT_EQ(f.strings("/steps/" + m.steps.at(0).name + "/contact_interactions"), lines);
}

// A shell's S varies through its thickness: the view gives one cell array per section point
// (S_SP<k>, the mean over the element's in-plane points at that section point, and its von
// Mises), and leaves S itself empty on shells, whose mean over SNEG and SPOS would hide bending.
TEST(ResultsView, ShellsGetOneCellArrayPerSectionPoint) {
  TempDir dir;
  const auto m = read_model(dir, "*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n3, 1., 1., 0.\n4, 0., 1., 0.\n5, 2., 0., 0.\n"
                                 "6, 2., 1., 0.\n*ELEMENT, TYPE=S4, ELSET=PLATE\n1, 1, 2, 3, 4\n2, 2, 5, 6, 3\n"
                                 "*MATERIAL, NAME=M\n*ELASTIC\n2e5, 0.3\n*SHELL SECTION, ELSET=PLATE, MATERIAL=M\n0.1\n"
                                 "*STEP\n*STATIC\n*END STEP\n");
  solver::FieldData s;
  s.key = "S";
  s.position = solver::Position::IntegrationPoint;
  s.component_labels = {"S11", "S22", "S33", "S12", "S13", "S23"};
  // Element 1 at in-plane points 1 and 2, element 2 at point 1: SNEG (1) and SPOS (5) each.
  s.elements = {1, 1, 1, 1, 2, 2};
  s.ip = {1, 1, 2, 2, 1, 1};
  s.section_point = {1, 5, 1, 5, 1, 5};
  const double s11[] = {-10, 10, -20, 20, -30, 30};
  for (double v : s11) s.values.insert(s.values.end(), {v, 0, 0, 0, 0, 0});
  solver::Frame frame;
  frame.fields.push_back(s);
  const auto arrays = io::build_view_arrays(m, frame, dir / "job.h5");
  auto array = [&](const std::string& name) -> const io::ViewArray* {
    for (const auto& a : arrays)
      if (a.name == name) return &a;
    return nullptr;
  };
  const io::ViewArray* sneg = array("S_SP1");
  const io::ViewArray* spos = array("S_SP5");
  ASSERT_TRUE(sneg && spos && array("S_SP1_Mises") && array("S"));
  EXPECT_DOUBLE_EQ(sneg->values[0], -15.0);  // cell 0, XX: the mean of −10 and −20
  EXPECT_DOUBLE_EQ(spos->values[6], 30.0);   // cell 1, XX
  EXPECT_DOUBLE_EQ(array("S_SP1_Mises")->values[1], 30.0);
  EXPECT_TRUE(std::isnan(array("S")->values[0]));
}
