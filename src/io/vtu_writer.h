// SeaSpring — MIT licence.
/// \file vtu_writer.h
/// \brief ParaView preview of particles: VTK XML UnstructuredGrid (.vtu) files.
///
/// One VTK_VERTEX cell per particle; all arrays are stored as raw binary in an appended
/// block (encoding="raw", header_type="UInt64": each array is a UInt64 byte count followed
/// by its bytes, in host byte order, which byte_order declares). Point data: id (UInt32),
/// type (UInt8), mk (UInt16), vel (Float32 x3), rhop (Float32), mass (Float32), then the
/// extra arrays in the order given; points are Float64 x3. Cell connectivity/offsets are
/// Int32 (Int64 beyond 2^31-1 particles), cell types UInt8.
#pragma once

#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "core/particle_set.h"

namespace seaspring::io {

/// An additional per-particle array (one value per particle), e.g. {"bonds", counts}
/// with a std::vector<std::uint8_t>, or {"stress", values} with a std::vector<float>.
struct VtuExtraArray {
    std::string name;
    std::variant<std::vector<float>, std::vector<std::uint8_t>> values;
};

/// Writes the particles to `path` (through "<path>.tmp", renamed when complete; the
/// temporary file is removed on failure). Throws seaspring::Error naming the file when an
/// extra array has the wrong length, an empty or duplicate name, or a name with one of
/// the characters & < > " ' or a control character; when the particle set's arrays have
/// different lengths; or when the file cannot be written.
void writeParticlesVtu(const std::string& path, const ParticleSet& p,
                       const std::vector<VtuExtraArray>& extra = {});

}  // namespace seaspring::io
