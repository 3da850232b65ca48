// SeaSpring — MIT licence.
/// \file run_log.h
/// \brief OUTDIR/Run.out: a copy of everything the solver prints (the banner, the case and
///        physics lines, warnings, progress lines, the summary and errors), as DualSPHysics
///        keeps its Run.out. The file is flushed at every line, so it can be followed during a
///        run and holds everything up to a crash.
#pragma once

#include <fstream>
#include <ostream>
#include <streambuf>
#include <string>

namespace seaspring::solver {

/// A stream buffer that passes every character to a console buffer and a file buffer; the
/// file is flushed at every newline and at every flush of the stream.
class TeeBuffer : public std::streambuf {
public:
    TeeBuffer(std::streambuf* console, std::streambuf* file) : console_(console), file_(file) {}

protected:
    int_type overflow(int_type c) override;
    std::streamsize xsputn(const char* s, std::streamsize n) override;
    int sync() override;

private:
    std::streambuf* console_;
    std::streambuf* file_;
};

/// The solver's log: `out()` writes to the console stream and to OUTDIR/Run.out.
class RunLog {
public:
    /// Creates OUTDIR (if needed) and OUTDIR/Run.out (replacing an older one; `append`: a
    /// restarted run continuing in OUTDIR adds to it). Throws seaspring::Error naming the
    /// file when it cannot be created.
    RunLog(const std::string& outdir, std::ostream& console, bool append = false);
    RunLog(const RunLog&) = delete;
    RunLog& operator=(const RunLog&) = delete;

    /// Console and Run.out.
    std::ostream& out() { return out_; }
    /// Writes `text` to `errors` (the console's error stream) and to Run.out, and flushes both.
    void error(std::ostream& errors, const std::string& text);
    /// OUTDIR/Run.out.
    const std::string& path() const { return path_; }

private:
    std::string path_;
    std::ofstream file_;
    TeeBuffer tee_;
    std::ostream out_;
};

}  // namespace seaspring::solver
