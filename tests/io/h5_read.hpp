#pragma once
/// Reading back results files with the plain HDF5 C API, for the io tests.
#include <hdf5.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace inpact::test {

/// A read-only HDF5 file.
class H5Reader {
 public:
  explicit H5Reader(const std::string& path) : id_(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT)) {}
  ~H5Reader() {
    if (id_ >= 0) H5Fclose(id_);
  }
  H5Reader(const H5Reader&) = delete;
  H5Reader& operator=(const H5Reader&) = delete;
  bool ok() const { return id_ >= 0; }
  hid_t id() const { return id_; }

  bool exists(const std::string& path) const {
    // H5Lexists needs every parent to exist: walk the path.
    std::string sofar;
    std::size_t pos = 1;
    while (pos <= path.size()) {
      const std::size_t next = path.find('/', pos);
      sofar = path.substr(0, next == std::string::npos ? path.size() : next);
      if (H5Lexists(id_, sofar.c_str(), H5P_DEFAULT) <= 0) return false;
      if (next == std::string::npos) break;
      pos = next + 1;
    }
    return true;
  }

  std::vector<hsize_t> dims(const std::string& path) const {
    hid_t ds = H5Dopen2(id_, path.c_str(), H5P_DEFAULT);
    if (ds < 0) throw std::runtime_error("no dataset " + path);
    hid_t space = H5Dget_space(ds);
    std::vector<hsize_t> d(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space)));
    H5Sget_simple_extent_dims(space, d.data(), nullptr);
    H5Sclose(space);
    H5Dclose(ds);
    return d;
  }

  template <class T>
  std::vector<T> read(const std::string& path, hid_t mem_type) const {
    std::size_t n = 1;
    for (hsize_t d : dims(path)) n *= d;
    std::vector<T> out(n);
    hid_t ds = H5Dopen2(id_, path.c_str(), H5P_DEFAULT);
    if (n && H5Dread(ds, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()) < 0)
      throw std::runtime_error("cannot read " + path);
    H5Dclose(ds);
    return out;
  }
  std::vector<double> doubles(const std::string& path) const { return read<double>(path, H5T_NATIVE_DOUBLE); }
  std::vector<std::int64_t> int64s(const std::string& path) const { return read<std::int64_t>(path, H5T_NATIVE_INT64); }
  std::vector<std::int32_t> int32s(const std::string& path) const { return read<std::int32_t>(path, H5T_NATIVE_INT32); }

  std::vector<std::string> strings(const std::string& path) const {
    const auto n = dims(path).at(0);
    std::vector<char*> ptrs(n);
    hid_t ds = H5Dopen2(id_, path.c_str(), H5P_DEFAULT);
    hid_t type = vlen_type();
    if (n) H5Dread(ds, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, ptrs.data());
    std::vector<std::string> out;
    for (char* p : ptrs) out.emplace_back(p ? p : "");
    if (n) {
      hid_t space = H5Dget_space(ds);
      H5Dvlen_reclaim(type, space, H5P_DEFAULT, ptrs.data());
      H5Sclose(space);
    }
    H5Tclose(type);
    H5Dclose(ds);
    return out;
  }

  /// A string attribute (variable or fixed length) of the object at `obj`.
  std::string attr_string(const std::string& obj, const std::string& name) const {
    hid_t a = H5Aopen_by_name(id_, obj.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
    if (a < 0) throw std::runtime_error("no attribute " + obj + "@" + name);
    hid_t ftype = H5Aget_type(a);
    std::string out;
    if (H5Tis_variable_str(ftype) > 0) {
      char* p = nullptr;
      hid_t type = vlen_type();
      H5Aread(a, type, &p);
      out = p ? p : "";
      H5free_memory(p);
      H5Tclose(type);
    } else {
      std::vector<char> buf(H5Tget_size(ftype) + 1, '\0');
      H5Aread(a, ftype, buf.data());
      out = buf.data();
    }
    H5Tclose(ftype);
    H5Aclose(a);
    return out;
  }

  std::vector<std::string> attr_strings(const std::string& obj, const std::string& name) const {
    hid_t a = H5Aopen_by_name(id_, obj.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
    hid_t space = H5Aget_space(a);
    const auto n = static_cast<std::size_t>(H5Sget_simple_extent_npoints(space));
    std::vector<char*> ptrs(n);
    hid_t type = vlen_type();
    if (n) H5Aread(a, type, ptrs.data());
    std::vector<std::string> out;
    for (char* p : ptrs) out.emplace_back(p ? p : "");
    if (n) H5Dvlen_reclaim(type, space, H5P_DEFAULT, ptrs.data());
    H5Tclose(type);
    H5Sclose(space);
    H5Aclose(a);
    return out;
  }

  template <class T>
  std::vector<T> attr_values(const std::string& obj, const std::string& name, hid_t mem_type) const {
    hid_t a = H5Aopen_by_name(id_, obj.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
    if (a < 0) throw std::runtime_error("no attribute " + obj + "@" + name);
    hid_t space = H5Aget_space(a);
    std::vector<T> out(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
    H5Aread(a, mem_type, out.data());
    H5Sclose(space);
    H5Aclose(a);
    return out;
  }
  double attr_double(const std::string& obj, const std::string& name) const {
    return attr_values<double>(obj, name, H5T_NATIVE_DOUBLE).at(0);
  }
  std::int32_t attr_int(const std::string& obj, const std::string& name) const {
    return attr_values<std::int32_t>(obj, name, H5T_NATIVE_INT32).at(0);
  }

 private:
  static hid_t vlen_type() {
    hid_t t = H5Tcopy(H5T_C_S1);
    H5Tset_size(t, H5T_VARIABLE);
    H5Tset_cset(t, H5T_CSET_UTF8);  // the writer's strings are UTF-8 (HDF5 does not convert charsets)
    return t;
  }
  hid_t id_;
};

}  // namespace inpact::test
