// SeaSpring — MIT licence.
/// \file h5_util.cpp
/// \brief Implementation of the checked HDF5 wrappers.
#include "io/h5_util.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>

#include "core/error.h"

namespace seaspring::io::h5 {
namespace {

/// HDF5 prints its error stack to stderr by default; we report it in our messages.
void silenceHdf5Printing() {
    static const bool done = [] {
        H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
        return true;
    }();
    (void)done;
}

herr_t takeMostSpecific(unsigned n, const H5E_error2_t* err, void* data) {
    if (n == 0 && err != nullptr && err->desc != nullptr)
        *static_cast<std::string*>(data) = err->desc;
    return 0;
}

/// " (HDF5: reason)" from the innermost entry of HDF5's error stack, then clears it.
std::string hdf5Reason() {
    std::string reason;
    H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, takeMostSpecific, &reason);
    H5Eclear2(H5E_DEFAULT);
    return reason.empty() ? std::string() : " (HDF5: " + reason + ")";
}

[[noreturn]] void failFile(const std::string& path, const std::string& message) {
    throw Error(formatLocation(path, 0, message));
}

/// Throws when an HDF5 call returned a negative status or identifier.
void check(long long status, const Location& loc, const std::string& what,
           const std::string& action) {
    if (status < 0) loc.fail(what, "cannot " + action + hdf5Reason());
}

template <typename T>
struct Traits;
#define SEASPRING_H5_TRAITS(T, NAME, MEM, STORED, CLASS, SIGN)                         \
    template <>                                                                        \
    struct Traits<T> {                                                                 \
        static const char* name() { return NAME; }                                     \
        static hid_t memory() { return MEM; }                                          \
        static hid_t stored() { return STORED; }                                       \
        static constexpr H5T_class_t type_class = CLASS;                               \
        static constexpr H5T_sign_t sign = SIGN;                                       \
    };
SEASPRING_H5_TRAITS(std::uint8_t, "uint8", H5T_NATIVE_UINT8, H5T_STD_U8LE, H5T_INTEGER, H5T_SGN_NONE)
SEASPRING_H5_TRAITS(std::uint16_t, "uint16", H5T_NATIVE_UINT16, H5T_STD_U16LE, H5T_INTEGER, H5T_SGN_NONE)
SEASPRING_H5_TRAITS(std::uint32_t, "uint32", H5T_NATIVE_UINT32, H5T_STD_U32LE, H5T_INTEGER, H5T_SGN_NONE)
SEASPRING_H5_TRAITS(std::uint64_t, "uint64", H5T_NATIVE_UINT64, H5T_STD_U64LE, H5T_INTEGER, H5T_SGN_NONE)
SEASPRING_H5_TRAITS(std::int32_t, "int32", H5T_NATIVE_INT32, H5T_STD_I32LE, H5T_INTEGER, H5T_SGN_2)
SEASPRING_H5_TRAITS(std::int64_t, "int64", H5T_NATIVE_INT64, H5T_STD_I64LE, H5T_INTEGER, H5T_SGN_2)
SEASPRING_H5_TRAITS(float, "float32", H5T_NATIVE_FLOAT, H5T_IEEE_F32LE, H5T_FLOAT, H5T_SGN_ERROR)
SEASPRING_H5_TRAITS(double, "float64", H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE, H5T_FLOAT, H5T_SGN_ERROR)
#undef SEASPRING_H5_TRAITS

/// "uint16", "float32", "string", ... for messages.
std::string describeType(hid_t type) {
    const H5T_class_t cls = H5Tget_class(type);
    const std::size_t bits = H5Tget_size(type) * 8;
    if (cls == H5T_INTEGER)
        return (H5Tget_sign(type) == H5T_SGN_NONE ? "uint" : "int") + std::to_string(bits);
    if (cls == H5T_FLOAT) return "float" + std::to_string(bits);
    if (cls == H5T_STRING) return "string";
    return "HDF5 type class " + std::to_string(static_cast<int>(cls));
}

template <typename T>
bool sameType(hid_t type) {
    if (H5Tget_class(type) != Traits<T>::type_class || H5Tget_size(type) != sizeof(T))
        return false;
    return Traits<T>::type_class != H5T_INTEGER || H5Tget_sign(type) == Traits<T>::sign;
}

std::string shapeText(const DatasetShape& s) {
    if (s.rank == 1) return "[" + std::to_string(s.rows) + "]";
    return "[" + std::to_string(s.rows) + " x " + std::to_string(s.cols) + "]";
}

/// Opens an attribute that must exist and hold a single value.
Handle openScalarAttribute(const Location& loc, const std::string& name, const std::string& what) {
    if (!loc.hasAttribute(name)) loc.fail(what, "is missing");
    Handle attr(H5Aopen(loc.id(), name.c_str(), H5P_DEFAULT), H5Aclose);
    check(attr.get(), loc, what, "open");
    Handle space(H5Aget_space(attr.get()), H5Sclose);
    check(space.get(), loc, what, "get the dataspace");
    const hssize_t n = H5Sget_simple_extent_npoints(space.get());
    if (n != 1) loc.fail(what, "holds " + std::to_string(n) + " values, expected a single value");
    return attr;
}

/// Creates (replacing any existing) scalar attribute and writes `value` into it.
void writeScalarAttribute(const Location& loc, const std::string& name, hid_t stored,
                          hid_t memory, const void* value) {
    const std::string what = "attribute '" + name + "' of " + loc.path();
    if (loc.hasAttribute(name)) check(H5Adelete(loc.id(), name.c_str()), loc, what, "replace");
    Handle space(H5Screate(H5S_SCALAR), H5Sclose);
    check(space.get(), loc, what, "create a scalar dataspace");
    Handle attr(H5Acreate2(loc.id(), name.c_str(), stored, space.get(), H5P_DEFAULT, H5P_DEFAULT),
                H5Aclose);
    check(attr.get(), loc, what, "create");
    check(H5Awrite(attr.get(), memory, value), loc, what, "write");
    check(attr.reset(), loc, what, "close");
}

std::string attributeWhat(const Location& loc, const std::string& name) {
    return "attribute '" + name + "' of " + loc.path();
}

}  // namespace

