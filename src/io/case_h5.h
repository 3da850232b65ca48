// SeaSpring — MIT licence.
/// \file case_h5.h
/// \brief The particle file gencase writes (OUTDIR/NAME.h5) and the solver reads.
///
/// Layout (format "seaspring-case", format_version 1):
///   /                 attributes format, format_version (int64), case_name, dimensions
///                     (int64), dp (double), np (int64), generator
///   /particles/id     uint32 [np]          /particles/type  uint8 [np] (ParticleType)
///   /particles/mk     uint16 [np]          /particles/pos   float64 [np x 3]
///   /particles/vel    float32 [np x 3]     /particles/rhop  float32 [np]
///   /particles/mass   float32 [np]
///   /particles/normal float32 [nbound x 3]  only when the case has mDBC normals: the ghost
///                     vector of each non-fluid particle (ids 0..nbound-1), ParticleSet::normal
///   /bonds            only when the case has VCPM solids; attribute first_solid (int64)
///   /bonds/offset     uint32 [n_solid+1]   /bonds/neighbour uint32 [slots]
///   /bonds/rest_length float64 [slots]     /bonds/kind      uint8 [slots] (BondKind flags)
///
/// Writing goes to "<path>.tmp", renamed to `path` only once complete; on failure the
/// temporary file is removed and an existing `path` is left untouched. Both writing and
/// reading check consistency: array lengths equal np, type values are ParticleTypes, the
/// bond rows are exactly the Solid particles (contiguous from first_solid), offsets start
/// at 0, never decrease and end at the slot count, neighbours < np, kinds are BondKind
/// flags, rest lengths are positive; /particles/normal has one finite entry per non-fluid
/// particle and those particles are ids 0..nbound-1. Errors name the file and what is wrong.
#pragma once

#include <cstdint>
#include <string>

#include "core/particle_set.h"

namespace seaspring::io {

/// Value of the root attribute "format".
inline constexpr const char* kCaseFormat = "seaspring-case";
/// Value of the root attribute "format_version" this code writes and reads.
inline constexpr int kCaseFormatVersion = 1;

struct CaseFileHeader {
    std::string case_name;
    int dimensions = 3;      ///< 2 or 3
    double dp = 0.0;         ///< particle spacing [m], > 0
    std::uint64_t np = 0;    ///< particle count; must equal the particle set's size
    std::string generator;   ///< e.g. "SeaSpring gencase 0.1.0"
};

/// Writes the case file. `bonds` is nullptr when the case has no VCPM solids.
void writeCaseH5(const std::string& path, const CaseFileHeader& header, const ParticleSet& p,
                 const BondNetwork* bonds);

struct CaseFileContents {
    CaseFileHeader header;
    ParticleSet particles;
    BondNetwork bonds;       ///< empty when !has_bonds
    bool has_bonds = false;
};

/// Reads and validates a case file written by writeCaseH5.
CaseFileContents readCaseH5(const std::string& path);

}  // namespace seaspring::io
