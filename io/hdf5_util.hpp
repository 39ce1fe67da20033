#pragma once
/// Thin RAII and error helpers over the HDF5 C API, private to io/ (never include from a
/// public header: the results writer keeps HDF5 out of its interface).
///
/// Every call that fails throws IoError with the file, what was being done and HDF5's own
/// innermost message; HDF5's automatic error printing is switched off (`silence_hdf5_errors`).
#include <hdf5.h>

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "io_error.hpp"

namespace inpact::io::h5 {

/// Turns off HDF5's automatic printing of its error stack to stderr, for the whole process
/// (errors are reported through IoError instead).
void silence_hdf5_errors();

/// The HDF5 error stack of the last failed call as one line ("" when empty).
std::string last_error_text();

/// Owns one HDF5 identifier of any kind (file, group, dataset, space, type, property list,
/// attribute) and releases it on destruction.
class Id {
 public:
  Id() = default;
  explicit Id(hid_t id) : id_(id) {}
  ~Id() { reset(); }
  Id(Id&& o) noexcept : id_(std::exchange(o.id_, H5I_INVALID_HID)) {}
  Id& operator=(Id&& o) noexcept {
    if (this != &o) {
      reset();
      id_ = std::exchange(o.id_, H5I_INVALID_HID);
    }
    return *this;
  }
  Id(const Id&) = delete;
  Id& operator=(const Id&) = delete;

  hid_t get() const { return id_; }
  operator hid_t() const { return id_; }  // NOLINT: reads like the C API it wraps
  bool valid() const { return id_ >= 0; }
  void reset();
  hid_t release() { return std::exchange(id_, H5I_INVALID_HID); }

 private:
  hid_t id_ = H5I_INVALID_HID;
};

template <class T> hid_t native_type();
template <> inline hid_t native_type<double>() { return H5T_NATIVE_DOUBLE; }
template <> inline hid_t native_type<std::int64_t>() { return H5T_NATIVE_INT64; }
template <> inline hid_t native_type<std::int32_t>() { return H5T_NATIVE_INT32; }
template <> inline hid_t native_type<std::uint8_t>() { return H5T_NATIVE_UINT8; }
template <> inline hid_t native_type<std::int8_t>() { return H5T_NATIVE_INT8; }

/// Transfer properties for every H5Dwrite and H5Dread: a 64 KiB type-conversion buffer instead
/// of HDF5's 1 MiB, which HDF5 allocates zeroed for each transfer that converts (variable-length
/// strings, the packed status rows): 1 MiB to clear and page in each time, 2 M instructions for
/// one row of the status table.
hid_t transfer_plist();

/// The file being written: every helper checks its HDF5 call and names this path on failure.
class Context {
 public:
  explicit Context(std::filesystem::path path) : path_(std::move(path)) {}
  const std::filesystem::path& path() const { return path_; }

  /// Throws IoError("<what>: <HDF5 message>") when `status` < 0; returns it otherwise.
  hid_t check(hid_t status, const std::string& what) const;
  [[noreturn]] void fail(const std::string& what) const;

  /// A new group; `track_order`: links are indexed by creation order, so readers list
  /// steps and frames in the order they were written rather than alphabetically.
  Id create_group(hid_t parent, const std::string& name, bool track_order = false) const;
  Id open_group(hid_t parent, const std::string& name) const;
  Id open_dataset(hid_t parent, const std::string& name) const;
  bool exists(hid_t parent, const std::string& name) const;

  /// A fixed-size dataset of `dims` written from `data` (row-major, native `mem_type`).
  void write_dataset(hid_t parent, const std::string& name, hid_t mem_type,
                     const std::vector<hsize_t>& dims, const void* data) const;
  template <class T>
  void write(hid_t parent, const std::string& name, std::span<const T> data, hsize_t n_cols = 0) const {
    std::vector<hsize_t> dims{n_cols ? data.size() / n_cols : data.size()};
    if (n_cols) dims.push_back(n_cols);
    write_dataset(parent, name, native_type<T>(), dims, data.data());
  }
  template <class T>
  void write(hid_t parent, const std::string& name, const std::vector<T>& data, hsize_t n_cols = 0) const {
    write<T>(parent, name, std::span<const T>(data), n_cols);
  }
  /// A 1-D dataset of variable-length UTF-8 strings.
  void write_strings(hid_t parent, const std::string& name, const std::vector<std::string>& values) const;

  /// A dataset extendable along its first dimension: starts with `dims` (dims[0] rows, often 0),
  /// chunked by `chunk`, unread elements read as `fill` (may be null: zero).
  Id create_extendable(hid_t parent, const std::string& name, hid_t type, const std::vector<hsize_t>& dims,
                       const std::vector<hsize_t>& chunk, const void* fill = nullptr) const;
  /// Grows the first dimension of `dataset` to `n_rows` (never shrinks).
  void extend(hid_t dataset, hsize_t n_rows) const;
  /// Writes rows [row, row + n_rows) of an extendable dataset (extended first when needed).
  void write_rows(hid_t dataset, hid_t mem_type, hsize_t row, hsize_t n_rows, const void* data) const;
  /// Writes frame `row` of a 3-D dataset extendable in its first dimension and chunked
  /// {1, chunk_rows, n_comp} (extended first when needed) straight into its chunks with
  /// H5Dwrite_chunk: no chunk cache, no chunk buffer to allocate, fill and copy into, as
  /// H5Dwrite would for each chunk. `data` holds the frame's n_rows × n_comp doubles, which are
  /// the file's type (native double, no filters). A last, partial chunk is padded with `pad`.
  void write_frame_chunks(hid_t dataset, hsize_t row, hsize_t n_rows, hsize_t chunk_rows, hsize_t n_comp,
                          const double* data, double pad) const;
  /// Number of rows (first dimension) of a dataset.
  hsize_t n_rows(hid_t dataset) const;

  // Attributes (overwritten when they exist).
  void attr_string(hid_t obj, const std::string& name, const std::string& value) const;
  /// A fixed-length, NUL-padded ASCII string attribute (what VTK's HDF reader expects).
  void attr_fixed_string(hid_t obj, const std::string& name, const std::string& value) const;
  void attr_strings(hid_t obj, const std::string& name, const std::vector<std::string>& values) const;
  void attr_int(hid_t obj, const std::string& name, std::int32_t value) const;
  void attr_ints(hid_t obj, const std::string& name, const std::vector<std::int32_t>& values) const;
  void attr_double(hid_t obj, const std::string& name, double value) const;

 private:
  Id create_attr(hid_t obj, const std::string& name, hid_t type, hid_t space) const;
  std::filesystem::path path_;
};

/// A variable-length UTF-8 string type.
Id vlen_string_type();

}  // namespace inpact::io::h5
