// SeaSpring — MIT licence.
/// \file part_output.cpp
#include "io/part_output.h"

#include <cstdio>
#include <filesystem>

#include "core/error.h"
#include "io/h5_util.h"

namespace seaspring::io {

namespace fs = std::filesystem;

std::string writePartH5(const std::string& outdir, const PartFrame& f) {
    char name[64];
    std::snprintf(name, sizeof name, "part_%04d.h5", f.index);
    const fs::path dir = fs::path(outdir) / "data";
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) throw Error(dir.string() + ": cannot create the output folder: " + ec.message());
    const fs::path final_path = dir / name;
    const fs::path tmp = dir / (std::string(name) + ".tmp");
    {
        h5::File file = h5::File::create(tmp.string());
        h5::WriteOptions contiguous;
        contiguous.chunk_rows = ~std::size_t(0);
        h5::writeDataset<double>(file, "pos", f.pos, f.np, 3, contiguous);
        h5::writeDataset<float>(file, "vel", f.vel, f.np, 3, contiguous);
        h5::writeDataset<float>(file, "rhop", f.rhop, f.np, 1, contiguous);
        h5::writeDataset<float>(file, "press", f.press, f.np, 1, contiguous);
        h5::writeDataset<std::uint32_t>(file, "id", f.id, f.np, 1, contiguous);
        h5::writeDataset<std::uint8_t>(file, "type", f.type, f.np, 1, contiguous);
        h5::writeDataset<std::uint16_t>(file, "mk", f.mk, f.np, 1, contiguous);
        h5::writeDataset<std::uint8_t>(file, "excluded", f.excluded, f.np, 1, contiguous);
        h5::writeDoubleAttribute(file, "time", f.time);
        h5::writeInt64Attribute(file, "step", f.step);
        h5::writeInt64Attribute(file, "np", std::int64_t(f.np));
        h5::writeStringAttribute(file, "format", "SeaSpring part");
        h5::writeInt64Attribute(file, "format_version", 1);
        file.close();
    }
    fs::rename(tmp, final_path, ec);
    if (ec) throw Error(final_path.string() + ": cannot write: " + ec.message());
    return "data/" + std::string(name);
}

PartData readPartH5(const std::string& path) {
    h5::File file = h5::File::openReadOnly(path);
    PartData d;
    d.time = h5::readDoubleAttribute(file, "time");
    d.step = h5::readInt64Attribute(file, "step");
    const std::size_t np = std::size_t(h5::readInt64Attribute(file, "np"));
    d.pos.resize(3 * np);
    d.vel.resize(3 * np);
    h5::readDatasetInto<double>(file, "pos", d.pos.data(), np, 3);
    h5::readDatasetInto<float>(file, "vel", d.vel.data(), np, 3);
    d.rhop = h5::readDataset<float>(file, "rhop");
    d.press = h5::readDataset<float>(file, "press");
    d.id = h5::readDataset<std::uint32_t>(file, "id");
    d.type = h5::readDataset<std::uint8_t>(file, "type");
    d.mk = h5::readDataset<std::uint16_t>(file, "mk");
    d.excluded = h5::readDataset<std::uint8_t>(file, "excluded");
    for (std::size_t n : {d.rhop.size(), d.press.size(), d.id.size(), d.type.size(), d.mk.size(), d.excluded.size()})
        if (n != np) throw Error(path + ": a dataset has " + std::to_string(n) + " rows, np is " + std::to_string(np));
    return d;
}

}  // namespace seaspring::io
