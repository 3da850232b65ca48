// SeaSpring — MIT licence.
/// \file vti_writer.h
/// \brief A field on a regular grid: VTK XML ImageData (.vti) files (ParaView, VTK's readers).
///
/// Point data only, Float32 arrays, raw binary in an appended block (encoding="raw",
/// header_type="UInt64": each array is a UInt64 byte count followed by its bytes, in host byte
/// order, which byte_order declares). Values are x fastest, then y, then z.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace seaspring::io {

struct VtiArray {
    std::string name;          ///< letters, digits, '_' and '.' only
    std::vector<float> values;  ///< nx * ny * nz
};

struct ImageGrid {
    std::array<double, 3> origin{0, 0, 0};   ///< first node [m]
    std::array<double, 3> spacing{1, 1, 1};  ///< between nodes [m], > 0
    std::array<int, 3> dims{1, 1, 1};        ///< nodes per axis, >= 1
    std::size_t nodes() const { return std::size_t(dims[0]) * std::size_t(dims[1]) * std::size_t(dims[2]); }
};

/// Writes `path` (through "<path>.tmp", renamed when complete; removed on failure). Throws
/// seaspring::Error naming the file for an array of the wrong length or a bad name, a bad grid,
/// or a file that cannot be written.
void writeImageVti(const std::string& path, const ImageGrid& g, const std::vector<VtiArray>& arrays);

}  // namespace seaspring::io
