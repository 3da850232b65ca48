// SeaSpring — MIT licence.
/// \file part_series.h
/// \brief What every `seaspring-post` subcommand reads and writes around its loop: the run's
///        part files OUTDIR/data/part_NNNN.h5 in a range, and a text output (CSV) written under
///        a temporary name and renamed only when complete.
#pragma once

#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace seaspring::post {

/// The part files OUTDIR/data/part_NNNN.h5 with first <= NNNN <= last (negative: no bound),
/// ascending: (index, path). Throws when OUTDIR/data is missing or holds none in the range.
std::vector<std::pair<int, std::string>> listPartFiles(const std::string& dirin, int first, int last);

/// A text file written as PATH.tmp and renamed to PATH by commit(); destroyed without commit()
/// (an error on the way), the temporary file is removed and PATH is left as it was.
class AtomicTextFile {
public:
    /// Opens PATH.tmp; throws seaspring::Error naming PATH when it cannot.
    explicit AtomicTextFile(std::string path);
    ~AtomicTextFile();
    AtomicTextFile(const AtomicTextFile&) = delete;
    AtomicTextFile& operator=(const AtomicTextFile&) = delete;
    std::FILE* file() const { return f_; }
    /// Closes and renames; throws seaspring::Error naming PATH on failure.
    void commit();

private:
    std::string path_, tmp_;
    std::FILE* f_ = nullptr;
    bool done_ = false;
};

}  // namespace seaspring::post
