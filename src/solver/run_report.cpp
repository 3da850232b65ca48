// SeaSpring — MIT licence.
/// \file run_report.cpp
#include "solver/run_report.h"

#include <cmath>
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
    j.value("steps_this_run", s.steps_run);  // loop_time_s and ns_per_particle_step are of these
    j.value("physical_time_s", s.physical_time);
    j.value("last_dt_s", s.dt_last);
    j.value("dtmin_hits", s.dtmin_hits);
    j.value("divides", static_cast<long long>(s.divides));
    j.value("sorts", static_cast<long long>(s.sorts));
    j.value("boundary_sorts", static_cast<long long>(s.boundary_sorts));
    j.value("merged_sorts", static_cast<long long>(s.merged_sorts));
    if (s.cell_switch_divide > 0) j.value("cell_switch_divide", static_cast<long long>(s.cell_switch_divide));
    if (s.cell_switch_time >= 0) j.value("cell_switch_time_s", s.cell_switch_time);
    j.value("wall_time_s", s.wall_time);
    j.value("loop_time_s", s.loop_time);
    j.value("ns_per_particle_step", s.ns_per_particle_step);
    j.value("outputs", s.outputs);
    j.value("output_time_s", s.output_time);
    j.value("gauge_rows", s.gauge_rows);
    j.beginObject("memory");  // at the summary's time (simulation.h)
    j.value("host_peak_bytes", static_cast<unsigned long long>(s.host_bytes_peak));
    if (s.gpu_bytes_total > 0) {
        j.value("gpu_arrays_peak_bytes", static_cast<unsigned long long>(s.gpu_bytes_peak));
        j.value("gpu_arrays_bytes_per_particle", s.np > 0 ? double(s.gpu_bytes_peak) / double(s.np) : 0.0);
        j.value("gpu_total_bytes", static_cast<unsigned long long>(s.gpu_bytes_total));
    }
    j.endObject();
    if (s.nsolid > 0) {
        j.beginObject("solids");
        j.value("particles", static_cast<long long>(s.nsolid));
        j.value("bonds", static_cast<long long>(s.bonds));
        j.value("clamp_bonds", static_cast<long long>(s.clamp_bonds));
        j.value("broken_bonds", static_cast<long long>(s.broken_bonds));
        j.value("substeps", s.solid_substeps);
        j.value("max_substeps_per_step", s.omega_max);
        j.value("solid_dt_s", s.solid_dt);
        j.beginArray("bodies");
        for (const SolidOutside& o : s.solids_outside) {
            j.beginObject();
            j.value("mkbound", o.mkbound);
            j.value("particles", static_cast<long long>(o.particles));
            j.value("outside_domain", static_cast<long long>(o.outside));
            j.value("outside_domain_most", static_cast<long long>(o.most));
            j.value("first_outside_time_s", o.first_time);
            j.endObject();
        }
        j.endArray();
        j.endObject();
    }
    j.value("stop_reason", s.stop_reason);
    j.value("exit_code", s.exit_code);
    j.value("checkpoints", s.checkpoints);
    if (!s.last_checkpoint.empty()) j.value("last_checkpoint", s.last_checkpoint);
    if (!s.restarted_from.empty()) {
        j.value("restarted_from", s.restarted_from);
        j.value("restart_time_s", s.restart_time);
    }
    if (s.blowup) {
        const BlowupDiagnosis& d = *s.blowup;
        j.beginObject("blowup");
        j.value("quantity", d.quantity);
        j.value("message", d.message);
        j.value("likely_option", d.likely_option);
        j.value("time_s", d.time);
        if (std::isfinite(d.onset)) j.value("onset_time_s", d.onset);
        j.value("step", d.step);
        j.value("value", d.value);
        j.value("bound", d.bound);
        j.value("count", static_cast<unsigned long long>(d.count));
        j.beginArray("particles");
        for (const BlowupParticle& p : d.particles) {
            j.beginObject();
            j.value("id", static_cast<long long>(p.id));
            j.beginArray("pos");
            j.value(p.pos.x);
            j.value(p.pos.y);
            j.value(p.pos.z);
            j.endArray();
            j.value("value", p.value);
            j.endObject();
        }
        j.endArray();
        j.value("last_good_output", s.last_good_output);
        j.value("last_good_time_s", s.last_good_time);
        j.endObject();
    }
    j.value("state_hash", s.state_hash);
    j.endObject();
    io::writeTextFileAtomic(path, j.str() + "\n");
}

