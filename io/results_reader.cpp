#include "results_reader.hpp"

#include <algorithm>
#include <cctype>
#include <system_error>

#include <fmt/format.h>

#include "hdf5_util.hpp"

namespace inpact::io {

namespace fs = std::filesystem;
using h5::Id;

namespace {

/// Read-side helpers over one open file; every failure throws IoError naming the file.
class Reader {
 public:
  explicit Reader(const fs::path& path) : ctx_(path) {}
  h5::Context& ctx() { return ctx_; }

  bool has_attr(hid_t obj, const std::string& name) const { return H5Aexists(obj, name.c_str()) > 0; }

  std::string attr_string(hid_t obj, const std::string& name) const {
    if (!has_attr(obj, name)) return "";
    Id a(ctx_.check(H5Aopen(obj, name.c_str(), H5P_DEFAULT), "cannot open attribute '" + name + "'"));
    Id ftype(H5Aget_type(a));
    if (H5Tget_class(ftype) != H5T_STRING) return "";
    if (H5Tis_variable_str(ftype) > 0) {
      Id type = h5::vlen_string_type();
      char* p = nullptr;
      ctx_.check(H5Aread(a, type, &p), "cannot read attribute '" + name + "'");
      std::string s = p ? p : "";
      H5free_memory(p);
      return s;
    }
    std::string s(H5Tget_size(ftype), '\0');
    ctx_.check(H5Aread(a, ftype, s.data()), "cannot read attribute '" + name + "'");
    return s.substr(0, s.find('\0'));
  }

  std::vector<std::string> attr_strings(hid_t obj, const std::string& name) const {
    std::vector<std::string> out;
    if (!has_attr(obj, name)) return out;
    Id a(ctx_.check(H5Aopen(obj, name.c_str(), H5P_DEFAULT), "cannot open attribute '" + name + "'"));
    Id space(H5Aget_space(a));
    const hssize_t n = H5Sget_simple_extent_npoints(space);
    if (n <= 0) return out;
    Id type = h5::vlen_string_type();
    std::vector<char*> ptrs(static_cast<std::size_t>(n));
    ctx_.check(H5Aread(a, type, ptrs.data()), "cannot read attribute '" + name + "'");
    for (char* p : ptrs) out.emplace_back(p ? p : "");
    H5Dvlen_reclaim(type, space, H5P_DEFAULT, ptrs.data());
    return out;
  }

  std::vector<hsize_t> dims(hid_t ds) const {
    Id space(ctx_.check(H5Dget_space(ds), "cannot get dataspace"));
    const int rank = H5Sget_simple_extent_ndims(space);
    std::vector<hsize_t> d(static_cast<std::size_t>(std::max(rank, 0)));
    H5Sget_simple_extent_dims(space, d.data(), nullptr);
    return d;
  }

  template <class T>
  std::vector<T> read(hid_t parent, const std::string& name) const {
    Id ds = ctx_.open_dataset(parent, name);
    std::size_t n = 1;
    for (hsize_t d : dims(ds)) n *= d;
    std::vector<T> out(n);
    if (n) ctx_.check(H5Dread(ds, h5::native_type<T>(), H5S_ALL, H5S_ALL, h5::transfer_plist(), out.data()),
                      "cannot read dataset '" + name + "'");
    return out;
  }

  std::vector<std::string> read_strings(hid_t parent, const std::string& name) const {
    Id ds = ctx_.open_dataset(parent, name);
    const auto d = dims(ds);
    const std::size_t n = d.empty() ? 0 : d[0];
    std::vector<std::string> out;
    if (!n) return out;
    Id type = h5::vlen_string_type();
    std::vector<char*> ptrs(n);
    ctx_.check(H5Dread(ds, type, H5S_ALL, H5S_ALL, h5::transfer_plist(), ptrs.data()), "cannot read dataset '" + name + "'");
    for (char* p : ptrs) out.emplace_back(p ? p : "");
    Id space(H5Dget_space(ds));
    H5Dvlen_reclaim(type, space, H5P_DEFAULT, ptrs.data());
    return out;
  }

