#include "hdf5_util.hpp"

#include <algorithm>

namespace inpact::io::h5 {

void silence_hdf5_errors() { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }

namespace {

herr_t collect_error(unsigned n, const H5E_error2_t* err, void* client) {
  auto* messages = static_cast<std::vector<std::string>*>(client);
  std::string text = err->desc ? err->desc : "";
  if (text.empty() && err->func_name) text = err->func_name;
  messages->push_back(text);
  (void)n;
  return 0;
}

}  // namespace

std::string last_error_text() {
  std::vector<std::string> messages;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_DOWNWARD, collect_error, &messages);
  H5Eclear2(H5E_DEFAULT);
  if (messages.empty()) return "";
  // The first entry is the API call that failed, the last the innermost cause.
  if (messages.size() == 1 || messages.front() == messages.back()) return messages.front();
  return messages.front() + " (" + messages.back() + ")";
}

void Id::reset() {
  if (id_ >= 0 && H5Iis_valid(id_) > 0) H5Idec_ref(id_);
  id_ = H5I_INVALID_HID;
}

Id vlen_string_type() {
  Id t(H5Tcopy(H5T_C_S1));
  H5Tset_size(t, H5T_VARIABLE);
  H5Tset_cset(t, H5T_CSET_UTF8);
  return t;
}

hid_t Context::check(hid_t status, const std::string& what) const {
  if (status < 0) fail(what);
  return status;
}

void Context::fail(const std::string& what) const {
  const std::string cause = last_error_text();
  throw IoError(path_, cause.empty() ? what : what + ": " + cause);
}

Id Context::create_group(hid_t parent, const std::string& name, bool track_order) const {
  Id gcpl(H5Pcreate(H5P_GROUP_CREATE));
  if (track_order) check(H5Pset_link_creation_order(gcpl, H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED),
                         "cannot set link creation order for group '" + name + "'");
  Id lcpl(H5Pcreate(H5P_LINK_CREATE));
  H5Pset_create_intermediate_group(lcpl, 1);
  H5Pset_char_encoding(lcpl, H5T_CSET_UTF8);
  return Id(check(H5Gcreate2(parent, name.c_str(), lcpl, gcpl, H5P_DEFAULT), "cannot create group '" + name + "'"));
}

Id Context::open_group(hid_t parent, const std::string& name) const {
  return Id(check(H5Gopen2(parent, name.c_str(), H5P_DEFAULT), "cannot open group '" + name + "'"));
}

Id Context::open_dataset(hid_t parent, const std::string& name) const {
  return Id(check(H5Dopen2(parent, name.c_str(), H5P_DEFAULT), "cannot open dataset '" + name + "'"));
}

bool Context::exists(hid_t parent, const std::string& name) const {
  return H5Lexists(parent, name.c_str(), H5P_DEFAULT) > 0;
}

hid_t transfer_plist() {
  static const hid_t dxpl = [] {
    const hid_t p = H5Pcreate(H5P_DATASET_XFER);
    H5Pset_buffer(p, 64 * 1024, nullptr, nullptr);
    return p;
  }();
  return dxpl;
}

void Context::write_dataset(hid_t parent, const std::string& name, hid_t mem_type,
                            const std::vector<hsize_t>& dims, const void* data) const {
  Id space(check(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr),
                 "cannot create dataspace for '" + name + "'"));
  Id ds(check(H5Dcreate2(parent, name.c_str(), mem_type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
              "cannot create dataset '" + name + "'"));
  const bool empty = std::any_of(dims.begin(), dims.end(), [](hsize_t d) { return d == 0; });
  if (!empty)
    check(H5Dwrite(ds, mem_type, H5S_ALL, H5S_ALL, transfer_plist(), data), "cannot write dataset '" + name + "'");
}

void Context::write_strings(hid_t parent, const std::string& name, const std::vector<std::string>& values) const {
  Id type = vlen_string_type();
  std::vector<const char*> ptrs;
  ptrs.reserve(values.size());
  for (const auto& v : values) ptrs.push_back(v.c_str());
  write_dataset(parent, name, type, {values.size()}, ptrs.data());
}

Id Context::create_extendable(hid_t parent, const std::string& name, hid_t type, const std::vector<hsize_t>& dims,
                              const std::vector<hsize_t>& chunk, const void* fill) const {
  std::vector<hsize_t> max_dims = dims;
  max_dims[0] = H5S_UNLIMITED;
  // A fixed dimension may not be smaller than its chunk (an empty field): leave it unlimited.
  for (std::size_t i = 1; i < dims.size(); ++i)
    if (dims[i] < chunk[i]) max_dims[i] = H5S_UNLIMITED;
  Id space(check(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), max_dims.data()),
                 "cannot create dataspace for '" + name + "'"));
  Id dcpl(H5Pcreate(H5P_DATASET_CREATE));
  check(H5Pset_chunk(dcpl, static_cast<int>(chunk.size()), chunk.data()), "cannot set chunking of '" + name + "'");
  if (fill) check(H5Pset_fill_value(dcpl, type, fill), "cannot set fill value of '" + name + "'");
  return Id(check(H5Dcreate2(parent, name.c_str(), type, space, H5P_DEFAULT, dcpl, H5P_DEFAULT),
                  "cannot create dataset '" + name + "'"));
}

hsize_t Context::n_rows(hid_t dataset) const {
  Id space(check(H5Dget_space(dataset), "cannot get dataspace"));
  hsize_t dims[H5S_MAX_RANK];
  check(H5Sget_simple_extent_dims(space, dims, nullptr), "cannot get dataset extent");
  return dims[0];
}

