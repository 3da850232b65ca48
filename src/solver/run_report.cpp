// SeaSpring — MIT licence.
/// \file run_report.cpp
#include "solver/run_report.h"

#include <cstdio>
#include <ostream>

#include "core/version.h"
#include "io/json_writer.h"

namespace seaspring::solver {

void writeRunJson(const std::string& path, const RunSummary& s) {
    io::JsonWriter j;
    j.beginObject();
    j.value("program", "seaspring");
    j.value("version", kVersion);
    j.value("case", s.case_name);
    j.value("backend", s.backend);
    j.value("device", s.device);
    j.value("threads", s.threads);
    j.value("physics", s.options);
    j.beginObject("particles");
    j.value("total", static_cast<long long>(s.np));
    j.value("fixed", static_cast<long long>(s.nfixed));
    j.value("moving", static_cast<long long>(s.nmoving));
    j.value("solid", static_cast<long long>(s.nsolid));
    j.value("fluid", static_cast<long long>(s.nfluid));
    j.value("fluid_active_at_end", static_cast<long long>(s.fluid_active));
    j.endObject();
    j.beginObject("excluded");
    j.value("out_of_domain", static_cast<long long>(s.excluded_position));
    j.value("density_out_of_range", static_cast<long long>(s.excluded_density));
    j.value("not_finite", static_cast<long long>(s.excluded_not_finite));
    j.endObject();
    j.value("steps", s.steps);
    j.value("physical_time_s", s.physical_time);
    j.value("last_dt_s", s.dt_last);
    j.value("dtmin_hits", s.dtmin_hits);
    j.value("divides", static_cast<long long>(s.divides));
    j.value("sorts", static_cast<long long>(s.sorts));
    j.value("wall_time_s", s.wall_time);
    j.value("loop_time_s", s.loop_time);
    j.value("ns_per_particle_step", s.ns_per_particle_step);
    j.value("outputs", s.outputs);
    j.value("gauge_rows", s.gauge_rows);
    if (s.nsolid > 0) {
        j.beginObject("solids");
        j.value("particles", static_cast<long long>(s.nsolid));
        j.value("bonds", static_cast<long long>(s.bonds));
        j.value("clamp_bonds", static_cast<long long>(s.clamp_bonds));
        j.value("broken_bonds", static_cast<long long>(s.broken_bonds));
        j.value("substeps", s.solid_substeps);
        j.value("max_substeps_per_step", s.omega_max);
        j.value("solid_dt_s", s.solid_dt);
        j.endObject();
    }
    j.value("stop_reason", s.stop_reason);
    j.value("state_hash", s.state_hash);
    j.endObject();
    io::writeTextFileAtomic(path, j.str() + "\n");
}

void printSummary(std::ostream& os, const RunSummary& s) {
    char line[512];
    std::snprintf(line, sizeof line,
                  "Finished (%s): %lld steps to t=%.6g s in %.3f s wall (loop %.3f s), %.2f ns/particle/step\n",
                  s.stop_reason.c_str(), s.steps, s.physical_time, s.wall_time, s.loop_time,
                  s.ns_per_particle_step);
    os << line;
    std::snprintf(line, sizeof line,
                  "Particles: %u (fluid %u, active at end %u); excluded: %u out of domain, %u density, %u "
                  "not finite; dt adjusted to DtMin %lld times; sorted at %llu of %llu divides\n",
                  s.np, s.nfluid, s.fluid_active, s.excluded_position, s.excluded_density,
                  s.excluded_not_finite, s.dtmin_hits, s.sorts, s.divides);
    os << line;
    if (s.nsolid > 0) {
        std::snprintf(line, sizeof line,
                      "Solids: %u particles, %llu bonds + %llu clamp bonds, %llu broken; %lld sub-steps of at most "
                      "%.4g s (at most %d per step)\n",
                      s.nsolid, static_cast<unsigned long long>(s.bonds), static_cast<unsigned long long>(s.clamp_bonds),
                      static_cast<unsigned long long>(s.broken_bonds), s.solid_substeps, s.solid_dt, s.omega_max);
        os << line;
    }
    os << "State hash: " << s.state_hash << "\n";
}

}  // namespace seaspring::solver
