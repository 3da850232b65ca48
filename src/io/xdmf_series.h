// SeaSpring — MIT licence.
/// \file xdmf_series.h
/// \brief OUTDIR/parts.xdmf: an XDMF 3 temporal collection over the data/part_NNNN.h5 files,
///        which ParaView opens directly (File > Open, "XDMF Reader").
///
/// The file holds one Domain with one Grid GridType="Collection" CollectionType="Temporal";
/// each frame is a Uniform grid with its Time, a Polyvertex topology (one vertex per
/// particle, excluded ones included), XYZ geometry from "FILE:/pos", and node attributes
/// vel (Vector, Float 4), rhop and press (Scalar, Float 4), type (UChar 1), mk (UInt 2),
/// id (UInt 4), excluded (UChar 1) and mass (Scalar, Float 4: ParaView's SPH filters take
/// it as their mass array) — the element types of the part file (part_output.h);
/// with VCPM solids also disp (Vector, Float 4), strain (Float 4), broken (UChar 1) and
/// damage (Float 4).
/// HDF5 paths are written as given, relative to the folder of parts.xdmf, so that an output
/// folder can be moved or copied as a whole. Times are printed with "%.17g".
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace seaspring::io {

class XdmfSeries {
public:
    /// The series OUTDIR/parts.xdmf; nothing is written until the first add().
    explicit XdmfSeries(std::string outdir);

    /// Adds a frame and rewrites parts.xdmf with all frames so far (temporary file, then
    /// rename, so a reader never sees a half-written file). `h5_relative_path` is the part
    /// file relative to OUTDIR, as writePartH5 returns it ("data/part_0003.h5"). Throws
    /// seaspring::Error for an empty path, a non-finite time or a file that cannot be
    /// written; the frame is then not kept.
    /// `solids`: the part file holds the solid fields (disp, strain, broken).
    void add(const std::string& h5_relative_path, double time, std::size_t np, bool solids = false);

    /// OUTDIR/parts.xdmf.
    const std::string& path() const { return path_; }
    std::size_t frameCount() const { return frames_.size(); }
    /// The frames so far (a restart file keeps them) ...
    const std::vector<std::string>& frames() const { return frames_; }
    /// ... and back (a restarted run continuing in the same OUTDIR; written at the next add()).
    void restoreFrames(std::vector<std::string> frames) { frames_ = std::move(frames); }

private:
    std::string outdir_;
    std::string path_;
    std::vector<std::string> frames_;  ///< the XML text of each frame's Uniform grid
};

}  // namespace seaspring::io
