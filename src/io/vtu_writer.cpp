// SeaSpring — MIT licence.
/// \file vtu_writer.cpp
/// \brief VTK XML UnstructuredGrid writer with raw appended data.
#include "io/vtu_writer.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <set>
#include <sstream>
#include <type_traits>

#include "core/error.h"

namespace seaspring::io {
namespace {

static_assert(sizeof(Vec3d) == 3 * sizeof(double) && std::is_standard_layout_v<Vec3d>,
              "Vec3d must be 3 contiguous doubles");
static_assert(sizeof(Vec3f) == 3 * sizeof(float) && std::is_standard_layout_v<Vec3f>,
              "Vec3f must be 3 contiguous floats");

constexpr std::uint8_t kVtkVertex = 1;
constexpr std::size_t kGeneratedChunk = std::size_t(1) << 20;  ///< values per generated write

/// Where an array is declared in the XML.
enum class Section { PointData, Points, Cells };
/// Arrays computed while writing instead of read from memory.
enum class Generated { None, Connectivity, Offsets, CellTypes };

struct Block {
    Section section;
    std::string vtk_type;  ///< "UInt32", "Float64", ...
    std::string name;
    int components;
    std::uint64_t bytes;
    const void* data;      ///< null for generated arrays
    Generated generated;
};

[[noreturn]] void fail(const std::string& path, const std::string& message) {
    throw Error(formatLocation(path, 0, message));
}

bool hostIsLittleEndian() {
    const std::uint16_t probe = 1;
    unsigned char first = 0;
    std::memcpy(&first, &probe, 1);
    return first == 1;
}

void checkName(const std::string& path, const std::string& name, std::set<std::string>& used) {
    if (name.empty()) fail(path, "VTU extra array with an empty name");
    for (const char ch : name)
        if (std::strchr("&<>\"'", ch) != nullptr || static_cast<unsigned char>(ch) < 0x20)
            fail(path, "VTU extra array name '" + name +
                           "' contains a character not allowed here (& < > \" ' or a control character)");
    if (!used.insert(name).second) fail(path, "VTU array name '" + name + "' is used twice");
}

std::vector<Block> collectBlocks(const std::string& path, const ParticleSet& p,
                                 const std::vector<VtuExtraArray>& extra) {
    const std::uint64_t n = p.size();
    const auto check = [&](const char* name, std::size_t size) {
        if (size != n)
            fail(path, std::string("particle array ") + name + " has " + std::to_string(size) +
                           " entries, expected " + std::to_string(n) + " (size of id)");
    };
    check("type", p.type.size());
    check("mk", p.mk.size());
    check("pos", p.pos.size());
    check("vel", p.vel.size());
    check("rhop", p.rhop.size());
    check("mass", p.mass.size());

    std::vector<Block> blocks = {
        {Section::PointData, "UInt32", "id", 1, n * 4, p.id.data(), Generated::None},
        {Section::PointData, "UInt8", "type", 1, n, p.type.data(), Generated::None},
        {Section::PointData, "UInt16", "mk", 1, n * 2, p.mk.data(), Generated::None},
        {Section::PointData, "Float32", "vel", 3, n * 12, p.vel.data(), Generated::None},
        {Section::PointData, "Float32", "rhop", 1, n * 4, p.rhop.data(), Generated::None},
        {Section::PointData, "Float32", "mass", 1, n * 4, p.mass.data(), Generated::None},
    };
    std::set<std::string> used;
    for (const Block& b : blocks) used.insert(b.name);
    for (const VtuExtraArray& e : extra) {
        checkName(path, e.name, used);
        std::size_t size = 0;
        if (const auto* f = std::get_if<std::vector<float>>(&e.values)) {
            size = f->size();
            blocks.push_back({Section::PointData, "Float32", e.name, 1, n * 4, f->data(), Generated::None});
        } else {
            const auto& u = std::get<std::vector<std::uint8_t>>(e.values);
            size = u.size();
            blocks.push_back({Section::PointData, "UInt8", e.name, 1, n, u.data(), Generated::None});
        }
        if (size != n)
            fail(path, "VTU extra array '" + e.name + "' has " + std::to_string(size) +
                           " values, expected one per particle (" + std::to_string(n) + ")");
    }
    blocks.push_back({Section::Points, "Float64", "Points", 3, n * 24, p.pos.data(), Generated::None});
    const bool wide = n > std::uint64_t(std::numeric_limits<std::int32_t>::max());
    const std::string index_type = wide ? "Int64" : "Int32";
    const std::uint64_t index_bytes = wide ? 8 : 4;
    blocks.push_back({Section::Cells, index_type, "connectivity", 1, n * index_bytes, nullptr,
                      Generated::Connectivity});
    blocks.push_back({Section::Cells, index_type, "offsets", 1, n * index_bytes, nullptr, Generated::Offsets});
    blocks.push_back({Section::Cells, "UInt8", "types", 1, n, nullptr, Generated::CellTypes});
    return blocks;
}

std::string headerXml(std::uint64_t n, const std::vector<Block>& blocks) {
    std::ostringstream os;
    os << "<?xml version=\"1.0\"?>\n"
       << "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\""
       << (hostIsLittleEndian() ? "LittleEndian" : "BigEndian") << "\" header_type=\"UInt64\">\n"
       << "  <UnstructuredGrid>\n"
       << "    <Piece NumberOfPoints=\"" << n << "\" NumberOfCells=\"" << n << "\">\n";
    const char* tags[] = {"PointData", "Points", "Cells"};
    std::uint64_t offset = 0;
    for (int s = 0; s < 3; ++s) {
        os << "      <" << tags[s] << ">\n";
        for (const Block& b : blocks) {
            if (static_cast<int>(b.section) != s) continue;
            os << "        <DataArray type=\"" << b.vtk_type << "\" Name=\"" << b.name << "\"";
            if (b.components != 1) os << " NumberOfComponents=\"" << b.components << "\"";
            os << " format=\"appended\" offset=\"" << offset << "\"/>\n";
            offset += sizeof(std::uint64_t) + b.bytes;
        }
        os << "      </" << tags[s] << ">\n";
    }
    os << "    </Piece>\n"
       << "  </UnstructuredGrid>\n"
       << "  <AppendedData encoding=\"raw\">\n"
       << "_";
    return os.str();
}

using FilePtr = std::unique_ptr<std::FILE, int (*)(std::FILE*)>;

class RawWriter {
public:
    RawWriter(const std::string& tmp, const std::string& path)
        : file_(std::fopen(tmp.c_str(), "wb"), &std::fclose), path_(path) {
        if (!file_) fail(path_, "cannot create " + tmp + ": " + std::strerror(errno));
    }

