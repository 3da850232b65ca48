// SeaSpring — MIT licence.
/// \file run_log.cpp
/// \brief The tee behind OUTDIR/Run.out (see run_log.h).
#include "solver/run_log.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>

#include "core/error.h"

namespace seaspring::solver {

TeeBuffer::int_type TeeBuffer::overflow(int_type c) {
    if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
    const char ch = traits_type::to_char_type(c);
    const bool console_ok = !traits_type::eq_int_type(console_->sputc(ch), traits_type::eof());
    const bool file_ok = !traits_type::eq_int_type(file_->sputc(ch), traits_type::eof());
    if (ch == '\n') file_->pubsync();
    return console_ok && file_ok ? c : traits_type::eof();
}

std::streamsize TeeBuffer::xsputn(const char* s, std::streamsize n) {
    const std::streamsize console_n = console_->sputn(s, n);
    const std::streamsize file_n = file_->sputn(s, n);
    if (std::memchr(s, '\n', std::size_t(n)) != nullptr) file_->pubsync();
    return std::min(console_n, file_n);
}

int TeeBuffer::sync() {
    const int console = console_->pubsync();
    const int file = file_->pubsync();
    return console == 0 && file == 0 ? 0 : -1;
}

namespace {
/// OUTDIR/Run.out, after creating OUTDIR.
std::string runLogPath(const std::string& outdir) {
    std::error_code ec;
    std::filesystem::create_directories(outdir, ec);
    if (ec) throw Error(formatLocation(outdir, 0, "cannot create the output folder: " + ec.message()));
    return (std::filesystem::path(outdir) / "Run.out").string();
}
}  // namespace

RunLog::RunLog(const std::string& outdir, std::ostream& console, bool append)
    : path_(runLogPath(outdir)),
      file_(path_, std::ios::out | (append ? std::ios::app : std::ios::trunc)),
      tee_(console.rdbuf(), file_.rdbuf()),
      out_(&tee_) {
    if (!file_)
        throw Error(formatLocation(path_, 0, std::string("cannot create the run log: ") + std::strerror(errno)));
}

void RunLog::error(std::ostream& errors, const std::string& text) {
    out_.flush();
    errors << text << std::flush;
    file_ << text << std::flush;
}

}  // namespace seaspring::solver
