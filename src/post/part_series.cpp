// SeaSpring — MIT licence.
/// \file part_series.cpp
/// \brief The part files of a run and the atomic text output (see part_series.h).
#include "post/part_series.h"

#include <algorithm>
#include <filesystem>

#include "core/error.h"

namespace seaspring::post {

namespace fs = std::filesystem;

std::vector<std::pair<int, std::string>> listPartFiles(const std::string& dirin, int first, int last) {
    const fs::path data = fs::path(dirin) / "data";
    std::error_code ec;
    if (!fs::is_directory(data, ec)) throw Error(data.string() + ": no such folder (is -dirin the run's OUTDIR?)");
    std::vector<std::pair<int, std::string>> v;
    for (const auto& e : fs::directory_iterator(data, ec)) {
        const std::string n = e.path().filename().string();
        if (n.size() < 5 + 4 + 3 || n.compare(0, 5, "part_") != 0 || n.compare(n.size() - 3, 3, ".h5") != 0) continue;
        const std::string num = n.substr(5, n.size() - 8);
        if (num.size() < 4 || num.size() > 9 || !std::all_of(num.begin(), num.end(), [](char ch) { return ch >= '0' && ch <= '9'; }))
            continue;
        const int idx = std::stoi(num);
        if ((first >= 0 && idx < first) || (last >= 0 && idx > last)) continue;
        v.emplace_back(idx, e.path().string());
    }
    std::sort(v.begin(), v.end());
    if (v.empty())
        throw Error(data.string() + ": no part_NNNN.h5 file" +
                    (first >= 0 || last >= 0 ? " in the range " + std::to_string(std::max(first, 0)) + ".." +
                                                   (last >= 0 ? std::to_string(last) : std::string("end"))
                                             : std::string()));
    return v;
}

AtomicTextFile::AtomicTextFile(std::string path) : path_(std::move(path)), tmp_(path_ + ".tmp") {
    if (path_.empty()) throw Error("no output file given");
    const fs::path parent = fs::path(path_).parent_path();
    std::error_code ec;
    if (!parent.empty()) fs::create_directories(parent, ec);
    f_ = std::fopen(tmp_.c_str(), "w");
    if (!f_) throw Error(path_ + ": cannot write the file");
}

AtomicTextFile::~AtomicTextFile() {
    if (done_) return;
    if (f_) std::fclose(f_);
    std::error_code ec;
    fs::remove(tmp_, ec);
}

void AtomicTextFile::commit() {
    const bool ok = std::ferror(f_) == 0;
    const int rc = std::fclose(f_);
    f_ = nullptr;
    if (!ok || rc != 0) throw Error(path_ + ": write failed");
    std::error_code ec;
    fs::rename(tmp_, path_, ec);
    if (ec) throw Error(path_ + ": cannot rename " + tmp_ + ": " + ec.message());
    done_ = true;
}

}  // namespace seaspring::post
