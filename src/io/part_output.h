// SeaSpring — MIT licence.
/// \file part_output.h
/// \brief The solver's per-output-time particle files OUTDIR/data/part_NNNN.h5.
///
/// Layout: /pos (np x 3 float64), /vel (np x 3 float32), /rhop, /press (float32), /id (uint32),
/// /type (uint8), /mk (uint16), /excluded (uint8: 0 active, 1 left the domain, 2 density out
/// of range, 3 not finite); root attributes time, step, np, format = "SeaSpring part",
/// format_version = 1. Particles in id order.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace seaspring::io {

struct PartFrame {
    int index = 0;
    double time = 0;
    long long step = 0;
    std::size_t np = 0;
    const double* pos = nullptr;
    const float* vel = nullptr;
    const float* rhop = nullptr;
    const float* press = nullptr;
    const std::uint32_t* id = nullptr;
    const std::uint8_t* type = nullptr;
    const std::uint16_t* mk = nullptr;
    const std::uint8_t* excluded = nullptr;
};

/// Writes OUTDIR/data/part_NNNN.h5 (temporary name, then rename); returns "data/part_NNNN.h5".
std::string writePartH5(const std::string& outdir, const PartFrame& f);

struct PartData {
    double time = 0;
    long long step = 0;
    std::vector<double> pos;
    std::vector<float> vel, rhop, press;
    std::vector<std::uint32_t> id;
    std::vector<std::uint8_t> type, excluded;
    std::vector<std::uint16_t> mk;
};

PartData readPartH5(const std::string& path);

}  // namespace seaspring::io
