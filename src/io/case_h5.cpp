// SeaSpring — MIT licence.
/// \file case_h5.cpp
/// \brief Writing and reading the HDF5 case file, with its consistency checks.
#include "io/case_h5.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <type_traits>

#include "core/error.h"
#include "io/h5_util.h"

namespace seaspring::io {
namespace {

static_assert(sizeof(Vec3d) == 3 * sizeof(double) && std::is_standard_layout_v<Vec3d>,
              "Vec3d must be 3 contiguous doubles to be written as N x 3");
static_assert(sizeof(Vec3f) == 3 * sizeof(float) && std::is_standard_layout_v<Vec3f>,
              "Vec3f must be 3 contiguous floats to be written as N x 3");
static_assert(sizeof(ParticleType) == 1, "ParticleType is stored as uint8");

/// Flags a BondKind value may hold.
constexpr std::uint8_t kBondKindMask = BondSecond | BondClampFlag;

/// Checks a header, particle set and (optional) bond network against each other.
/// Throws Error "FILE: PREFIX<what is wrong>".
class CaseChecker {
public:
    CaseChecker(const std::string& file, const std::string& prefix) : file_(file), prefix_(prefix) {}

    void check(const CaseFileHeader& h, const ParticleSet& p, const BondNetwork* b) const {
        if (h.dimensions != 2 && h.dimensions != 3)
            fail("dimensions = ", h.dimensions, ", expected 2 or 3");
        if (!(h.dp > 0.0) || !std::isfinite(h.dp)) fail("dp = ", h.dp, ", expected a positive number");
        if (h.np != p.size())
            fail("np = ", h.np, " but /particles/id has ", p.size(), " entries");
        if (h.np > std::numeric_limits<std::uint32_t>::max())
            fail("np = ", h.np, " exceeds the uint32 particle id range");
        checkLength("/particles/type", p.type.size(), h.np);
        checkLength("/particles/mk", p.mk.size(), h.np);
        checkLength("/particles/pos", p.pos.size(), h.np);
        checkLength("/particles/vel", p.vel.size(), h.np);
        checkLength("/particles/rhop", p.rhop.size(), h.np);
        checkLength("/particles/mass", p.mass.size(), h.np);
        std::size_t solids = 0;
        for (std::size_t i = 0; i < p.size(); ++i) {
            const auto t = static_cast<unsigned>(p.type[i]);
            if (t > static_cast<unsigned>(ParticleType::Fluid))
                fail("/particles/type[", i, "] = ", t, " is not a particle type (0..3)");
            if (p.type[i] == ParticleType::Solid) ++solids;
        }
        checkNormals(p);
        if (b == nullptr) {
            if (solids > 0) fail(solids, " particles are of type solid but there is no /bonds group");
            return;
        }
        checkBonds(*b, p, solids);
    }

private:
    template <typename... Args>
    [[noreturn]] void fail(Args&&... args) const {
        throw Error(formatLocation(file_, 0, prefix_ + detail::concat(std::forward<Args>(args)...)));
    }

    void checkLength(const char* name, std::size_t n, std::uint64_t np) const {
        if (n != np) fail(name, " has ", n, " entries, expected np = ", np);
    }

    void checkNormals(const ParticleSet& p) const {
        if (p.normal.empty()) return;
        const std::size_t nbound = p.boundaryCount();
        if (p.normal.size() != nbound)
            fail("/particles/normal has ", p.normal.size(), " entries, expected one per non-fluid particle (",
                 nbound, ")");
        for (std::size_t i = 0; i < nbound; ++i)
            if (p.type[i] == ParticleType::Fluid)
                fail("/particles/normal: particle ", i, " is fluid, but the ", nbound,
                     " non-fluid particles must come first (ids 0..", nbound - 1, ")");
        for (std::size_t i = 0; i < nbound; ++i) {
            const Vec3f n = p.normal[i];
            if (!std::isfinite(n.x) || !std::isfinite(n.y) || !std::isfinite(n.z))
                fail("/particles/normal[", i, "] = (", n.x, ", ", n.y, ", ", n.z, ") is not finite");
        }
    }

