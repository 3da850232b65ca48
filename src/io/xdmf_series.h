// SeaSpring — MIT licence.
/// \file xdmf_series.h
/// \brief OUTDIR/parts.xdmf: one XDMF 3 temporal collection over the part_NNNN.h5 files that
///        ParaView opens directly (Polyvertex points; vel, rhop, press, type, mk, id, excluded).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace seaspring::io {

class XdmfSeries {
public:
    explicit XdmfSeries(std::string outdir);
    /// Adds a frame and rewrites parts.xdmf (temporary name, then rename) with all frames.
    void add(const std::string& h5_relative_path, double time, std::size_t np);
    const std::string& path() const { return path_; }

private:
    struct Frame {
        std::string file;
        double time;
        std::size_t np;
    };
    std::string outdir_, path_;
    std::vector<Frame> frames_;
};

}  // namespace seaspring::io
