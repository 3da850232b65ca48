// SeaSpring — MIT licence.
/// \file part_output.h
/// \brief The solver's particle file of one output time, OUTDIR/data/part_NNNN.h5.
///
/// Layout (format "SeaSpring part", format_version 2), every dataset contiguous (neither
/// chunked nor compressed: output speed comes first), particles in id order:
///   /pos   float64 [np x 3] [m]        /vel      float32 [np x 3] [m/s]
///   /rhop  float32 [np] [kg/m^3]        /press    float32 [np] [Pa]
///   /mass  float32 [np] [kg] (the case's particle masses: fluid, boundary, solid differ)
///   /id    uint32 [np]                  /type     uint8 [np] (ParticleType values)
///   /mk    uint16 [np]                  /excluded uint8 [np] (0 active, >0 excluded: 1 left
///                                                  the domain, 2 density out of range,
///                                                  3 not finite)
///   with VCPM solids only (zero for the other particles):
///   /disp  float32 [np x 3] displacement from the initial position [m]
///   /strain float32 [np] mean relative elongation (|r|-L0)/L0 of the intact bonds
///   /broken uint8 [np] number of broken bonds
///   /damage float32 [np] broken bonds / initial bonds of the particle (0 intact .. 1 detached)
///   root attributes: time (float64 [s]), step (int64, time steps done), np (int64),
///                    format (string), format_version (int64), and the case constants that
///                    ParaView's SPH filters ask for: h (float64, smoothing length [m]), dp
///                    (float64 [m]), kernel (string: "Wendland C2" or "cubic spline"; both
///                    reach 2h), rhop0 (float64 [kg/m^3]), dimension (int64, 2 or 3), b (float64, Tait B [Pa])
/// Version 1 (before /mass and the case constants) is still read: mass is then empty.
/// np = 0 is valid (empty datasets). The file is written as "part_NNNN.h5.tmp" and renamed
/// when complete, so a crash never leaves a half-written part_NNNN.h5.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace seaspring::io {

/// Value of the root attribute "format".
inline constexpr const char* kPartFormat = "SeaSpring part";
/// Value of the root attribute "format_version" this code writes (it reads 1 and 2).
inline constexpr int kPartFormatVersion = 2;

/// The case constants a part file carries as root attributes (for ParaView's SPH filters).
struct PartConstants {
    double h = 0;            ///< smoothing length [m]
    double dp = 0;           ///< particle spacing [m]
    std::string kernel;      ///< "Wendland C2" or "cubic spline"
    double rhop0 = 0;        ///< reference density [kg/m^3]
    int dimension = 3;       ///< 2 or 3
    double b = 0;            ///< Tait B [Pa] (the solver's pressure is Tait(rhop) with float(b))
};

/// One output time; particles in id order (array index = particle id). The arrays are
/// borrowed, not copied; each may be nullptr only when np == 0.
struct PartFrame {
    int index = 0;            ///< output number: file data/part_NNNN.h5 (at least 4 digits)
    double time = 0;          ///< physical time [s]
    long long step = 0;       ///< time steps done
    std::size_t np = 0;       ///< all particles, excluded ones included
    const double* pos = nullptr;             ///< 3*np, x y z interleaved [m]
    const float* vel = nullptr;              ///< 3*np [m/s]
    const float* rhop = nullptr;             ///< np [kg/m^3]
    const float* press = nullptr;            ///< np [Pa]
    const std::uint32_t* id = nullptr;       ///< np
    const std::uint8_t* type = nullptr;      ///< np (ParticleType values)
    const std::uint16_t* mk = nullptr;       ///< np
    const std::uint8_t* excluded = nullptr;  ///< np, 0 = active, >0 = excluded (reason code)
    const float* mass = nullptr;             ///< np [kg]
    PartConstants constants;                 ///< root attributes h, dp, kernel, rhop0, dimension, b
    // Solid fields: all three or none (cases without VCPM solids).
    const float* disp = nullptr;             ///< 3*np [m]
    const float* strain = nullptr;           ///< np
    const std::uint8_t* broken = nullptr;    ///< np
    const float* damage = nullptr;           ///< np
};

/// "data/part_0007.h5" for index 7 (at least 4 digits; "data/part_12345.h5" beyond).
std::string partFileName(int index);

/// Writes OUTDIR/data/part_NNNN.h5, creating OUTDIR/data if needed. Returns the path
/// relative to OUTDIR ("data/part_0000.h5"). Throws seaspring::Error naming the file on
/// any failure (negative index, missing arrays, folder or file not writable); the
/// temporary file is then removed and an existing part file is left as it was.
std::string writePartH5(const std::string& outdir, const PartFrame& f);

/// The contents of a part file, as read back by readPartH5.
struct PartData {
    double time = 0;
    long long step = 0;
    std::vector<double> pos;                  ///< 3*np
    std::vector<float> vel, rhop, press;      ///< 3*np, np, np
    std::vector<std::uint32_t> id;
    std::vector<std::uint8_t> type, excluded;
    std::vector<std::uint16_t> mk;
    std::vector<float> mass;                  ///< np (empty in a version 1 file)
    PartConstants constants;                  ///< the defaults above in a version 1 file
    std::vector<float> disp, strain, damage;  ///< solid fields (empty when absent)
    std::vector<std::uint8_t> broken;
    std::size_t np() const { return id.size(); }
};

/// Reads a part file (for tests and tools). Checks the format attributes and that every
/// dataset has the type and shape above; errors name the file and the dataset.
PartData readPartH5(const std::string& path);

}  // namespace seaspring::io