    void checkBonds(const BondNetwork& b, const ParticleSet& p, std::size_t solids) const {
        if (b.offset.empty()) fail("/bonds/offset is empty, expected n_solid + 1 entries");
        const std::size_t n_solid = b.solidCount();
        const std::size_t slots = b.neighbour.size();
        if (b.first_solid + std::uint64_t(n_solid) > p.size())
            fail("/bonds rows cover particles ", b.first_solid, "..", b.first_solid + std::uint64_t(n_solid),
                 " (first_solid + n_solid) but np = ", p.size());
        if (n_solid != solids)
            fail("/bonds has ", n_solid, " rows but there are ", solids, " solid particles");
        for (std::size_t r = 0; r < n_solid; ++r) {
            const std::size_t i = b.first_solid + r;
            if (p.type[i] != ParticleType::Solid)
                fail("/bonds row ", r, " belongs to particle ", i, " of type ",
                     particleTypeName(p.type[i]), ", expected solid (first_solid = ", b.first_solid, ")");
        }
        if (b.offset[0] != 0) fail("/bonds/offset[0] = ", b.offset[0], ", expected 0");
        for (std::size_t r = 0; r < n_solid; ++r)
            if (b.offset[r + 1] < b.offset[r])
                fail("/bonds/offset[", r + 1, "] = ", b.offset[r + 1], " is less than /bonds/offset[", r,
                     "] = ", b.offset[r], " (offsets must not decrease)");
        if (b.offset.back() != slots)
            fail("/bonds/offset[", n_solid, "] = ", b.offset.back(), ", expected the slot count ", slots,
                 " (length of /bonds/neighbour)");
        if (b.rest_length.size() != slots)
            fail("/bonds/rest_length has ", b.rest_length.size(), " entries, expected ", slots);
        if (b.kind.size() != slots) fail("/bonds/kind has ", b.kind.size(), " entries, expected ", slots);
        for (std::size_t k = 0; k < slots; ++k) {
            if (b.neighbour[k] >= p.size())
                fail("/bonds/neighbour[", k, "] = ", b.neighbour[k], " is not a particle id (np = ", p.size(), ")");
            if ((b.kind[k] & ~kBondKindMask) != 0)
                fail("/bonds/kind[", k, "] = ", unsigned(b.kind[k]), " is not a combination of BondKind flags (0..3)");
            if (!(b.rest_length[k] > 0.0) || !std::isfinite(b.rest_length[k]))
                fail("/bonds/rest_length[", k, "] = ", b.rest_length[k], ", expected a positive length");
        }
    }

