// SeaSpring — MIT licence.
/// \file part_output.cpp
/// \brief Writing and reading the per-output particle files data/part_NNNN.h5.
#include "io/part_output.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>

#include "core/error.h"
#include "io/h5_util.h"

namespace seaspring::io {
namespace {

namespace fs = std::filesystem;

/// Creates `path` empty (truncating) to learn, with errno's words, whether it can be
/// written at all; HDF5's own message for that case does not say why.
void probeWritable(const std::string& path) {
    std::FILE* file = std::fopen(path.c_str(), "wb");
    if (file == nullptr)
        throw Error(formatLocation(path, 0, std::string("cannot create the part file: ") +
                                                std::strerror(errno)));
    std::fclose(file);
}

void writeContents(const std::string& path, const PartFrame& f) {
    // Never chunk: every dataset has at most np rows, so this row limit keeps them contiguous.
    h5::WriteOptions contiguous;
    contiguous.chunk_rows = std::numeric_limits<std::size_t>::max();
    contiguous.deflate_level = 0;
    h5::File file = h5::File::create(path);
    h5::writeDataset<double>(file, "pos", f.pos, f.np, 3, contiguous);
    h5::writeDataset<float>(file, "vel", f.vel, f.np, 3, contiguous);
    h5::writeDataset<float>(file, "rhop", f.rhop, f.np, 1, contiguous);
    h5::writeDataset<float>(file, "press", f.press, f.np, 1, contiguous);
    h5::writeDataset<std::uint32_t>(file, "id", f.id, f.np, 1, contiguous);
    h5::writeDataset<std::uint8_t>(file, "type", f.type, f.np, 1, contiguous);
    h5::writeDataset<std::uint16_t>(file, "mk", f.mk, f.np, 1, contiguous);
    h5::writeDataset<std::uint8_t>(file, "excluded", f.excluded, f.np, 1, contiguous);
    h5::writeDataset<float>(file, "mass", f.mass, f.np, 1, contiguous);
    if (f.disp) {
        h5::writeDataset<float>(file, "disp", f.disp, f.np, 3, contiguous);
        h5::writeDataset<float>(file, "strain", f.strain, f.np, 1, contiguous);
        h5::writeDataset<std::uint8_t>(file, "broken", f.broken, f.np, 1, contiguous);
        h5::writeDataset<float>(file, "damage", f.damage, f.np, 1, contiguous);
    }
    h5::writeDoubleAttribute(file, "time", f.time);
    h5::writeInt64Attribute(file, "step", f.step);
    h5::writeInt64Attribute(file, "np", static_cast<std::int64_t>(f.np));
    h5::writeStringAttribute(file, "format", kPartFormat);
    h5::writeInt64Attribute(file, "format_version", kPartFormatVersion);
    h5::writeDoubleAttribute(file, "h", f.constants.h);
    h5::writeDoubleAttribute(file, "dp", f.constants.dp);
    h5::writeStringAttribute(file, "kernel", f.constants.kernel);
    h5::writeDoubleAttribute(file, "rhop0", f.constants.rhop0);
    h5::writeInt64Attribute(file, "dimension", f.constants.dimension);
    h5::writeDoubleAttribute(file, "b", f.constants.b);
    file.close();
}

}  // namespace

std::string partFileName(int index) {
    if (index < 0)
        throw Error("part file index " + std::to_string(index) + " is negative");
    char name[32];
    std::snprintf(name, sizeof name, "data/part_%04d.h5", index);
    return name;
}

std::string writePartH5(const std::string& outdir, const PartFrame& f) {
    const std::string relative = partFileName(f.index);
    const fs::path final_path = fs::path(outdir) / relative;
    const fs::path dir = final_path.parent_path();
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec)
        throw Error(formatLocation(dir.string(), 0,
                                   "cannot create the output folder: " + ec.message()));
    const std::string tmp = final_path.string() + ".tmp";
    try {
        probeWritable(tmp);
        writeContents(tmp, f);
    } catch (...) {
        fs::remove(tmp, ec);
        throw;
    }
    fs::rename(tmp, final_path, ec);
    if (ec) {
        std::error_code ignored;
        fs::remove(tmp, ignored);
        throw Error(formatLocation(final_path.string(), 0,
                                   "cannot rename the finished part file into place: " +
                                       ec.message()));
    }
    return relative;
}

PartData readPartH5(const std::string& path) {
    h5::File file = h5::File::openReadOnly(path);
    const std::string format = h5::readStringAttribute(file, "format");
    if (format != kPartFormat)
        file.fail("attribute 'format' of /",
                  "is \"" + format + "\", expected \"" + kPartFormat + "\"");
    const std::int64_t version = h5::readInt64Attribute(file, "format_version");
    if (version != 1 && version != kPartFormatVersion)
        file.fail("attribute 'format_version' of /",
                  "is " + std::to_string(version) + ", this code reads versions 1 to " +
                      std::to_string(kPartFormatVersion));
    const std::int64_t np_attr = h5::readInt64Attribute(file, "np");
    if (np_attr < 0) file.fail("attribute 'np' of /", "is negative: " + std::to_string(np_attr));
    const auto np = static_cast<std::size_t>(np_attr);

    PartData d;
    d.time = h5::readDoubleAttribute(file, "time");
    d.step = h5::readInt64Attribute(file, "step");
    d.pos.resize(3 * np);
    d.vel.resize(3 * np);
    d.rhop.resize(np);
    d.press.resize(np);
    d.id.resize(np);
    d.type.resize(np);
    d.mk.resize(np);
    d.excluded.resize(np);
    // readDatasetInto checks each dataset's element type and its exact shape against np.
    h5::readDatasetInto<double>(file, "pos", d.pos.data(), np, 3);
    h5::readDatasetInto<float>(file, "vel", d.vel.data(), np, 3);
    h5::readDatasetInto<float>(file, "rhop", d.rhop.data(), np, 1);
    h5::readDatasetInto<float>(file, "press", d.press.data(), np, 1);
    h5::readDatasetInto<std::uint32_t>(file, "id", d.id.data(), np, 1);
    h5::readDatasetInto<std::uint8_t>(file, "type", d.type.data(), np, 1);
    h5::readDatasetInto<std::uint16_t>(file, "mk", d.mk.data(), np, 1);
    h5::readDatasetInto<std::uint8_t>(file, "excluded", d.excluded.data(), np, 1);
    if (version >= 2) {
        d.mass.resize(np);
        h5::readDatasetInto<float>(file, "mass", d.mass.data(), np, 1);
        d.constants.h = h5::readDoubleAttribute(file, "h");
        d.constants.dp = h5::readDoubleAttribute(file, "dp");
        d.constants.kernel = h5::readStringAttribute(file, "kernel");
        d.constants.rhop0 = h5::readDoubleAttribute(file, "rhop0");
        d.constants.dimension = int(h5::readInt64Attribute(file, "dimension"));
        d.constants.b = h5::readDoubleAttribute(file, "b");
    }
    if (file.hasChild("disp")) {
        d.disp.resize(3 * np);
        d.strain.resize(np);
        d.broken.resize(np);
        d.damage.resize(np);
        h5::readDatasetInto<float>(file, "disp", d.disp.data(), np, 3);
        h5::readDatasetInto<float>(file, "strain", d.strain.data(), np, 1);
        h5::readDatasetInto<std::uint8_t>(file, "broken", d.broken.data(), np, 1);
        h5::readDatasetInto<float>(file, "damage", d.damage.data(), np, 1);
    }
    return d;
}

}  // namespace seaspring::io