    void write(const void* data, std::size_t bytes) {
        if (bytes == 0) return;
        if (std::fwrite(data, 1, bytes, file_.get()) != bytes)
            fail(path_, std::string("cannot write: ") + std::strerror(errno));
    }

    template <typename Index>
    void writeGenerated(Generated g, std::uint64_t n) {
        std::vector<Index> index;
        std::vector<std::uint8_t> types;
        for (std::uint64_t start = 0; start < n; start += kGeneratedChunk) {
            const std::size_t count = static_cast<std::size_t>(std::min<std::uint64_t>(kGeneratedChunk, n - start));
            if (g == Generated::CellTypes) {
                types.assign(count, kVtkVertex);
                write(types.data(), count);
                continue;
            }
            index.resize(count);
            const std::uint64_t first = g == Generated::Offsets ? start + 1 : start;
            for (std::size_t k = 0; k < count; ++k) index[k] = static_cast<Index>(first + k);
            write(index.data(), count * sizeof(Index));
        }
    }

    void close() {
        std::FILE* f = file_.release();
        if (std::fclose(f) != 0) fail(path_, std::string("cannot close: ") + std::strerror(errno));
    }

private:
    FilePtr file_;
    std::string path_;
};

void writeFile(const std::string& tmp, const std::string& path, std::uint64_t n,
               const std::vector<Block>& blocks) {
    RawWriter out(tmp, path);
    const std::string header = headerXml(n, blocks);
    out.write(header.data(), header.size());
    for (const Block& b : blocks) {
        out.write(&b.bytes, sizeof(b.bytes));
        if (b.generated == Generated::None) {
            out.write(b.data, b.bytes);
        } else if (b.vtk_type == "Int64") {
            out.writeGenerated<std::int64_t>(b.generated, n);
        } else {
            out.writeGenerated<std::int32_t>(b.generated, n);
        }
    }
    const std::string footer = "\n  </AppendedData>\n</VTKFile>\n";
    out.write(footer.data(), footer.size());
    out.close();
}

}  // namespace

void writeParticlesVtu(const std::string& path, const ParticleSet& p,
                       const std::vector<VtuExtraArray>& extra) {
    const std::vector<Block> blocks = collectBlocks(path, p, extra);
    const std::string tmp = path + ".tmp";
    try {
        writeFile(tmp, path, p.size(), blocks);
        if (std::rename(tmp.c_str(), path.c_str()) != 0)
            fail(path, "cannot rename " + tmp + " to it: " + std::strerror(errno));
    } catch (...) {
        std::remove(tmp.c_str());
        throw;
    }
}

}  // namespace seaspring::io
