// SeaSpring — MIT licence.
/// \file vti_writer.cpp
/// \brief VTK XML ImageData writer (see vti_writer.h).
#include "io/vti_writer.h"

#include <cctype>
#include <cstdint>
#include <cstdio>
#include <filesystem>

#include "core/error.h"

namespace seaspring::io {

void writeImageVti(const std::string& path, const ImageGrid& g, const std::vector<VtiArray>& arrays) {
    for (int a = 0; a < 3; ++a)
        if (g.dims[a] < 1 || !(g.spacing[a] > 0))
            throw Error(path + ": bad image grid (nodes " + std::to_string(g.dims[a]) + ", spacing " +
                        std::to_string(g.spacing[a]) + " along axis " + std::to_string(a) + ")");
    const std::size_t n = g.nodes();
    for (const VtiArray& v : arrays) {
        if (v.values.size() != n)
            throw Error(path + ": array " + v.name + " has " + std::to_string(v.values.size()) + " values for " +
                        std::to_string(n) + " nodes");
        bool ok = !v.name.empty();
        for (char ch : v.name) ok = ok && (std::isalnum(static_cast<unsigned char>(ch)) || ch == '_' || ch == '.');
        if (!ok) throw Error(path + ": bad array name '" + v.name + "'");
    }
    const std::string tmp = path + ".tmp";
    std::FILE* f = std::fopen(tmp.c_str(), "wb");
    if (!f) throw Error(path + ": cannot write the file");
    const std::uint16_t probe = 1;
    const bool little = *reinterpret_cast<const std::uint8_t*>(&probe) == 1;
    char extent[128], geo[256];
    std::snprintf(extent, sizeof extent, "0 %d 0 %d 0 %d", g.dims[0] - 1, g.dims[1] - 1, g.dims[2] - 1);
    std::snprintf(geo, sizeof geo, "Origin=\"%.17g %.17g %.17g\" Spacing=\"%.17g %.17g %.17g\"", g.origin[0], g.origin[1],
                  g.origin[2], g.spacing[0], g.spacing[1], g.spacing[2]);
    std::fprintf(f,
                 "<?xml version=\"1.0\"?>\n<VTKFile type=\"ImageData\" version=\"1.0\" byte_order=\"%s\" "
                 "header_type=\"UInt64\">\n  <ImageData WholeExtent=\"%s\" %s>\n    <Piece Extent=\"%s\">\n"
                 "      <PointData>\n",
                 little ? "LittleEndian" : "BigEndian", extent, geo, extent);
    std::uint64_t offset = 0;
    for (const VtiArray& v : arrays) {
        std::fprintf(f, "        <DataArray type=\"Float32\" Name=\"%s\" format=\"appended\" offset=\"%llu\" />\n",
                     v.name.c_str(), static_cast<unsigned long long>(offset));
        offset += sizeof(std::uint64_t) + n * sizeof(float);
    }
    std::fprintf(f, "      </PointData>\n    </Piece>\n  </ImageData>\n  <AppendedData encoding=\"raw\">\n   _");
    for (const VtiArray& v : arrays) {
        const std::uint64_t bytes = n * sizeof(float);
        std::fwrite(&bytes, sizeof bytes, 1, f);
        std::fwrite(v.values.data(), sizeof(float), n, f);
    }
    std::fprintf(f, "\n  </AppendedData>\n</VTKFile>\n");
    const bool ok = std::ferror(f) == 0;
    if (std::fclose(f) != 0 || !ok) {
        std::error_code ec;
        std::filesystem::remove(tmp, ec);
        throw Error(path + ": write failed");
    }
    std::error_code ec;
    std::filesystem::rename(tmp, path, ec);
    if (ec) {
        std::filesystem::remove(tmp, ec);
        throw Error(path + ": cannot rename " + tmp);
    }
}

}  // namespace seaspring::io
