#include "results_writer.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <set>

#include <fmt/format.h>

#include "contact/interaction_table.hpp"
#include "hdf5_util.hpp"
#include "results_view.hpp"
#include "xdmf_writer.hpp"

namespace inpact::io {

namespace fs = std::filesystem;
using h5::Id;

namespace {

constexpr std::int32_t kSchemaVersion = 1;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
/// Target size of one chunk of a field's data (bytes): large enough that a frame of a big
/// model is a few direct writes, small enough to read one component range cheaply.
constexpr std::size_t kChunkBytes = std::size_t{1} << 20;
/// Block HDF5 reserves for metadata, and for small datasets, at a time (see results_file_access).
constexpr hsize_t kMetadataBlockBytes = 16 * 1024;

/// File access of a results file. HDF5 places each new piece of metadata (object headers,
/// group B-trees and heaps, attributes) in a block it reserves for metadata, by default 2 KiB
/// at a time, between the data of the datasets written in between; a results file holds a few
/// hundred such pieces. 16 KiB blocks keep more of them side by side, so that a flush writes
/// them in fewer writes (229 → 198 for the study bench's case; the file grows by 240 bytes).
/// The same for small datasets (sets, index arrays).
h5::Id results_file_access() {
  Id fapl(H5Pcreate(H5P_FILE_ACCESS));
  H5Pset_meta_block_size(fapl, kMetadataBlockBytes);
  H5Pset_small_data_block_size(fapl, kMetadataBlockBytes);
  return fapl;
}

/// An HDF5 link name for a model name: '/' would make a path, "." is reserved.
std::string link_name(const std::string& name) {
  std::string s = name.empty() ? "_" : name;
  std::replace(s.begin(), s.end(), '/', '_');
  if (s == ".") s = "_";
  return s;
}

/// The .sta row as stored in /status (one compound record).
struct StatusRecord {
  std::int32_t step, increment, attempt;
  std::int8_t cut_back;
  std::int32_t severe_discon_iters, equil_iters, total_iters;
  double total_time, step_time, inc_of_time;
  std::int32_t augmentations;
};

Id status_memory_type() {
  Id t(H5Tcreate(H5T_COMPOUND, sizeof(StatusRecord)));
  H5Tinsert(t, "step", HOFFSET(StatusRecord, step), H5T_NATIVE_INT32);
  H5Tinsert(t, "increment", HOFFSET(StatusRecord, increment), H5T_NATIVE_INT32);
  H5Tinsert(t, "attempt", HOFFSET(StatusRecord, attempt), H5T_NATIVE_INT32);
  H5Tinsert(t, "cut_back", HOFFSET(StatusRecord, cut_back), H5T_NATIVE_INT8);
  H5Tinsert(t, "severe_discon_iters", HOFFSET(StatusRecord, severe_discon_iters), H5T_NATIVE_INT32);
  H5Tinsert(t, "equil_iters", HOFFSET(StatusRecord, equil_iters), H5T_NATIVE_INT32);
  H5Tinsert(t, "total_iters", HOFFSET(StatusRecord, total_iters), H5T_NATIVE_INT32);
  H5Tinsert(t, "total_time", HOFFSET(StatusRecord, total_time), H5T_NATIVE_DOUBLE);
  H5Tinsert(t, "step_time", HOFFSET(StatusRecord, step_time), H5T_NATIVE_DOUBLE);
  H5Tinsert(t, "inc_of_time", HOFFSET(StatusRecord, inc_of_time), H5T_NATIVE_DOUBLE);
  H5Tinsert(t, "augmentations", HOFFSET(StatusRecord, augmentations), H5T_NATIVE_INT32);
  return t;
}

const char* procedure_name(const model::Step& step) { return step.static_procedure ? "STATIC" : "NONE"; }

}  // namespace

const char* position_name(Position p) {
  switch (p) {
    case Position::Nodal: return "NODAL";
    case Position::IntegrationPoint: return "INTEGRATION_POINT";
    case Position::ElementNodal: return "ELEMENT_NODAL";
    case Position::Centroid: return "CENTROID";
  }
  return "NODAL";
}

std::vector<std::string> contact_pair_names(const model::Model& model) {
  std::vector<std::string> names;
  const auto table = contact::interaction_table(model);  // (kept alive: the loop reads its rows)
  for (const auto& row : table->rows) names.push_back(row.name());
  return names;
}

// ---------------------------------------------------------------------------------------------

struct ResultsWriter::Impl {
  struct FieldState {
    Id data;
    hsize_t nloc = 0;
    hsize_t n_comp = 0;
    hsize_t rows_per_chunk = 1;
    Position position = Position::Nodal;
  };
  struct StepState {
    std::string name;
    Id group, frames, field_outputs;
    Id step_time, total_time, increment;
    hsize_t n_frames = 0;
    std::map<std::string, FieldState> fields;
    std::map<std::string, Id> history;  ///< frames/<KEY>: whole-model history values (ALLSE, ALLSD)
  };