// ---- Handle, Location, File ------------------------------------------------------------

Handle& Handle::operator=(Handle&& other) noexcept {
    if (this != &other) {
        reset();
        id_ = other.id_;
        closer_ = other.closer_;
        other.id_ = H5I_INVALID_HID;
    }
    return *this;
}

herr_t Handle::reset() {
    herr_t status = 0;
    if (valid() && closer_ != nullptr) status = closer_(id_);
    id_ = H5I_INVALID_HID;
    return status;
}

std::string Location::childPath(const std::string& name) const {
    return path_ == "/" ? "/" + name : path_ + "/" + name;
}

void Location::fail(const std::string& what, const std::string& message) const {
    failFile(file_, what + ": " + message);
}

Location Location::createGroup(const std::string& name) const {
    const std::string what = "group " + childPath(name);
    Handle group(H5Gcreate2(id(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
    check(group.get(), *this, what, "create");
    return Location(std::move(group), file_, childPath(name));
}

Location Location::openGroup(const std::string& name) const {
    const std::string what = "group " + childPath(name);
    if (!hasChild(name)) fail(what, "is missing");
    Handle group(H5Gopen2(id(), name.c_str(), H5P_DEFAULT), H5Gclose);
    check(group.get(), *this, what, "open");
    return Location(std::move(group), file_, childPath(name));
}

bool Location::hasChild(const std::string& name) const {
    const htri_t found = H5Lexists(id(), name.c_str(), H5P_DEFAULT);
    check(found, *this, childPath(name), "look up");
    return found > 0;
}

bool Location::hasAttribute(const std::string& name) const {
    const htri_t found = H5Aexists(id(), name.c_str());
    check(found, *this, attributeWhat(*this, name), "look up");
    return found > 0;
}

void Location::removeChild(const std::string& name) const {
    if (!hasChild(name)) fail(childPath(name), "is missing");
    check(H5Ldelete(id(), name.c_str(), H5P_DEFAULT), *this, childPath(name), "remove");
}

File File::create(const std::string& path) {
    silenceHdf5Printing();
    Handle file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
    if (!file.valid()) failFile(path, "cannot create HDF5 file" + hdf5Reason());
    return File(std::move(file), path, "/");
}

namespace {
Handle openExisting(const std::string& path, unsigned flags) {
    silenceHdf5Printing();
    if (std::FILE* probe = std::fopen(path.c_str(), "rb")) {
        std::fclose(probe);
    } else {
        failFile(path, std::string("cannot open file: ") + std::strerror(errno));
    }
    const htri_t is_hdf5 = H5Fis_hdf5(path.c_str());
    if (is_hdf5 == 0) failFile(path, "is not an HDF5 file");
    if (is_hdf5 < 0) failFile(path, "cannot check whether it is an HDF5 file" + hdf5Reason());
    Handle file(H5Fopen(path.c_str(), flags, H5P_DEFAULT), H5Fclose);
    if (!file.valid()) failFile(path, "cannot open HDF5 file" + hdf5Reason());
    return file;
}
}  // namespace

File File::openReadOnly(const std::string& path) {
    return File(openExisting(path, H5F_ACC_RDONLY), path, "/");
}

File File::openReadWrite(const std::string& path) {
    return File(openExisting(path, H5F_ACC_RDWR), path, "/");
}

void File::close() {
    if (!handle_.valid()) return;
    check(H5Fflush(id(), H5F_SCOPE_LOCAL), *this, "file", "flush");
    check(handle_.reset(), *this, "file", "close");
}

// ---- Datasets ----------------------------------------------------------------------------

template <typename T>
void writeDataset(const Location& loc, const std::string& name, const T* data, std::size_t rows,
                  std::size_t cols, const WriteOptions& options) {
    const std::string what = "dataset " + loc.childPath(name);
    if (cols == 0) loc.fail(what, "column count must be at least 1");
    if (rows > 0 && data == nullptr) loc.fail(what, "no data given for " + std::to_string(rows) + " rows");
    if (options.deflate_level < 0 || options.deflate_level > 9)
        loc.fail(what, "deflate level " + std::to_string(options.deflate_level) + " is not in 0..9");
    const int rank = cols == 1 ? 1 : 2;
    const hsize_t dims[2] = {rows, cols};
    Handle space(H5Screate_simple(rank, dims, nullptr), H5Sclose);
    check(space.get(), loc, what, "create the dataspace");
    Handle dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
    check(dcpl.get(), loc, what, "create the creation property list");
    check(H5Pset_fill_time(dcpl.get(), H5D_FILL_TIME_NEVER), loc, what, "set the fill time");
    const bool chunked = rows > 0 && (rows > options.chunk_rows || options.deflate_level > 0);
    if (chunked) {
        // HDF5 chunks must stay below 4 GiB.
        const std::size_t max_rows = std::max<std::size_t>(1, 0xFFFFFFFFull / (cols * sizeof(T)));
        const std::size_t chunk_rows = std::clamp<std::size_t>(options.chunk_rows, 1, max_rows);
        const hsize_t chunk[2] = {std::min(rows, chunk_rows), cols};
        check(H5Pset_chunk(dcpl.get(), rank, chunk), loc, what, "set the chunk size");
        if (options.deflate_level > 0)
            check(H5Pset_deflate(dcpl.get(), static_cast<unsigned>(options.deflate_level)), loc,
                  what, "enable gzip compression");
    }
    Handle set(H5Dcreate2(loc.id(), name.c_str(), Traits<T>::stored(), space.get(), H5P_DEFAULT,
                          dcpl.get(), H5P_DEFAULT),
               H5Dclose);
    check(set.get(), loc, what, "create");
    if (rows > 0)
        check(H5Dwrite(set.get(), Traits<T>::memory(), H5S_ALL, H5S_ALL, H5P_DEFAULT, data), loc,
              what, "write " + std::to_string(rows) + " rows");
    check(set.reset(), loc, what, "close");
}

DatasetShape datasetShape(const Location& loc, const std::string& name) {
    const std::string what = "dataset " + loc.childPath(name);
    if (!loc.hasChild(name)) loc.fail(what, "is missing");
    Handle set(H5Dopen2(loc.id(), name.c_str(), H5P_DEFAULT), H5Dclose);
    check(set.get(), loc, what, "open");
    Handle space(H5Dget_space(set.get()), H5Sclose);
    check(space.get(), loc, what, "get the dataspace");
    const int rank = H5Sget_simple_extent_ndims(space.get());
    check(rank, loc, what, "get the rank");
    if (rank != 1 && rank != 2)
        loc.fail(what, "has rank " + std::to_string(rank) + ", expected 1 or 2");
    hsize_t dims[2] = {0, 1};
    check(H5Sget_simple_extent_dims(space.get(), dims, nullptr), loc, what, "get the dimensions");
    DatasetShape shape;
    shape.rank = rank;
    shape.rows = dims[0];
    shape.cols = rank == 1 ? 1 : dims[1];
    return shape;
}

template <typename T>
void readDatasetInto(const Location& loc, const std::string& name, T* out, std::size_t rows,
                     std::size_t cols) {
    const std::string what = "dataset " + loc.childPath(name);
    const DatasetShape shape = datasetShape(loc, name);
    const DatasetShape expected{cols == 1 ? 1 : 2, rows, cols};
    Handle set(H5Dopen2(loc.id(), name.c_str(), H5P_DEFAULT), H5Dclose);
    check(set.get(), loc, what, "open");
    Handle type(H5Dget_type(set.get()), H5Tclose);
    check(type.get(), loc, what, "get the element type");
    if (!sameType<T>(type.get()))
        loc.fail(what, "has element type " + describeType(type.get()) + ", expected " +
                           Traits<T>::name());
    if (shape.rank != expected.rank || shape.rows != rows || shape.cols != cols)
        loc.fail(what, "has shape " + shapeText(shape) + ", expected " + shapeText(expected));
    if (rows * cols == 0) return;
    if (out == nullptr) loc.fail(what, "no output buffer given");
    check(H5Dread(set.get(), Traits<T>::memory(), H5S_ALL, H5S_ALL, H5P_DEFAULT, out), loc, what,
          "read " + std::to_string(rows) + " rows");
}

template <typename T>
std::vector<T> readDataset(const Location& loc, const std::string& name) {
    const DatasetShape shape = datasetShape(loc, name);
    if (shape.rank != 1)
        loc.fail("dataset " + loc.childPath(name), "has shape " + shapeText(shape) + ", expected 1-D");
    std::vector<T> values(shape.rows);
    readDatasetInto<T>(loc, name, values.data(), shape.rows, 1);
    return values;
}

#define SEASPRING_H5_INSTANTIATE(T)                                                              \
    template void writeDataset<T>(const Location&, const std::string&, const T*, std::size_t,    \
                                  std::size_t, const WriteOptions&);                             \
    template void readDatasetInto<T>(const Location&, const std::string&, T*, std::size_t,       \
                                     std::size_t);                                               \
    template std::vector<T> readDataset<T>(const Location&, const std::string&);
SEASPRING_H5_INSTANTIATE(std::uint8_t)
SEASPRING_H5_INSTANTIATE(std::uint16_t)
SEASPRING_H5_INSTANTIATE(std::uint32_t)
SEASPRING_H5_INSTANTIATE(std::uint64_t)
SEASPRING_H5_INSTANTIATE(std::int32_t)
SEASPRING_H5_INSTANTIATE(std::int64_t)
SEASPRING_H5_INSTANTIATE(float)
SEASPRING_H5_INSTANTIATE(double)
#undef SEASPRING_H5_INSTANTIATE

// ---- Attributes --------------------------------------------------------------------------

void writeDoubleAttribute(const Location& loc, const std::string& name, double value) {
    writeScalarAttribute(loc, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &value);
}

void writeInt64Attribute(const Location& loc, const std::string& name, std::int64_t value) {
    writeScalarAttribute(loc, name, H5T_STD_I64LE, H5T_NATIVE_INT64, &value);
}

void writeStringAttribute(const Location& loc, const std::string& name, const std::string& value) {
    const std::string what = attributeWhat(loc, name);
    if (value.find('\0') != std::string::npos) loc.fail(what, "string contains a NUL character");
    Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
    check(type.get(), loc, what, "create the string type");
    check(H5Tset_size(type.get(), value.size() + 1), loc, what, "set the string length");
    check(H5Tset_strpad(type.get(), H5T_STR_NULLTERM), loc, what, "set the string padding");
    check(H5Tset_cset(type.get(), H5T_CSET_UTF8), loc, what, "set the character set");
    writeScalarAttribute(loc, name, type.get(), type.get(), value.c_str());
}

namespace {
/// Opens attribute `name`, checks its type class and returns it with its type.
std::pair<Handle, Handle> openTypedAttribute(const Location& loc, const std::string& name,
                                             H5T_class_t wanted, const char* wanted_text) {
    const std::string what = attributeWhat(loc, name);
    Handle attr = openScalarAttribute(loc, name, what);
    Handle type(H5Aget_type(attr.get()), H5Tclose);
    check(type.get(), loc, what, "get the type");
    if (H5Tget_class(type.get()) != wanted)
        loc.fail(what, "has type " + describeType(type.get()) + ", expected " + wanted_text);
    return {std::move(attr), std::move(type)};
}
}  // namespace

double readDoubleAttribute(const Location& loc, const std::string& name) {
    auto [attr, type] = openTypedAttribute(loc, name, H5T_FLOAT, "a floating-point number");
    double value = 0.0;
    check(H5Aread(attr.get(), H5T_NATIVE_DOUBLE, &value), loc, attributeWhat(loc, name), "read");
    return value;
}

std::int64_t readInt64Attribute(const Location& loc, const std::string& name) {
    auto [attr, type] = openTypedAttribute(loc, name, H5T_INTEGER, "an integer");
    if (H5Tget_sign(type.get()) == H5T_SGN_NONE && H5Tget_size(type.get()) >= 8)
        loc.fail(attributeWhat(loc, name), "has type uint64, expected a signed 64-bit integer");
    std::int64_t value = 0;
    check(H5Aread(attr.get(), H5T_NATIVE_INT64, &value), loc, attributeWhat(loc, name), "read");
    return value;
}

std::string readStringAttribute(const Location& loc, const std::string& name) {
    const std::string what = attributeWhat(loc, name);
    auto [attr, type] = openTypedAttribute(loc, name, H5T_STRING, "a string");
    const htri_t variable = H5Tis_variable_str(type.get());
    check(variable, loc, what, "inspect the string type");
    Handle memory(H5Tcopy(type.get()), H5Tclose);
    check(memory.get(), loc, what, "copy the string type");
    if (variable > 0) {
        char* text = nullptr;
        check(H5Aread(attr.get(), memory.get(), &text), loc, what, "read");
        std::string value = text != nullptr ? text : "";
        H5free_memory(text);
        return value;
    }
    const std::size_t size = H5Tget_size(type.get());
    std::vector<char> buffer(size + 1, '\0');
    check(H5Aread(attr.get(), memory.get(), buffer.data()), loc, what, "read");
    return std::string(buffer.data(), ::strnlen(buffer.data(), size));
}

}  // namespace seaspring::io::h5