  /// Link names of a group, in creation order when the group tracks it, else by name.
  std::vector<std::string> children(hid_t group) const {
    std::vector<std::string> names;
    Id gcpl(H5Gget_create_plist(group));
    unsigned flags = 0;
    H5Pget_link_creation_order(gcpl, &flags);
    const H5_index_t index = (flags & H5P_CRT_ORDER_INDEXED) ? H5_INDEX_CRT_ORDER : H5_INDEX_NAME;
    H5G_info_t info;
    ctx_.check(H5Gget_info(group, &info), "cannot list a group");
    for (hsize_t i = 0; i < info.nlinks; ++i) {
      const ssize_t len = H5Lget_name_by_idx(group, ".", index, H5_ITER_INC, i, nullptr, 0, H5P_DEFAULT);
      if (len < 0) continue;
      std::string s(static_cast<std::size_t>(len) + 1, '\0');
      H5Lget_name_by_idx(group, ".", index, H5_ITER_INC, i, s.data(), s.size(), H5P_DEFAULT);
      s.resize(static_cast<std::size_t>(len));
      names.push_back(std::move(s));
    }
    return names;
  }

 private:
  h5::Context ctx_;
};

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

std::string qualified(const std::vector<std::string>& instances, std::int32_t inst, std::int64_t label) {
  if (inst < 0 || static_cast<std::size_t>(inst) >= instances.size() || instances[inst].empty())
    return std::to_string(label);
  return instances[inst] + "." + std::to_string(label);
}

/// The /status members a study needs, read by name (HDF5 converts the compound).
struct StatusPart {
  std::int32_t cut_back_flag;
  std::int32_t total_iters;
  std::int32_t augmentations;
};

ResultsStatusTotals read_status(Reader& r, hid_t file) {
  ResultsStatusTotals t;
  if (!r.ctx().exists(file, "status")) return t;
  Id ds = r.ctx().open_dataset(file, "status");
  const auto d = r.dims(ds);
  const std::size_t n = d.empty() ? 0 : d[0];
  if (!n) return t;
  Id type(H5Tcreate(H5T_COMPOUND, sizeof(StatusPart)));
  H5Tinsert(type, "cut_back", HOFFSET(StatusPart, cut_back_flag), H5T_NATIVE_INT32);
  H5Tinsert(type, "total_iters", HOFFSET(StatusPart, total_iters), H5T_NATIVE_INT32);
  H5Tinsert(type, "augmentations", HOFFSET(StatusPart, augmentations), H5T_NATIVE_INT32);
  std::vector<StatusPart> rows(n);
  r.ctx().check(H5Dread(ds, type, H5S_ALL, H5S_ALL, h5::transfer_plist(), rows.data()), "cannot read /status");
  for (const StatusPart& p : rows) {
    ++t.attempts;
    if (p.cut_back_flag) ++t.cut_backs;
    else ++t.increments;
    t.iterations += p.total_iters;
    t.augmentations += p.augmentations;
  }
  return t;
}

}  // namespace

const ResultsField* ResultsStep::field(const std::string& key) const {
  for (const auto& f : fields)
    if (f.key == key) return &f;
  return nullptr;
}

const ResultsStep* ResultsFile::step(const std::string& name) const {
  for (const auto& s : steps)
    if (s.name == name) return &s;
  return nullptr;
}

std::string results_status(const fs::path& path) {
  h5::silence_hdf5_errors();
  std::error_code ec;
  if (path.extension() == ".part" || !fs::is_regular_file(path, ec) || H5Fis_hdf5(path.c_str()) <= 0) return "";
  try {
    Reader r(path);
    Id file(r.ctx().check(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), "cannot open the file"));
    if (r.attr_string(file, "schema") != "inpact-results") return "";
    return r.attr_string(file, "status");
  } catch (const IoError&) {
    return "";
  }
}