std::string memoryLine(const RunSummary& s) {
    const double mib = 1024.0 * 1024.0, np = s.np > 0 ? double(s.np) : 1.0;
    char line[320];
    std::string out = "Memory:";
    if (s.gpu_bytes_total > 0) {
        std::snprintf(line, sizeof line,
                      " GPU arrays at most %.1f MiB (%.1f bytes per particle) of the device's %.0f MiB;",
                      double(s.gpu_bytes_peak) / mib, double(s.gpu_bytes_peak) / np, double(s.gpu_bytes_total) / mib);
        out += line;
    }
    std::snprintf(line, sizeof line, " host peak %.1f MiB (%.0f bytes per particle)\n", double(s.host_bytes_peak) / mib,
                  double(s.host_bytes_peak) / np);
    return out + line;
}

void printSummary(std::ostream& os, const RunSummary& s) {
    char line[512];
    std::snprintf(line, sizeof line,
                  "%s (%s): %lld steps to t=%.6g s in %.3f s wall (loop %.3f s), %.2f ns/particle/step\n",
                  s.exit_code == 0 ? "Finished" : "Stopped", s.stop_reason.c_str(), s.steps, s.physical_time, s.wall_time, s.loop_time,
                  s.ns_per_particle_step);
    os << line;
    if (!s.restarted_from.empty()) {  // the rates above are of this run's steps
        std::snprintf(line, sizeof line, "  (%lld of them in this run, from t=%.6g s: %s)\n", s.steps_run, s.restart_time,
                      s.restarted_from.c_str());
        os << line;
    }
    if (s.outputs > 0) {
        std::snprintf(line, sizeof line, "Outputs: %d in %.3f s (state downloads, checks, part files)\n", s.outputs,
                      s.output_time);
        os << line;
    }
    std::snprintf(line, sizeof line,
                  "Particles: %u (fluid %u, active at end %u); excluded: %u out of domain, %u density, %u "
                  "not finite; dt adjusted to DtMin %lld times; sorted at %llu of %llu divides",
                  s.np, s.nfluid, s.fluid_active, s.excluded_position, s.excluded_density,
                  s.excluded_not_finite, s.dtmin_hits, s.sorts, s.divides);
    os << line;
    if (s.nmoving > 0 || s.nsolid > 0) {  // the boundary block is sorted only when its movers need it
        std::snprintf(line, sizeof line, " (the boundary block at %llu)", s.boundary_sorts);
        os << line;
    }
    if (s.cell_switch_divide > 0) {  // solver/cell_switch.h
        std::snprintf(line, sizeof line, "; cells of h from divide %llu", s.cell_switch_divide);
        os << line;
        if (s.cell_switch_time >= 0) {
            std::snprintf(line, sizeof line, " (t=%g s)", s.cell_switch_time);
            os << line;
        }
    }
    os << "\n";
    if (s.nsolid > 0) {
        std::snprintf(line, sizeof line,
                      "Solids: %u particles, %llu bonds + %llu clamp bonds, %llu broken; %lld sub-steps of at most "
                      "%.4g s (at most %d per step)\n",
                      s.nsolid, static_cast<unsigned long long>(s.bonds), static_cast<unsigned long long>(s.clamp_bonds),
                      static_cast<unsigned long long>(s.broken_bonds), s.solid_substeps, s.solid_dt, s.omega_max);
        os << line;
    }
    for (const SolidOutside& o : s.solids_outside)
        if (o.most > 0) {
            std::snprintf(line, sizeof line,
                          "Solid mkbound=%d: %u of %u particles outside the domain at the end (at most %u, first at "
                          "t=%.4g s)\n",
                          o.mkbound, o.outside, o.particles, o.most, o.first_time);
            os << line;
        }
    os << memoryLine(s);
    os << "State hash: " << s.state_hash << "\n";
}

}  // namespace seaspring::solver