    std::string file_;
    std::string prefix_;
};

/// Root attribute holding an int64 that must fit `lo..hi`.
std::int64_t readBoundedInt(const h5::Location& loc, const std::string& name, std::int64_t lo,
                            std::int64_t hi) {
    const std::int64_t v = h5::readInt64Attribute(loc, name);
    if (v < lo || v > hi)
        loc.fail("attribute '" + name + "' of " + loc.path(),
                 "value " + std::to_string(v) + " is outside " + std::to_string(lo) + ".." + std::to_string(hi));
    return v;
}

void writeFile(const std::string& tmp, const CaseFileHeader& h, const ParticleSet& p,
               const BondNetwork* bonds) {
    const std::size_t n = p.size();
    h5::File file = h5::File::create(tmp);
    h5::writeStringAttribute(file, "format", kCaseFormat);
    h5::writeInt64Attribute(file, "format_version", kCaseFormatVersion);
    h5::writeStringAttribute(file, "case_name", h.case_name);
    h5::writeInt64Attribute(file, "dimensions", h.dimensions);
    h5::writeDoubleAttribute(file, "dp", h.dp);
    h5::writeInt64Attribute(file, "np", static_cast<std::int64_t>(h.np));
    h5::writeStringAttribute(file, "generator", h.generator);
    {
        const h5::Location g = file.createGroup("particles");
        h5::writeDataset(g, "id", p.id);
        h5::writeDataset(g, "type", reinterpret_cast<const std::uint8_t*>(p.type.data()), n);
        h5::writeDataset(g, "mk", p.mk);
        h5::writeDataset(g, "pos", reinterpret_cast<const double*>(p.pos.data()), n, 3);
        h5::writeDataset(g, "vel", reinterpret_cast<const float*>(p.vel.data()), n, 3);
        h5::writeDataset(g, "rhop", p.rhop);
        h5::writeDataset(g, "mass", p.mass);
        if (!p.normal.empty())
            h5::writeDataset(g, "normal", reinterpret_cast<const float*>(p.normal.data()), p.normal.size(), 3);
    }
    if (bonds != nullptr) {
        const h5::Location g = file.createGroup("bonds");
        h5::writeInt64Attribute(g, "first_solid", bonds->first_solid);
        h5::writeDataset(g, "offset", bonds->offset);
        h5::writeDataset(g, "neighbour", bonds->neighbour);
        h5::writeDataset(g, "rest_length", bonds->rest_length);
        h5::writeDataset(g, "kind", bonds->kind);
    }
    file.close();
}

}  // namespace

void writeCaseH5(const std::string& path, const CaseFileHeader& header, const ParticleSet& p,
                 const BondNetwork* bonds) {
    CaseChecker(path, "cannot write case file: ").check(header, p, bonds);
    const std::string tmp = path + ".tmp";
    try {
        writeFile(tmp, header, p, bonds);
        if (std::rename(tmp.c_str(), path.c_str()) != 0)
            throw Error(formatLocation(path, 0, "cannot rename " + tmp + " to it: " + std::strerror(errno)));
    } catch (...) {
        std::remove(tmp.c_str());
        throw;
    }
}

CaseFileContents readCaseH5(const std::string& path) {
    const h5::File file = h5::File::openReadOnly(path);
    const std::string format = h5::readStringAttribute(file, "format");
    if (format != kCaseFormat)
        file.fail("attribute 'format' of /", "is '" + format + "', expected '" + kCaseFormat + "'");
    const std::int64_t version = h5::readInt64Attribute(file, "format_version");
    if (version != kCaseFormatVersion)
        file.fail("attribute 'format_version' of /", "is " + std::to_string(version) +
                                                         ", this build reads version " +
                                                         std::to_string(kCaseFormatVersion));
    CaseFileContents c;
    CaseFileHeader& h = c.header;
    h.case_name = h5::readStringAttribute(file, "case_name");
    h.dimensions = static_cast<int>(readBoundedInt(file, "dimensions", 2, 3));
    h.dp = h5::readDoubleAttribute(file, "dp");
    h.np = static_cast<std::uint64_t>(
        readBoundedInt(file, "np", 0, std::numeric_limits<std::uint32_t>::max()));
    h.generator = h5::readStringAttribute(file, "generator");

    const std::size_t n = h.np;
    ParticleSet& p = c.particles;
    {
        const h5::Location g = file.openGroup("particles");
        // Check np against the stored length before allocating np entries.
        const h5::DatasetShape ids = h5::datasetShape(g, "id");
        if (ids.rows != n)
            g.fail("dataset /particles/id", "has " + std::to_string(ids.rows) +
                                                " rows but attribute 'np' of / is " + std::to_string(n));
        p.resize(n);
        h5::readDatasetInto(g, "id", p.id.data(), n);
        h5::readDatasetInto(g, "type", reinterpret_cast<std::uint8_t*>(p.type.data()), n);
        h5::readDatasetInto(g, "mk", p.mk.data(), n);
        h5::readDatasetInto(g, "pos", reinterpret_cast<double*>(p.pos.data()), n, 3);
        h5::readDatasetInto(g, "vel", reinterpret_cast<float*>(p.vel.data()), n, 3);
        h5::readDatasetInto(g, "rhop", p.rhop.data(), n);
        h5::readDatasetInto(g, "mass", p.mass.data(), n);
        if (g.hasChild("normal")) {
            // Checked against the non-fluid count by CaseChecker; the stored rows bound the allocation.
            const h5::DatasetShape ns = h5::datasetShape(g, "normal");
            if (ns.rank != 2 || ns.cols != 3)
                g.fail("dataset /particles/normal", "has shape " + std::to_string(ns.rows) + " x " +
                                                        std::to_string(ns.cols) + ", expected nbound x 3");
            if (ns.rows == 0)
                g.fail("dataset /particles/normal", "has no rows (a case without normals has no such dataset)");
            if (ns.rows > n)
                g.fail("dataset /particles/normal",
                       "has " + std::to_string(ns.rows) + " rows, more than the np = " + std::to_string(n) + " particles");
            p.normal.resize(ns.rows);
            h5::readDatasetInto(g, "normal", reinterpret_cast<float*>(p.normal.data()), ns.rows, 3);
        }
    }
    c.has_bonds = file.hasChild("bonds");
    if (c.has_bonds) {
        const h5::Location g = file.openGroup("bonds");
        BondNetwork& b = c.bonds;
        b.first_solid = static_cast<std::uint32_t>(
            readBoundedInt(g, "first_solid", 0, std::numeric_limits<std::uint32_t>::max()));
        b.offset = h5::readDataset<std::uint32_t>(g, "offset");
        b.neighbour = h5::readDataset<std::uint32_t>(g, "neighbour");
        const std::size_t slots = b.neighbour.size();
        b.rest_length.resize(slots);
        b.kind.resize(slots);
        h5::readDatasetInto(g, "rest_length", b.rest_length.data(), slots);
        h5::readDatasetInto(g, "kind", b.kind.data(), slots);
    }
    CaseChecker(path, "").check(h, p, c.has_bonds ? &c.bonds : nullptr);
    return c;
}

}  // namespace seaspring::io