  Impl(fs::path h5, const model::Model& m)
      : h5_path(std::move(h5)), part_path(fs::path(h5_path).concat(".part")), ctx(part_path), model(&m) {}

  fs::path h5_path, part_path;
  h5::Context ctx;
  const model::Model* model;
  Id file;
  Id status_type;
  Id status;
  hsize_t n_status = 0;
  std::optional<StepState> step;
  std::set<std::string> step_names;
  int n_steps = 0;
  Id view_frames, vtk_point_data, vtk_cell_data;
  std::vector<XdmfFrame> xdmf_frames;
  std::size_t topology_length = 0;
  bool single_type = false;
  bool flush_each_frame = true;
  bool finished = false;

  void write_model(const std::vector<std::string>& pair_names);
  void write_view_geometry();
  void write_view_frame(const Frame& frame, const std::vector<ViewArray>& arrays);
  void write_history(const Frame& frame, hsize_t row);
  FieldState& field_state(const FieldData& f, hsize_t n_comp, hsize_t nloc);
  void flush();
  void close();
};

void ResultsWriter::Impl::write_model(const std::vector<std::string>& pair_names) {
  const model::Mesh& mesh = model->mesh;
  Id g = ctx.create_group(file, "model");

  // Nodes.
  {
    Id nodes = ctx.create_group(g, "nodes");
    ctx.write(nodes, "labels", mesh.nodes.labels);
    std::vector<double> xyz;
    xyz.reserve(mesh.nodes.size() * 3);
    for (const auto& c : mesh.nodes.coords) xyz.insert(xyz.end(), c.begin(), c.end());
    ctx.write(nodes, "coordinates", xyz, 3);
    ctx.write(nodes, "instance", mesh.nodes.instance);
  }
  ctx.write_strings(g, "instances", model->instances);

  // Elements, one group per type, in element-row order within each type.
  {
    Id elements = ctx.create_group(g, "elements");
    const auto& el = mesh.elements;
    std::map<std::uint8_t, std::vector<std::int64_t>> rows_of_type;
    for (std::size_t e = 0; e < el.size(); ++e) rows_of_type[el.type[e]].push_back(static_cast<std::int64_t>(e));
    for (const auto& [type, rows] : rows_of_type) {
      const auto& info = model::element_type(type);
      Id tg = ctx.create_group(elements, std::string(info.name));
      std::vector<std::int64_t> labels, conn;
      std::vector<std::int32_t> instance;
      labels.reserve(rows.size());
      instance.reserve(rows.size());
      conn.reserve(rows.size() * info.n_nodes);
      for (std::int64_t e : rows) {
        labels.push_back(el.labels[e]);
        instance.push_back(el.instance[e]);
        for (std::int32_t n : el.nodes_of(e)) conn.push_back(n);
      }
      ctx.write(tg, "labels", labels);
      ctx.write(tg, "connectivity", conn, info.n_nodes);
      ctx.write(tg, "instance", instance);
      ctx.write(tg, "rows", rows);
    }
  }

  // Sets and surfaces: node rows, element rows, (element row, face) pairs.
  {
    Id sets = ctx.create_group(g, "sets");
    auto write_sets = [&](const char* group, const std::map<std::string, model::Set>& map) {
      Id sg = ctx.create_group(sets, group);
      for (const auto& [key, set] : map) {
        std::vector<std::int64_t> rows(set.rows.begin(), set.rows.end());
        const std::string name = link_name(key);
        ctx.write(sg, name, rows);
        Id ds = ctx.open_dataset(sg, name);
        ctx.attr_string(ds, "name", set.name);
        if (set.internal) ctx.attr_int(ds, "internal", 1);
      }
    };
    write_sets("nsets", mesh.nsets);
    write_sets("elsets", mesh.elsets);
    Id sg = ctx.create_group(sets, "surfaces");
    for (const auto& [key, surf] : mesh.surfaces) {
      const std::string name = link_name(key);
      if (surf.kind == model::Surface::Kind::Element) {
        // (element row, face) pairs; a surface of shell edges: (element row, edge), 0 = E1.
        const auto& pieces = surf.edges.empty() ? surf.faces : surf.edges;
        std::vector<std::int64_t> faces;
        faces.reserve(pieces.size() * 2);
        for (const auto& f : pieces) {
          faces.push_back(f.element);
          faces.push_back(f.face);
        }
        ctx.write(sg, name, faces, 2);
      } else {
        std::vector<std::int64_t> rows(surf.nodes.begin(), surf.nodes.end());
        ctx.write(sg, name, rows);
      }
      Id ds = ctx.open_dataset(sg, name);
      ctx.attr_string(ds, "name", surf.name);
      ctx.attr_string(ds, "kind", !surf.edges.empty()                         ? "SHELL EDGES"
                                 : surf.kind == model::Surface::Kind::Element ? "ELEMENT"
                                 : surf.kind == model::Surface::Kind::Node ? "NODE" : "ANALYTICAL");
    }
  }

  Id contact = ctx.create_group(g, "contact");
  ctx.write_strings(contact, "pairs", pair_names);
}

void ResultsWriter::Impl::write_view_geometry() {
  // /VTKHDF, version 1.0 (what ParaView 5.11 / VTK 9.2 reads; its reader has no time steps):
  // one unstructured grid whose point and cell data are hard links to the last frame's view
  // arrays. Points is a hard link to /model/nodes/coordinates, so the mesh is stored once.
  const ViewTopology topo = build_view_topology(model->mesh);
  Id vtk = ctx.create_group(file, "VTKHDF");
  ctx.attr_ints(vtk, "Version", {1, 0});
  ctx.attr_fixed_string(vtk, "Type", "UnstructuredGrid");
  const std::vector<std::int64_t> n_points{static_cast<std::int64_t>(model->mesh.nodes.size())};
  const std::vector<std::int64_t> n_cells{static_cast<std::int64_t>(topo.vtk_types.size())};
  const std::vector<std::int64_t> n_conn{static_cast<std::int64_t>(topo.vtk_connectivity.size())};
  ctx.write(vtk, "NumberOfPoints", n_points);
  ctx.write(vtk, "NumberOfCells", n_cells);
  ctx.write(vtk, "NumberOfConnectivityIds", n_conn);
  ctx.check(H5Lcreate_hard(file, "/model/nodes/coordinates", vtk, "Points", H5P_DEFAULT, H5P_DEFAULT),
            "cannot link /VTKHDF/Points");
  ctx.write(vtk, "Types", topo.vtk_types);
  ctx.write(vtk, "Offsets", topo.vtk_offsets);
  ctx.write(vtk, "Connectivity", topo.vtk_connectivity);
  vtk_point_data = ctx.create_group(vtk, "PointData");
  vtk_cell_data = ctx.create_group(vtk, "CellData");

  // /xdmf: per frame, the view arrays the sidecar points at; for a mesh of several element
  // types also the mixed topology (one type: the sidecar points at its connectivity).
  Id x = ctx.create_group(file, "xdmf");
  const auto& types = model->mesh.elements.type;
  single_type = !types.empty() && std::all_of(types.begin(), types.end(), [&](auto t) { return t == types[0]; });
  if (!single_type) {
    ctx.write(x, "topology", topo.xdmf_mixed);
    topology_length = topo.xdmf_mixed.size();
  } else if (!vtk_node_order(model::element_type(types[0])).empty()) {
    ctx.write(x, "topology", topo.vtk_connectivity, model::element_type(types[0]).n_nodes);
  }
  view_frames = ctx.create_group(x, "frames", true);
}

/// The frame's history values as /steps/<STEP>/frames/<KEY> (nf,), created at their first frame
/// (earlier rows NaN); keys absent from this frame get NaN in its row.
void ResultsWriter::Impl::write_history(const Frame& frame, hsize_t row) {
  for (const solver::HistoryValue& h : frame.history) {
    auto it = step->history.find(h.key);
    if (it == step->history.end())
      it = step->history.emplace(h.key, ctx.create_extendable(step->frames, h.key, H5T_NATIVE_DOUBLE, {0}, {256}, &kNaN))
               .first;
    ctx.write_rows(it->second, H5T_NATIVE_DOUBLE, row, 1, &h.value);
  }
  for (auto& [key, id] : step->history) ctx.extend(id, row + 1);
}

void ResultsWriter::Impl::write_view_frame(const Frame& frame, const std::vector<ViewArray>& arrays) {
  const std::size_t k = xdmf_frames.size();
  const std::string name = std::to_string(k);
  Id g = ctx.create_group(view_frames, name);
  ctx.attr_string(g, "step", step->name);
  ctx.attr_int(g, "increment", frame.increment);
  ctx.attr_double(g, "step_time", frame.step_time);
  ctx.attr_double(g, "total_time", frame.total_time);

  // Relink /VTKHDF/PointData and CellData to this frame's arrays.
  for (hid_t group : {vtk_point_data.get(), vtk_cell_data.get()}) {
    H5G_info_t info;
    ctx.check(H5Gget_info(group, &info), "cannot list /VTKHDF arrays");
    std::vector<std::string> old;
    for (hsize_t i = 0; i < info.nlinks; ++i) {
      char buf[1024];
      const ssize_t len = H5Lget_name_by_idx(group, ".", H5_INDEX_NAME, H5_ITER_INC, i, buf, sizeof buf, H5P_DEFAULT);
      if (len > 0) old.emplace_back(buf, static_cast<std::size_t>(len));
    }
    for (const auto& o : old) ctx.check(H5Ldelete(group, o.c_str(), H5P_DEFAULT), "cannot unlink /VTKHDF/" + o);
  }

  XdmfFrame xf{fmt::format("{} frame {}", step->name, step->n_frames - 1), frame.total_time, {}};
  for (const ViewArray& a : arrays) {
    const std::string array_name = link_name(a.name);
    const hsize_t n_rows = a.values.size() / a.n_comp;
    ctx.write(g, array_name, a.values, a.n_comp > 1 ? a.n_comp : 0);
    ctx.check(H5Lcreate_hard(g, array_name.c_str(), a.cell ? vtk_cell_data : vtk_point_data, array_name.c_str(),
                             H5P_DEFAULT, H5P_DEFAULT),
              "cannot link /VTKHDF array " + array_name);
    xf.attributes.push_back({a.name, a.cell, n_rows, a.n_comp, "/xdmf/frames/" + name + "/" + array_name});
  }
  xdmf_frames.push_back(std::move(xf));
}

ResultsWriter::Impl::FieldState& ResultsWriter::Impl::field_state(const FieldData& f, hsize_t n_comp, hsize_t nloc) {
  auto it = step->fields.find(f.key);
  if (it != step->fields.end()) return it->second;  // checked by write_frame
  // First appearance in this step: the data set, its attributes and its location indices.
  Id g = ctx.create_group(step->field_outputs, link_name(f.key));
  ctx.attr_string(g, "position", position_name(f.position));
  ctx.attr_strings(g, "componentLabels", f.component_labels);
  ctx.attr_string(g, "region", f.region);
  const hsize_t rows_per_chunk =
      std::clamp<hsize_t>(kChunkBytes / (n_comp * sizeof(double)), 1, std::max<hsize_t>(nloc, 1));
  FieldState s;
  s.nloc = nloc;
  s.n_comp = n_comp;
  s.rows_per_chunk = rows_per_chunk;
  s.position = f.position;
  // Frames before the field's first appearance (and any frame without it) read as NaN.
  s.data = ctx.create_extendable(g, "data", H5T_NATIVE_DOUBLE, {step->n_frames, nloc, n_comp},
                                 {1, rows_per_chunk, n_comp}, &kNaN);
  if (f.position == Position::Nodal) {
    if (f.nodes.empty()) {
      std::vector<std::int64_t> all(nloc);
      for (hsize_t i = 0; i < nloc; ++i) all[i] = static_cast<std::int64_t>(i);
      ctx.write(g, "nodes", all);
    } else {
      ctx.write(g, "nodes", f.nodes);
    }
  }
  if (!f.elements.empty()) ctx.write(g, "elements", f.elements);
  if (!f.instance.empty()) ctx.write(g, "instance", f.instance);
  if (!f.ip.empty()) ctx.write(g, "ip", f.ip);
  if (!f.section_point.empty()) ctx.write(g, "section_point", f.section_point);
  if (!f.pair.empty()) ctx.write(g, "pair", f.pair);
  return step->fields.emplace(f.key, std::move(s)).first->second;
}

void ResultsWriter::Impl::flush() {
  if (H5Fflush(file, H5F_SCOPE_GLOBAL) < 0) ctx.fail("cannot flush the results file");
}

void ResultsWriter::Impl::close() {
  step.reset();
  status.reset();
  status_type.reset();
  view_frames.reset();
  vtk_point_data.reset();
  vtk_cell_data.reset();
  if (file.valid()) {
    const herr_t rc = H5Fclose(file.release());
    if (rc < 0) ctx.fail("cannot close the results file");
  }
}

// ---------------------------------------------------------------------------------------------

ResultsWriter::ResultsWriter(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
ResultsWriter::ResultsWriter(ResultsWriter&&) noexcept = default;
ResultsWriter& ResultsWriter::operator=(ResultsWriter&&) noexcept = default;

ResultsWriter::~ResultsWriter() {
  if (!impl_) return;
  try {
    impl_->close();
  } catch (const IoError&) {
    // Destructors do not throw; the .part file stays as evidence.
  }
}

void start_results_library() { h5::silence_hdf5_errors(); }

ResultsWriter ResultsWriter::create(const fs::path& h5_path, const model::Model& model, std::string deck_sha256,
                                    std::string solver_version, const ResultsOptions& options) {
  h5::silence_hdf5_errors();
  auto impl = std::make_unique<Impl>(h5_path, model);
  Impl& w = *impl;
  w.flush_each_frame = options.flush_each_frame;
  std::error_code ec;
  // Results of an earlier run of the same job must not pass for this run's.
  fs::remove(w.h5_path, ec);
  fs::remove(fs::path(w.h5_path).replace_extension(".xdmf"), ec);

  // Default (earliest) format bounds: a file whose writer was killed opens without h5clear.
  w.file = Id(w.ctx.check(H5Fcreate(w.part_path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, results_file_access()),
                          "cannot create the results file"));
  w.ctx.attr_string(w.file, "schema", "inpact-results");
  w.ctx.attr_int(w.file, "schema_version", kSchemaVersion);
  w.ctx.attr_string(w.file, "solver_version", solver_version);
  w.ctx.attr_string(w.file, "deck_sha256", deck_sha256);
  w.ctx.attr_string(w.file, "status", "RUNNING");
  if (!options.linear_solver.empty()) {
    w.ctx.attr_string(w.file, "linear_solver", options.linear_solver);
    w.ctx.attr_string(w.file, "linear_solver_choice", options.linear_solver_choice);
  }

  w.write_model(options.contact_pairs ? *options.contact_pairs : contact_pair_names(model));
  w.ctx.create_group(w.file, "steps", true);

  w.status_type = status_memory_type();
  Id file_type(H5Tcopy(w.status_type));
  H5Tpack(file_type);
  Id dcpl(H5Pcreate(H5P_DATASET_CREATE));
  const hsize_t zero = 0, unlimited = H5S_UNLIMITED, chunk = 256;
  H5Pset_chunk(dcpl, 1, &chunk);
  Id space(H5Screate_simple(1, &zero, &unlimited));
  w.status = Id(w.ctx.check(H5Dcreate2(w.file, "status", file_type, space, H5P_DEFAULT, dcpl, H5P_DEFAULT),
                            "cannot create /status"));

  w.write_view_geometry();
  w.flush();
  return ResultsWriter(std::move(impl));
}

void ResultsWriter::begin_step(const model::Step& s) {
  Impl& w = *impl_;
  std::string name = link_name(s.name);
  for (int i = 2; w.step_names.count(name); ++i) name = fmt::format("{} ({})", link_name(s.name), i);
  w.step_names.insert(name);
  w.step.reset();
  Impl::StepState st;
  st.name = name;
  Id steps = w.ctx.open_group(w.file, "steps");
  st.group = w.ctx.create_group(steps, name);
  w.ctx.attr_string(st.group, "procedure", procedure_name(s));
  w.ctx.attr_int(st.group, "nlgeom", s.nlgeom ? 1 : 0);
  w.ctx.attr_double(st.group, "time_period", s.static_procedure ? s.static_procedure->time_period : 1.0);
  w.ctx.attr_int(st.group, "number", ++w.n_steps);
  st.frames = w.ctx.create_group(st.group, "frames");
  st.step_time = w.ctx.create_extendable(st.frames, "step_time", H5T_NATIVE_DOUBLE, {0}, {256});
  st.total_time = w.ctx.create_extendable(st.frames, "total_time", H5T_NATIVE_DOUBLE, {0}, {256});
  st.increment = w.ctx.create_extendable(st.frames, "increment", H5T_NATIVE_INT32, {0}, {256});
  st.field_outputs = w.ctx.create_group(st.group, "fieldOutputs", true);
  w.step = std::move(st);
}

void ResultsWriter::write_contact_interactions(const std::vector<std::string>& lines) {
  Impl& w = *impl_;
  if (!w.step) w.ctx.fail("write_contact_interactions called before begin_step");
  w.ctx.write_strings(w.step->group, "contact_interactions", lines);
}

void ResultsWriter::write_frame(const Frame& frame) {
  Impl& w = *impl_;
  if (!w.step) w.ctx.fail("write_frame called before begin_step");
  Impl::StepState& st = *w.step;

  // Check every field before writing anything, so a bad field leaves the file as it was.
  std::set<std::string> keys;
  for (const FieldData& f : frame.fields) {
    const std::size_t n_comp = f.component_labels.size();
    auto bad = [&](const std::string& why) { w.ctx.fail(fmt::format("step '{}', field {}: {}", st.name, f.key, why)); };
    if (f.key.empty()) bad("empty field key");
    if (!keys.insert(f.key).second) bad("written twice in one frame");
    if (n_comp == 0) bad("no component labels");
    if (f.values.size() % n_comp) bad(fmt::format("{} values is not a multiple of {} components", f.values.size(), n_comp));
    const std::size_t nloc = f.values.size() / n_comp;
    auto check_size = [&](std::size_t size, const char* what) {
      if (size && size != nloc) bad(fmt::format("{} {} for {} locations", size, what, nloc));
    };
    check_size(f.nodes.size(), "nodes");
    check_size(f.elements.size(), "elements");
    check_size(f.instance.size(), "instances");
    check_size(f.ip.size(), "integration points");
    check_size(f.section_point.size(), "section points");
    check_size(f.pair.size(), "pairs");
    const std::size_t n_nodes = w.model->mesh.nodes.size();
    if (f.position == Position::Nodal) {
      if (f.nodes.empty() && nloc != n_nodes) bad(fmt::format("{} locations without node rows, model has {} nodes", nloc, n_nodes));
      for (std::int64_t n : f.nodes)
        if (n < 0 || static_cast<std::size_t>(n) >= n_nodes) bad(fmt::format("node row {} out of range", n));
    } else if (f.elements.size() != nloc) {
      bad("an element-based field needs one element label per location");
    }
    if (auto it = st.fields.find(f.key); it != st.fields.end()) {
      const Impl::FieldState& s = it->second;
      if (s.nloc != nloc || s.n_comp != n_comp || s.position != f.position)
        bad(fmt::format("{} locations × {} components ({}), but {} × {} ({}) in an earlier frame; a field keeps "
                        "its locations within a step",
                        nloc, n_comp, position_name(f.position), s.nloc, s.n_comp, position_name(s.position)));
    }
  }
  // The view arrays resolve element labels: unknown labels throw here, still before writing.
  const std::vector<ViewArray> arrays = build_view_arrays(*w.model, frame, w.part_path);

  const hsize_t row = st.n_frames++;
  w.ctx.write_rows(st.step_time, H5T_NATIVE_DOUBLE, row, 1, &frame.step_time);
  w.ctx.write_rows(st.total_time, H5T_NATIVE_DOUBLE, row, 1, &frame.total_time);
  const std::int32_t inc = frame.increment;
  w.ctx.write_rows(st.increment, H5T_NATIVE_INT32, row, 1, &inc);
  for (const FieldData& f : frame.fields) {
    const hsize_t n_comp = f.component_labels.size();
    Impl::FieldState& s = w.field_state(f, n_comp, f.values.size() / n_comp);
    w.ctx.write_frame_chunks(s.data, row, s.nloc, s.rows_per_chunk, s.n_comp, f.values.data(), kNaN);
  }
  // Fields absent from this frame still get its row (NaN), so data rows match frames.
  for (auto& [key, s] : st.fields) w.ctx.extend(s.data, st.n_frames);
  w.write_history(frame, row);

  w.write_view_frame(frame, arrays);
  if (w.flush_each_frame) w.flush();
}

void ResultsWriter::append_status(std::span<const StatusRow> rows) {
  Impl& w = *impl_;
  if (rows.empty()) return;
  std::vector<StatusRecord> records;
  records.reserve(rows.size());
  for (const StatusRow& r : rows)
    records.push_back({r.step, r.increment, r.attempt, static_cast<std::int8_t>(r.cut_back ? 1 : 0),
                       r.severe_discon_iters, r.equil_iters, r.total_iters, r.total_time, r.step_time, r.inc_of_time,
                       r.augmentations});
  w.ctx.write_rows(w.status, w.status_type, w.n_status, records.size(), records.data());
  w.n_status += records.size();
}

void ResultsWriter::finish(RunStatus status) {
  Impl& w = *impl_;
  if (w.finished) return;
  w.ctx.attr_string(w.file, "status", status == RunStatus::Completed ? "COMPLETED" : "ABORTED");
  w.close();
  w.finished = true;
  std::error_code ec;
  fs::rename(w.part_path, w.h5_path, ec);
  if (ec) throw IoError(w.part_path, "cannot rename to " + w.h5_path.filename().string() + ": " + ec.message());

  XdmfMesh mesh;
  mesh.h5_file = w.h5_path.filename().string();
  mesh.n_nodes = w.model->mesh.nodes.size();
  mesh.n_cells = w.model->mesh.elements.size();
  mesh.coordinates_path = "/model/nodes/coordinates";
  if (w.single_type) {
    const auto& type = model::element_type(w.model->mesh.elements.type[0]);
    mesh.topology_type = xdmf_topology_name(type);
    mesh.nodes_per_cell = type.n_nodes;
    mesh.topology_path = vtk_node_order(type).empty() ? "/model/elements/" + std::string(type.name) + "/connectivity"
                                                      : "/xdmf/topology";
  } else {
    mesh.topology_length = w.topology_length;
    mesh.topology_path = "/xdmf/topology";
  }
  std::vector<XdmfFrame> frames = w.xdmf_frames;
  if (frames.empty()) frames.push_back({"model", 0.0, {}});  // the mesh alone still opens
  write_xdmf(xdmf_path(), mesh, frames);
}

const fs::path& ResultsWriter::part_path() const { return impl_->part_path; }
const fs::path& ResultsWriter::h5_path() const { return impl_->h5_path; }
fs::path ResultsWriter::xdmf_path() const { return fs::path(impl_->h5_path).replace_extension(".xdmf"); }
std::size_t ResultsWriter::n_frames() const { return impl_->xdmf_frames.size(); }

}  // namespace inpact::io