void Context::extend(hid_t dataset, hsize_t n_rows) const {
  Id space(check(H5Dget_space(dataset), "cannot get dataspace"));
  const int rank = check(H5Sget_simple_extent_ndims(space), "cannot get dataset rank");
  hsize_t dims[H5S_MAX_RANK];
  H5Sget_simple_extent_dims(space, dims, nullptr);
  if (dims[0] >= n_rows) return;
  dims[0] = n_rows;
  (void)rank;
  check(H5Dset_extent(dataset, dims), "cannot extend dataset");
}

void Context::write_rows(hid_t dataset, hid_t mem_type, hsize_t row, hsize_t n, const void* data) const {
  extend(dataset, row + n);
  Id file_space(check(H5Dget_space(dataset), "cannot get dataspace"));
  const int rank = H5Sget_simple_extent_ndims(file_space);
  hsize_t dims[H5S_MAX_RANK];
  H5Sget_simple_extent_dims(file_space, dims, nullptr);
  hsize_t start[H5S_MAX_RANK] = {};
  hsize_t count[H5S_MAX_RANK];
  start[0] = row;
  count[0] = n;
  for (int i = 1; i < rank; ++i) count[i] = dims[i];
  check(H5Sselect_hyperslab(file_space, H5S_SELECT_SET, start, nullptr, count, nullptr), "cannot select rows");
  hsize_t n_values = 1;
  for (int i = 0; i < rank; ++i) n_values *= count[i];
  if (n_values == 0) return;
  Id mem_space(check(H5Screate_simple(rank, count, nullptr), "cannot create memory dataspace"));
  check(H5Dwrite(dataset, mem_type, mem_space, file_space, transfer_plist(), data), "cannot write rows");
}

void Context::write_frame_chunks(hid_t dataset, hsize_t row, hsize_t n_rows, hsize_t chunk_rows, hsize_t n_comp,
                                 const double* data, double pad) const {
  extend(dataset, row + 1);
  if (n_rows == 0 || n_comp == 0) return;
  const hsize_t chunk_values = chunk_rows * n_comp;
  std::vector<double> last;  // the padded partial chunk, when there is one
  for (hsize_t first = 0; first < n_rows; first += chunk_rows) {
    const hsize_t offset[3] = {row, first, 0};
    const double* chunk = data + first * n_comp;
    if (first + chunk_rows > n_rows) {
      last.assign(chunk_values, pad);
      std::copy(chunk, data + n_rows * n_comp, last.begin());
      chunk = last.data();
    }
    check(H5Dwrite_chunk(dataset, transfer_plist(), 0, offset, chunk_values * sizeof(double), chunk),
          "cannot write a chunk of rows");
  }
}

Id Context::create_attr(hid_t obj, const std::string& name, hid_t type, hid_t space) const {
  if (H5Aexists(obj, name.c_str()) > 0) H5Adelete(obj, name.c_str());
  return Id(check(H5Acreate2(obj, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT),
                  "cannot create attribute '" + name + "'"));
}

void Context::attr_string(hid_t obj, const std::string& name, const std::string& value) const {
  Id type = vlen_string_type();
  Id space(H5Screate(H5S_SCALAR));
  Id a = create_attr(obj, name, type, space);
  const char* p = value.c_str();
  check(H5Awrite(a, type, &p), "cannot write attribute '" + name + "'");
}

void Context::attr_fixed_string(hid_t obj, const std::string& name, const std::string& value) const {
  Id type(H5Tcopy(H5T_C_S1));
  H5Tset_size(type, std::max<std::size_t>(value.size(), 1));
  H5Tset_strpad(type, H5T_STR_NULLPAD);
  H5Tset_cset(type, H5T_CSET_ASCII);
  Id space(H5Screate(H5S_SCALAR));
  Id a = create_attr(obj, name, type, space);
  check(H5Awrite(a, type, value.c_str()), "cannot write attribute '" + name + "'");
}

void Context::attr_strings(hid_t obj, const std::string& name, const std::vector<std::string>& values) const {
  Id type = vlen_string_type();
  const hsize_t n = values.size();
  Id space(H5Screate_simple(1, &n, nullptr));
  Id a = create_attr(obj, name, type, space);
  std::vector<const char*> ptrs;
  for (const auto& v : values) ptrs.push_back(v.c_str());
  if (n) check(H5Awrite(a, type, ptrs.data()), "cannot write attribute '" + name + "'");
}

void Context::attr_int(hid_t obj, const std::string& name, std::int32_t value) const {
  Id space(H5Screate(H5S_SCALAR));
  Id a = create_attr(obj, name, H5T_NATIVE_INT32, space);
  check(H5Awrite(a, H5T_NATIVE_INT32, &value), "cannot write attribute '" + name + "'");
}

void Context::attr_ints(hid_t obj, const std::string& name, const std::vector<std::int32_t>& values) const {
  const hsize_t n = values.size();
  Id space(H5Screate_simple(1, &n, nullptr));
  Id a = create_attr(obj, name, H5T_NATIVE_INT32, space);
  if (n) check(H5Awrite(a, H5T_NATIVE_INT32, values.data()), "cannot write attribute '" + name + "'");
}

void Context::attr_double(hid_t obj, const std::string& name, double value) const {
  Id space(H5Screate(H5S_SCALAR));
  Id a = create_attr(obj, name, H5T_NATIVE_DOUBLE, space);
  check(H5Awrite(a, H5T_NATIVE_DOUBLE, &value), "cannot write attribute '" + name + "'");
}

}  // namespace inpact::io::h5
