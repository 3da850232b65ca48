// SeaSpring — MIT licence.
#include "io/checkpoint_file.h"

#include <cstdio>
#include <filesystem>
#include <sstream>
#include <vector>

#include "core/error.h"
#include "io/h5_util.h"

namespace seaspring::io {

namespace {

constexpr const char* kFormat = "seaspring-restart";
constexpr std::int64_t kFormatVersion = 1;

std::string h5Name(std::string s) {
    for (char& c : s)
        if (c == '/') c = '.';
    return s;
}

std::string joinNames(const std::vector<std::string>& names) {
    std::string r = "\n";  // never empty (an HDF5 string attribute of length 0 is not allowed)
    for (const std::string& n : names) r += n + "\n";
    return r;
}
std::vector<std::string> splitNames(const std::string& s) {
    std::vector<std::string> r;
    std::istringstream in(s);
    for (std::string line; std::getline(in, line);)
        if (!line.empty()) r.push_back(line);
    return r;
}

template <class M, typename T>
void writeValues(const io::h5::File& f, const char* group, const M& m) {
    const io::h5::Location g = f.createGroup(group);
    std::vector<std::string> names;
    std::vector<T> values;
    for (const auto& kv : m) {
        names.push_back(kv.first);
        values.push_back(T(kv.second));
    }
    io::h5::writeDataset(g, "values", values);
    io::h5::writeStringAttribute(g, "names", joinNames(names));
}

template <class M, typename T>
void readValues(const io::h5::File& f, const char* group, M& m) {
    const io::h5::Location g = f.openGroup(group);
    const std::vector<std::string> names = splitNames(io::h5::readStringAttribute(g, "names"));
    const std::vector<T> values = io::h5::readDataset<T>(g, "values");
    if (values.size() != names.size())
        g.fail("dataset values", "has " + std::to_string(values.size()) + " values for " + std::to_string(names.size()) +
                                     " names");
    for (std::size_t k = 0; k < names.size(); ++k) m[names[k]] = typename M::mapped_type(values[k]);
}

}  // namespace

void writeCheckpointFile(const std::string& path, const CheckpointData& d) {
    const std::string tmp = path + ".tmp";
    {
        io::h5::File f = io::h5::File::create(tmp);
        io::h5::writeStringAttribute(f, "format", kFormat);
        io::h5::writeInt64Attribute(f, "format_version", kFormatVersion);
        {
            const io::h5::Location g = f.createGroup("arrays");
            for (const auto& kv : d.blobs) {
                const std::string name = h5Name(kv.first);
                io::h5::writeDataset(g, name, kv.second.bytes);
                // The element size: an attribute "<name>:elem" of the group.
                io::h5::writeInt64Attribute(g, name + ":elem", kv.second.elem_size);
            }
            std::vector<std::string> names;
            for (const auto& kv : d.blobs) names.push_back(kv.first);
            io::h5::writeStringAttribute(g, "names", joinNames(names));
        }
        writeValues<std::map<std::string, double>, double>(f, "reals", d.reals);
        writeValues<std::map<std::string, long long>, std::int64_t>(f, "ints", d.ints);
        {
            const io::h5::Location g = f.createGroup("texts");
            std::vector<std::string> names;
            int k = 0;
            for (const auto& kv : d.texts) {
                names.push_back(kv.first);
                io::h5::writeStringAttribute(g, "t" + std::to_string(k++), kv.second);
            }
            io::h5::writeStringAttribute(g, "names", joinNames(names));
        }
        f.close();
    }
    std::error_code ec;
    std::filesystem::rename(tmp, path, ec);
    if (ec) throw Error(path + ": cannot replace the restart file with " + tmp + " (" + ec.message() + ")");
}

CheckpointData readCheckpointFile(const std::string& path) {
    if (!std::filesystem::exists(path)) throw Error(path + ": restart file not found");
    io::h5::File f = io::h5::File::openReadOnly(path);
    if (!f.hasAttribute("format") || io::h5::readStringAttribute(f, "format") != kFormat)
        throw Error(path + ": not a SeaSpring restart file (no format attribute \"" + std::string(kFormat) + "\")");
    const std::int64_t version = io::h5::readInt64Attribute(f, "format_version");
    if (version != kFormatVersion)
        throw Error(path + ": restart file format version " + std::to_string(version) + ", this build reads " +
                    std::to_string(kFormatVersion));
    CheckpointData d;
    d.source = path;
    {
        const io::h5::Location g = f.openGroup("arrays");
        for (const std::string& name : splitNames(io::h5::readStringAttribute(g, "names"))) {
            CheckpointData::Blob& b = d.blobs[name];
            b.bytes = io::h5::readDataset<std::uint8_t>(g, h5Name(name));
            const std::int64_t elem = io::h5::readInt64Attribute(g, h5Name(name) + ":elem");
            if (elem <= 0 || b.bytes.size() % std::size_t(elem) != 0)
                g.fail("dataset " + h5Name(name), "element size " + std::to_string(elem) + " does not divide " +
                                                      std::to_string(b.bytes.size()) + " bytes");
            b.elem_size = std::uint32_t(elem);
        }
    }
    readValues<std::map<std::string, double>, double>(f, "reals", d.reals);
    readValues<std::map<std::string, long long>, std::int64_t>(f, "ints", d.ints);
    {
        const io::h5::Location g = f.openGroup("texts");
        int k = 0;
        for (const std::string& name : splitNames(io::h5::readStringAttribute(g, "names")))
            d.texts[name] = io::h5::readStringAttribute(g, "t" + std::to_string(k++));
    }
    return d;
}

bool cutForResume(const std::string& path, long long offset) {
    std::error_code ec;
    if (offset < 0 || !std::filesystem::is_regular_file(path, ec)) return false;
    const auto size = std::filesystem::file_size(path, ec);
    if (ec || (long long)size < offset) return false;
    std::filesystem::resize_file(path, std::uintmax_t(offset), ec);
    if (ec) throw Error(path + ": cannot cut the file to its restart point (" + ec.message() + ")");
    return true;
}

}  // namespace seaspring::io
