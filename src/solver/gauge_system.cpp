// SeaSpring — MIT licence.
/// \file gauge_system.cpp
/// \brief The gauges during a run (see gauge_system.h).
#include "solver/gauge_system.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <ostream>

#include "core/error.h"
#include "io/checkpoint_file.h"
#include "physics/gauges.h"

namespace seaspring::solver {

namespace fs = std::filesystem;
using model::GaugeKind;
using model::GaugeSpec;

namespace {
constexpr double kNever = 1e300;

/// The next multiple of `dt` strictly after `t` (DualSPHysics' OutputNext rule); t itself
/// for dt = 0 (every step).
double nextMultiple(double t, double dt) {
    if (dt <= 0) return t;
    double n = dt * std::floor(t / dt);
    if (n <= t) n = dt * (std::floor(t / dt) + 1.0);
    return n;
}

const char* fileKind(GaugeKind k) {
    switch (k) {
        case GaugeKind::Velocity: return "Vel";
        case GaugeKind::Pressure: return "Press";
        case GaugeKind::Swl: return "Swl";
        case GaugeKind::MaxZ: return "MaxZ";
        case GaugeKind::Force: return "Force";
        case GaugeKind::SolidMarker: return "Marker";
    }
    return "?";
}

const char* header(GaugeKind k) {
    switch (k) {
        case GaugeKind::Velocity: return "time;velx;vely;velz;posx;posy;posz;wsum";
        case GaugeKind::Pressure: return "time;press;posx;posy;posz;wsum";
        case GaugeKind::Swl: return "time;swlx;swly;swlz;pos0x;pos0y;pos0z;pos2x;pos2y;pos2z";
        case GaugeKind::MaxZ: return "time;zmax;posx;posy;posz";
        case GaugeKind::Force: return "time;forcex;forcey;forcez";
        case GaugeKind::SolidMarker: return "time;posx;posy;posz;dispx;dispy;dispz";
    }
    return "";
}

}  // namespace

struct GaugeSystem::Item {
    GaugeSpec spec;
    double computedt = 0, cstart = 0, cend = kNever;
    bool output = false;
    double outputdt = 0, ostart = 0, oend = kNever;
    double next_compute = 0, next_output = 0;
    std::uint32_t first = 0, count = 0;  ///< points, maxz rows or ids of the query
    physics::Double3 point0{0, 0, 0}, dir{0, 0, 0};
    double masslimit = 0;
    std::vector<std::uint32_t> force_ids;  ///< boundary ids of the force target, ascending
    physics::Double3 pos0{0, 0, 0};         ///< marker: initial position
    std::FILE* file = nullptr;
};

GaugeSystem::GaugeSystem(const SolverCase& c, const std::string& outdir, std::ostream& log,
                         const CheckpointData* resume)
    : massfluid_(c.constants.massfluid), dim_(c.constants.dimensions), domain_minz_(c.domain_min.z) {
    // A restart file of this case has as many gauges, in the same order (its keys are
    // numbered); a file of another case is refused before (Simulation::resume checks the name).
    if (resume && resume->integer("gauges/count") != (long long)c.gauges.gauges.size())
        throw Error(resume->source + ": restart file has " + std::to_string(resume->integer("gauges/count")) +
                    " gauges, the case " + std::to_string(c.gauges.gauges.size()));
    const model::GaugeSet& set = c.gauges;
    const double tout = c.params.time_out;
    auto fail = [&](const GaugeSpec& sp, const std::string& msg) {
        throwInputError(c.xml_path, sp.line, "<" + std::string(model::gaugeElementName(sp.kind)) + " name=\"" +
                                                 sp.name + "\">: " + msg);
    };
    // A point (the backend places it in its cells, gauge_arrays.h); 2D points are moved onto the
    // particles' plane. Points outside the domain measure nothing (zero sums), as DualSPHysics.
    auto addPoint = [&](const Vec3d& p) {
        physics::Double3 d{p.x, dim_ == 2 ? c.domain_min.y : p.y, p.z};
        const bool inside = d.x >= c.domain_min.x && d.x <= c.domain_max.x && d.z >= c.domain_min.z &&
                            d.z <= c.domain_max.z && (dim_ == 2 || (d.y >= c.domain_min.y && d.y <= c.domain_max.y));
        q_.points.push_back(d);
        outside_.push_back(!inside);
    };
    bool any_output = false;
    for (const GaugeSpec& sp : set.gauges) {
        auto it = std::make_unique<Item>();
        Item& item = *it;
        item.spec = sp;
        const model::GaugeTiming &own = sp.timing, &def = set.defaults;
        item.computedt = own.computedt.value_or(def.computedt.value_or(tout));
        item.cstart = own.compute_start.value_or(def.compute_start.value_or(0.0));
        item.cend = own.compute_end.value_or(def.compute_end.value_or(kNever));
        item.output = own.output.value_or(def.output.value_or(false));
        item.outputdt = own.outputdt.value_or(def.outputdt.value_or(0.0));
        item.ostart = own.output_start.value_or(def.output_start.value_or(0.0));
        item.oend = own.output_end.value_or(def.output_end.value_or(kNever));
        item.next_compute = item.cstart;
        item.next_output = item.ostart;
        if (own.savevtkpart.value_or(def.savevtkpart.value_or(false)))
            log << "  note: gauge " << sp.name << ": savevtkpart is not implemented (ignored)\n";
        switch (sp.kind) {
            case GaugeKind::Velocity:
            case GaugeKind::Pressure:
                item.first = std::uint32_t(q_.points.size());
                item.count = 1;
                addPoint(sp.point);
                break;
            case GaugeKind::Swl: {
                const physics::SwlLine line = physics::swlLine(physics::Double3{sp.point0.x, sp.point0.y, sp.point0.z},
                                                               physics::Double3{sp.point2.x, sp.point2.y, sp.point2.z},
                                                               sp.pointdp);
                item.point0 = line.point0;
                item.dir = line.dir;
                item.first = std::uint32_t(q_.points.size());
                item.count = line.count;
                for (std::uint32_t k = 0; k < line.count; ++k) {
                    const physics::Double3 q = line.point(k);
                    addPoint(Vec3d{q.x, q.y, q.z});
                }
                item.masslimit = sp.masslimit ? *sp.masslimit
                                              : sp.masslimit_coef.value_or(physics::swlMassLimitCoef(dim_)) * massfluid_;
                break;
            }
            case GaugeKind::MaxZ: {
                // The box around the column, reach r (the backend searches its cells, gauge_arrays.h).
                const double r = sp.distlimit;
                item.first = std::uint32_t(q_.columns.size());
                item.count = 1;
                q_.columns.push_back(MaxzColumn{physics::Double3{sp.point0.x - r, sp.point0.y - r, sp.point0.z - r},
                                                physics::Double3{sp.point0.x + r, sp.point0.y + r, sp.point0.z + sp.height + r},
                                                sp.point0.x, sp.point0.y, r * r});
                break;
            }
            case GaugeKind::Force: {
                for (const MkBlock& b : c.blocks)
                    if (b.type != ParticleType::Fluid && b.mk_local == sp.target_mkbound)
                        for (std::uint32_t k = 0; k < b.count; ++k) item.force_ids.push_back(b.begin + k);
                if (item.force_ids.empty())
                    fail(sp, "target mkbound=" + std::to_string(sp.target_mkbound) + " has no boundary particles");
                std::sort(item.force_ids.begin(), item.force_ids.end());
                break;
            }
            case GaugeKind::SolidMarker: {
                const ParticleSet& ps = c.particles;
                double best = kNever;
                std::uint32_t best_id = 0;
                for (const MkBlock& b : c.blocks) {
                    if (b.type != ParticleType::Solid || (sp.target_mkbound >= 0 && b.mk_local != sp.target_mkbound)) continue;
                    for (std::uint32_t k = 0; k < b.count; ++k) {
                        const std::uint32_t id = b.begin + k;
                        const Vec3d d = ps.pos[id] - sp.point;
                        const double r2 = d.x * d.x + (dim_ == 3 ? d.y * d.y : 0.0) + d.z * d.z;
                        if (r2 < best || (r2 == best && id < best_id)) {
                            best = r2;
                            best_id = id;
                        }
                    }
                }
                if (best == kNever)
                    fail(sp, sp.target_mkbound >= 0 ? "target mkbound=" + std::to_string(sp.target_mkbound) +
                                                          " is not a VCPM solid with particles"
                                                    : std::string("the case has no VCPM solid particle"));
                item.first = std::uint32_t(q_.ids.size());
                item.count = 1;
                q_.ids.push_back(best_id);
                item.pos0 = physics::Double3{ps.pos[best_id].x, ps.pos[best_id].y, ps.pos[best_id].z};
                log << "  gauge " << sp.name << ": solid particle " << best_id << " at (" << item.pos0.x << ", "
                    << item.pos0.y << ", " << item.pos0.z << "), " << std::sqrt(best) << " m from the point\n";
                break;
            }
        }
        if (item.output) {
            if (!any_output) fs::create_directories(fs::path(outdir) / "gauges");
            any_output = true;
            const std::string path =
                (fs::path(outdir) / "gauges" / ("Gauges" + std::string(fileKind(sp.kind)) + "_" + sp.name + ".csv")).string();
            const std::string key = "gauges/" + std::to_string(items_.size()) + "/";
            const bool cont = resume && io::cutForResume(path, resume->integer(key + "offset"));
            item.file = std::fopen(path.c_str(), cont ? "a" : "w");
            if (!item.file) throw Error(path + ": cannot write the gauge file");
            if (!cont) std::fprintf(item.file, "%s\n", header(sp.kind));
        }
        if (resume) {
            const std::string key = "gauges/" + std::to_string(items_.size()) + "/";
            item.next_compute = resume->real(key + "next_compute");
            item.next_output = resume->real(key + "next_output");
        }
        items_.push_back(std::move(it));
    }
    if (resume) rows_ = resume->integer("gauges/rows");
    log << "  gauges: " << items_.size() << (any_output ? " (CSV in " + outdir + "/gauges)" : " (output off: nothing written)")
        << "\n";
}

GaugeSystem::~GaugeSystem() {
    for (auto& it : items_)
        if (it->file) std::fclose(it->file);
}

void GaugeSystem::attach(Backend& b) const { b.setGauges(q_); }

void GaugeSystem::save(CheckpointData& d) {
    d.ints["gauges/count"] = (long long)items_.size();
    d.ints["gauges/rows"] = rows_;
    for (std::size_t k = 0; k < items_.size(); ++k) {
        const Item& it = *items_[k];
        const std::string key = "gauges/" + std::to_string(k) + "/";
        d.reals[key + "next_compute"] = it.next_compute;
        d.reals[key + "next_output"] = it.next_output;
        long long offset = -1;
        if (it.file) {
            std::fflush(it.file);
            offset = std::ftell(it.file);
        }
        d.ints[key + "offset"] = offset;
    }
}

double GaugeSystem::nextTime() const {
    double t = kNever;
    for (const auto& it : items_)
        if (it->next_compute <= it->cend) t = std::min(t, it->next_compute);
    return t;
}

void GaugeSystem::flush() {
    for (auto& it : items_)
        if (it->file) std::fflush(it->file);
}

void GaugeSystem::evaluate(double t, Backend& b) {
    const double eps = 1e-12 * std::max(1.0, std::fabs(t));
    std::vector<Item*> due;
    bool forces = false;
    for (auto& it : items_)
        if (t >= it->cstart - eps && t <= it->cend + eps && t >= it->next_compute - eps) {
            due.push_back(it.get());
            forces = forces || it->spec.kind == GaugeKind::Force;
        }
    if (due.empty()) return;
    GaugeResults r;
    b.gauges(r);
    std::vector<physics::Double3> bforce;
    if (forces) b.boundaryForces(bforce);
    for (std::size_t k = 0; k < q_.points.size(); ++k)
        if (outside_[k]) r.samples[k] = physics::GaugeSample{};
    for (Item* it : due) {
        it->next_compute = nextMultiple(t, it->computedt);
        const bool write = it->file && t >= it->ostart - eps && t <= it->oend + eps && t >= it->next_output - eps;
        if (!write) continue;
        it->next_output = nextMultiple(t, it->outputdt);
        std::FILE* f = it->file;
        const GaugeSpec& sp = it->spec;
        std::fprintf(f, "%.10g", t);
        switch (sp.kind) {
            case GaugeKind::Velocity: {
                const physics::GaugeSample& s = r.samples[it->first];
                std::fprintf(f, ";%.9g;%.9g;%.9g;%.9g;%.9g;%.9g;%.9g\n", physics::shepard(s.vx, s.wsum, sp.kclimit),
                             physics::shepard(s.vy, s.wsum, sp.kclimit), physics::shepard(s.vz, s.wsum, sp.kclimit),
                             sp.point.x, sp.point.y, sp.point.z, s.wsum);
                break;
            }
            case GaugeKind::Pressure: {
                const physics::GaugeSample& s = r.samples[it->first];
                std::fprintf(f, ";%.9g;%.9g;%.9g;%.9g;%.9g\n", physics::shepard(s.press, s.wsum, sp.kclimit), sp.point.x,
                             sp.point.y, sp.point.z, s.wsum);
                break;
            }
            case GaugeKind::Swl: {
                std::vector<double> mass(it->count);
                for (std::uint32_t k = 0; k < it->count; ++k) mass[k] = r.samples[it->first + k].mass;
                const physics::Double3 s = physics::swlSurface(mass.data(), int(it->count), it->point0, it->dir, it->masslimit);
                std::fprintf(f, ";%.9g;%.9g;%.9g;%.9g;%.9g;%.9g;%.9g;%.9g;%.9g\n", s.x, s.y, s.z, sp.point0.x, sp.point0.y,
                             sp.point0.z, sp.point2.x, sp.point2.y, sp.point2.z);
                break;
            }
            case GaugeKind::MaxZ: {
                double z = -1e300;
                for (std::uint32_t k = 0; k < it->count; ++k) z = std::max(z, r.maxz[it->first + k]);
                std::fprintf(f, ";%.9g;%.9g;%.9g;%.9g\n", std::max(z, domain_minz_), sp.point0.x, sp.point0.y, sp.point0.z);
                break;
            }
            case GaugeKind::Force: {
                double fx = 0, fy = 0, fz = 0;
                for (std::uint32_t id : it->force_ids) {
                    fx += bforce[id].x;
                    fy += bforce[id].y;
                    fz += bforce[id].z;
                }
                std::fprintf(f, ";%.9g;%.9g;%.9g\n", fx, fy, fz);
                break;
            }
            case GaugeKind::SolidMarker: {
                const physics::Double3 p = r.positions[it->first];
                std::fprintf(f, ";%.12g;%.12g;%.12g;%.9g;%.9g;%.9g\n", p.x, p.y, p.z, p.x - it->pos0.x, p.y - it->pos0.y,
                             p.z - it->pos0.z);
                break;
            }
        }
        ++rows_;
    }
}

}  // namespace seaspring::solver
