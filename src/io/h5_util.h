// SeaSpring — MIT licence.
/// \file h5_util.h
/// \brief Thin RAII wrappers over the HDF5 C API: files, groups, whole-array datasets
///        and scalar attributes, every call checked.
///
/// Every failure throws seaspring::Error as "FILE: OBJECT: what failed (HDF5: reason)",
/// e.g. "out/case.h5: dataset /particles/pos: has 4 rows, expected 5". HDF5's own
/// error printing to stderr is switched off the first time a file is created or opened
/// (the reason is taken from HDF5's error stack instead).
///
/// Arrays are written and read whole, in one H5Dwrite/H5Dread call. Shapes: `cols == 1`
/// is a 1-D dataset [rows]; `cols > 1` a 2-D dataset [rows][cols] (e.g. N×3 positions).
/// Element types supported: uint8, uint16, uint32, uint64, int32, int64, float, double;
/// they are stored little-endian; reading checks the stored type is the same kind
/// (integer sign and size, or float size) and never converts silently.
#pragma once

#include <hdf5.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace seaspring::io::h5 {

/// Owns one HDF5 identifier and closes it with the matching H5*close function.
class Handle {
public:
    using Closer = herr_t (*)(hid_t);

    Handle() = default;
    Handle(hid_t id, Closer closer) : id_(id), closer_(closer) {}
    ~Handle() { reset(); }
    Handle(Handle&& other) noexcept : id_(other.id_), closer_(other.closer_) {
        other.id_ = H5I_INVALID_HID;
    }
    Handle& operator=(Handle&& other) noexcept;
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;

    hid_t get() const { return id_; }
    bool valid() const { return id_ >= 0; }
    /// Closes now; returns the closer's status (negative on failure), 0 when not open.
    herr_t reset();

private:
    hid_t id_ = H5I_INVALID_HID;
    Closer closer_ = nullptr;
};

/// A file or a group, with its names kept for error messages.
class Location {
public:
    hid_t id() const { return handle_.get(); }
    const std::string& file() const { return file_; }
    /// Object path inside the file: "/" for the file, "/particles" for a group.
    const std::string& path() const { return path_; }
    /// Path of a child object, e.g. childPath("pos") == "/particles/pos".
    std::string childPath(const std::string& name) const;

    Location createGroup(const std::string& name) const;
    Location openGroup(const std::string& name) const;
    /// True when a link (group or dataset) of that name exists here.
    bool hasChild(const std::string& name) const;
    bool hasAttribute(const std::string& name) const;
    /// Unlinks the child object `name` (a dataset or group); throws if it is missing.
    void removeChild(const std::string& name) const;

    /// Throws Error "FILE: OBJECT: message" (OBJECT = `what`, e.g. "dataset /bonds/kind").
    [[noreturn]] void fail(const std::string& what, const std::string& message) const;

protected:
    Location(Handle handle, std::string file, std::string path)
        : handle_(std::move(handle)), file_(std::move(file)), path_(std::move(path)) {}

    Handle handle_;
    std::string file_;
    std::string path_;
};

/// An open HDF5 file (the root group "/").
class File : public Location {
public:
    /// Creates (truncating) a file for writing.
    static File create(const std::string& path);
    /// Opens an existing file read-only. Distinguishes "does not exist" from "not HDF5".
    static File openReadOnly(const std::string& path);
    /// Opens an existing file for reading and writing (e.g. to amend it in tests).
    static File openReadWrite(const std::string& path);
    /// Flushes and closes, checked. Groups opened from this file must be gone already.
    void close();

private:
    using Location::Location;
};

/// Dataset storage choices.
struct WriteOptions {
    /// Datasets with more rows than this are chunked in chunks of this many rows;
    /// smaller ones are contiguous.
    std::size_t chunk_rows = std::size_t(1) << 20;
    /// gzip level 1-9 (forces chunking); 0 = no compression.
    int deflate_level = 0;
};

/// Shape of a stored dataset: rank 1 -> cols == 1.
struct DatasetShape {
    int rank = 0;
    std::size_t rows = 0;
    std::size_t cols = 0;
};

/// Writes `data[rows*cols]` (row-major) as dataset `name` in one H5Dwrite call.
template <typename T>
void writeDataset(const Location& loc, const std::string& name, const T* data,
                  std::size_t rows, std::size_t cols = 1, const WriteOptions& options = {});

template <typename T>
void writeDataset(const Location& loc, const std::string& name, const std::vector<T>& data,
                  const WriteOptions& options = {}) {
    writeDataset<T>(loc, name, data.data(), data.size(), 1, options);
}

/// Shape of dataset `name`; throws if it is missing or has rank other than 1 or 2.
DatasetShape datasetShape(const Location& loc, const std::string& name);

/// Reads dataset `name` into `out[rows*cols]` in one H5Dread call. Throws unless the
/// dataset has exactly that shape (rank 1 when cols == 1) and element type T.
template <typename T>
void readDatasetInto(const Location& loc, const std::string& name, T* out,
                     std::size_t rows, std::size_t cols = 1);

/// Reads a whole 1-D dataset of element type T, whatever its length.
template <typename T>
std::vector<T> readDataset(const Location& loc, const std::string& name);

/// Scalar attributes on a file or group. Writing replaces an attribute of the same name.
/// Strings are stored fixed-length, NUL-terminated, UTF-8; variable-length strings (as
/// written by h5py) are read too. Reading checks the stored type class (float / integer /
/// string) and that the attribute is a single value.
void writeDoubleAttribute(const Location& loc, const std::string& name, double value);
void writeInt64Attribute(const Location& loc, const std::string& name, std::int64_t value);
void writeStringAttribute(const Location& loc, const std::string& name, const std::string& value);
double readDoubleAttribute(const Location& loc, const std::string& name);
std::int64_t readInt64Attribute(const Location& loc, const std::string& name);
std::string readStringAttribute(const Location& loc, const std::string& name);

}  // namespace seaspring::io::h5