ResultsFile read_results(const fs::path& path, const ReadResultsOptions& options) {
  h5::silence_hdf5_errors();
  std::error_code ec;
  if (path.extension() == ".part")
    throw IoError(path, "a partial results file (.part): its run is still writing it or was killed; "
                        "compare the finished JOB.h5");
  if (!fs::exists(path, ec)) {
    fs::path part = path;
    part += ".part";
    if (fs::exists(part, ec))
      throw IoError(path, "no such file, but " + part.filename().string() +
                              " exists: the run is still writing it or was killed");
    throw IoError(path, "no such file");
  }
  if (H5Fis_hdf5(path.c_str()) <= 0)
    throw IoError(path, "not an HDF5 file, so not an inpact results file");

  Reader r(path);
  Id file(r.ctx().check(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), "cannot open the file"));
  if (r.attr_string(file, "schema") != "inpact-results")
    throw IoError(path, "not an inpact results file (no root attribute schema=\"inpact-results\")");

  ResultsFile out;
  out.path = path;
  out.status = r.attr_string(file, "status");
  out.solver_version = r.attr_string(file, "solver_version");
  out.deck_sha256 = r.attr_string(file, "deck_sha256");
  if (!options.allow_incomplete && out.status != "COMPLETED")
    throw IoError(path, fmt::format("status {}: the run did not complete (its results are not final)",
                                    out.status.empty() ? "missing" : out.status));

  // Model: node names by row, element names, node sets, contact pair names.
  Id model = r.ctx().open_group(file, "model");
  const auto instances = r.ctx().exists(model, "instances") ? r.read_strings(model, "instances")
                                                            : std::vector<std::string>{};
  std::size_t n_nodes = 0;
  {
    Id nodes = r.ctx().open_group(model, "nodes");
    const auto labels = r.read<std::int64_t>(nodes, "labels");
    const auto inst = r.ctx().exists(nodes, "instance") ? r.read<std::int32_t>(nodes, "instance")
                                                        : std::vector<std::int32_t>(labels.size(), 0);
    n_nodes = labels.size();
    if (options.names) {
      out.node_names.reserve(labels.size());
      for (std::size_t i = 0; i < labels.size(); ++i)
        out.node_names.push_back(qualified(instances, i < inst.size() ? inst[i] : 0, labels[i]));
    }
  }
  if (options.names && r.ctx().exists(model, "elements")) {
    Id elements = r.ctx().open_group(model, "elements");
    for (const auto& type : r.children(elements)) {
      Id tg = r.ctx().open_group(elements, type);
      const auto labels = r.read<std::int64_t>(tg, "labels");
      const auto inst = r.ctx().exists(tg, "instance") ? r.read<std::int32_t>(tg, "instance")
                                                       : std::vector<std::int32_t>(labels.size(), 0);
      for (std::size_t i = 0; i < labels.size(); ++i)
        out.element_names.push_back(type + " " + qualified(instances, i < inst.size() ? inst[i] : 0, labels[i]));
    }
  }
  if (r.ctx().exists(model, "sets") && H5Lexists(model, "sets/nsets", H5P_DEFAULT) > 0) {
    Id nsets = r.ctx().open_group(model, "sets/nsets");
    for (const auto& name : r.children(nsets)) out.nsets[upper(name)] = r.read<std::int64_t>(nsets, name);
  }
  std::vector<std::string> pairs;
  if (H5Lexists(model, "contact", H5P_DEFAULT) > 0 && H5Lexists(model, "contact/pairs", H5P_DEFAULT) > 0)
    pairs = r.read_strings(model, "contact/pairs");

  // Steps, frames, fields.
  Id steps = r.ctx().open_group(file, "steps");
  for (const auto& step_name : r.children(steps)) {
    Id sg = r.ctx().open_group(steps, step_name);
    ResultsStep st;
    st.name = step_name;
    Id frames = r.ctx().open_group(sg, "frames");
    st.step_time = r.read<double>(frames, "step_time");
    st.total_time = r.read<double>(frames, "total_time");
    st.increment = r.read<std::int32_t>(frames, "increment");
    if (!r.ctx().exists(sg, "fieldOutputs")) {
      out.steps.push_back(std::move(st));
      continue;
    }
    Id fo = r.ctx().open_group(sg, "fieldOutputs");
    for (const auto& key : r.children(fo)) {
      Id fg = r.ctx().open_group(fo, key);
      ResultsField f;
      f.key = key;
      f.position = r.attr_string(fg, "position");
      f.region = r.attr_string(fg, "region");
      f.components = r.attr_strings(fg, "componentLabels");
      {
        Id ds = r.ctx().open_dataset(fg, "data");
        const auto d = r.dims(ds);
        if (d.size() != 3) r.ctx().fail(fmt::format("step '{}', field {}: data is not (frames, locations, components)",
                                                    step_name, key));
        f.n_frames = d[0];
        f.n_loc = d[1];
        f.n_comp = d[2];
      }
      bool wanted = options.with_data;
      if (wanted && !options.data_for.empty()) {
        wanted = options.data_for.count(f.key) > 0;
        for (const auto& c : f.components) wanted = wanted || options.data_for.count(c) > 0;
      }
      if (wanted) f.data = r.read<double>(fg, "data");
      if (!options.names && !options.data_for.empty() && !wanted) {  // known by key and components only
        st.fields.push_back(std::move(f));
        continue;
      }
      auto optional_i32 = [&](const char* name) {
        return r.ctx().exists(fg, name) ? r.read<std::int32_t>(fg, name) : std::vector<std::int32_t>{};
      };
      const auto inst = optional_i32("instance");
      const auto ip = optional_i32("ip");
      const auto section_point = optional_i32("section_point");
      const auto pair = optional_i32("pair");
      f.locations.reserve(f.n_loc);
      f.node_rows.assign(f.n_loc, -1);
      auto bad = [&](const std::string& why) {
        r.ctx().fail(fmt::format("step '{}', field {}: {}", step_name, key, why));
      };
      if (r.ctx().exists(fg, "nodes")) {
        const auto rows = r.read<std::int64_t>(fg, "nodes");
        if (rows.size() != f.n_loc) bad("nodes has the wrong length");
        for (std::size_t i = 0; i < rows.size(); ++i) {
          if (rows[i] < 0 || static_cast<std::size_t>(rows[i]) >= n_nodes) bad("node row out of range");
          f.node_rows[i] = rows[i];
          if (!options.names) continue;
          std::string name = "node " + out.node_names[rows[i]];
          if (i < pair.size()) {
            const auto p = pair[i];
            name += " (pair " + (p >= 0 && static_cast<std::size_t>(p) < pairs.size() ? pairs[p] : std::to_string(p)) + ")";
          }
          f.locations.push_back(std::move(name));
        }
      } else if (!options.names) {
      } else if (r.ctx().exists(fg, "elements")) {
        const auto labels = r.read<std::int64_t>(fg, "elements");
        if (labels.size() != f.n_loc) bad("elements has the wrong length");
        const char* sub = f.position == "ELEMENT_NODAL" ? " node " : " ip ";
        for (std::size_t i = 0; i < labels.size(); ++i) {
          std::string name = "element " + qualified(instances, i < inst.size() ? inst[i] : 0, labels[i]);
          if (i < ip.size()) name += sub + std::to_string(ip[i]);
          if (i < section_point.size() && section_point[i] > 0) name += " sp " + std::to_string(section_point[i]);
          f.locations.push_back(std::move(name));
        }
      } else {
        for (std::size_t i = 0; i < f.n_loc; ++i) f.locations.push_back("location " + std::to_string(i + 1));
      }
      st.fields.push_back(std::move(f));
    }
    out.steps.push_back(std::move(st));
  }
  out.totals = read_status(r, file);
  return out;
}

}  // namespace inpact::io
