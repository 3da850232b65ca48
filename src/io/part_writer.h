// SeaSpring — MIT licence.
/// \file part_writer.h
/// \brief Part files written behind the run: the arrays of one output time handed to a
///        background thread, which writes data/part_NNNN.h5 (writePartH5) while the run goes
///        on; one file at a time, in output order.
///
/// Why: on a GPU the host thread mostly waits for the device, and an output's HDF5 write is
/// a large share of an output (0.5 s per output at 4.36 M particles on an NVIDIA H200, of
/// which the write is the part this hides; docs/performance-large.md, twenty-first session).
/// With `background` false (the CPU backend, whose threads the write would slow) every file
/// is written at once, as before.
///
/// At most one file is in flight: submitting the next waits for the previous one, so the
/// extra memory is one output's arrays. A failed write is not lost: its error (seaspring::Error
/// naming the file) is thrown by the next submit or by wait(). The HDF5 library is used by
/// one thread at a time only if the owner calls wait() before its own HDF5 calls (restart
/// files) and before it reads the files.
#pragma once

#include <cstdint>
#include <future>
#include <memory>
#include <string>
#include <vector>

#include "io/part_output.h"

namespace seaspring::io {

/// The arrays of one output time (id order), owned; the arrays every output shares (ids, MKs,
/// masses: the case's) are borrowed and must outlive the writer.
struct PartArrays {
    int index = 0;
    double time = 0;
    long long step = 0;
    std::size_t np = 0;
    std::vector<double> pos;
    std::vector<float> vel, rhop, press;
    std::vector<std::uint8_t> type, excluded;
    std::vector<float> disp, strain, damage;  ///< solid fields: all three or none
    std::vector<std::uint8_t> broken;
    const std::uint32_t* id = nullptr;
    const std::uint16_t* mk = nullptr;
    const float* mass = nullptr;
    PartConstants constants;
};

/// The frame writePartH5 takes, borrowing from `a`.
PartFrame frameOf(const PartArrays& a);

class PartWriter {
public:
    PartWriter(std::string outdir, bool background);
    PartWriter(const PartWriter&) = delete;
    PartWriter& operator=(const PartWriter&) = delete;
    /// Waits for a file still being written (its error, if any, is lost here: call wait()).
    ~PartWriter();
    /// Writes `a` as OUTDIR/data/part_NNNN.h5 (NNNN = a.index), in the background or at once;
    /// returns its path relative to OUTDIR. Waits for the previous file first and throws its
    /// error, if it failed.
    std::string submit(PartArrays a);
    /// Waits until every submitted file is written; throws the error of one that failed.
    void wait();
    /// The arrays of the last file written (after wait()), for the next output to fill in
    /// place: their pages are mapped already, where fresh vectors of an output's size (about
    /// 45 bytes a particle) would be cleared page by page by the kernel. Empty at first; the
    /// caller resizes what it uses.
    PartArrays takeSpare();

private:
    std::string outdir_;
    bool background_;
    std::future<void> pending_;
    std::shared_ptr<PartArrays> last_;  ///< the arrays of the file submitted last
};

}  // namespace seaspring::io
