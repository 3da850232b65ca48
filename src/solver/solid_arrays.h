// SeaSpring — MIT licence.
/// \file solid_arrays.h
/// \brief The arrays of the VCPM solid drivers, written once for both backends: `Buf` is the
///        container (host: std::vector; CUDA: cuda::DeviceBuffer). Set-up from a SolidSetup,
///        the physics views (SolidState, SolidBonds, ClampNodes), the snapshot of the staggered
///        midpoint coupling and the host copy all live here; the drivers only loop or launch.
///
/// The container interface is in buffers.h.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "physics/vcpm.h"
#include "physics/vcpm_substep.h"
#include "solver/backend.h"
#include "solver/buffers.h"
#include "solver/solid_passes.h"

namespace seaspring::solver {

template <template <typename> class Buf>
struct SolidArrays {
    std::uint32_t n = 0, nclamp = 0, first = 0;
    Buf<std::uint8_t> count, flags, broken, broken_saved;
    Buf<std::uint32_t> partner, slot;
    Buf<double> rest, sum, work, kfac, vw, vw_partner;
    Buf<std::uint8_t> row_slot;     ///< the rows' bending (empty without it; physics/vcpm_rows.h)
    Buf<physics::Double3> row_d;    ///< its row curvatures, written by every sums pass
    int row_axes = 0;
    Buf<std::uint16_t> body;
    Buf<physics::VcpmMaterial> materials;
    Buf<physics::Double3> pos, pos_half, vel, vel0, fluid_force;
    Buf<physics::Double3> impulse;  ///< ledger: sum of F dt per particle [N s]
    Buf<physics::SolidAlarm> alarm; ///< blow-up alarms (physics/blowup_bounds.h)
    // Contact (empty without it; physics/solid_contact.h).
    bool contact_on = false;
    physics::ContactParams contact;
    std::uint32_t contact_cap = 0;
    Buf<std::uint32_t> contact_count, contact_entry, clamp_pid;
    Buf<physics::Double3> contact_force, contact_pos0, contact_impulse, contact_impulse_saved;
    Buf<double> contact_work, contact_work_saved;
    Buf<physics::Double3> pos_saved, vel_saved;
    Buf<physics::Double3> load_force, load_rate;  ///< empty without point loads
    Buf<std::uint8_t> clamp_count;
    Buf<std::uint32_t> clamp_partner, clamp_slot;
    Buf<physics::Double3> clamp_pos_initial, clamp_start, clamp_end;
    Buf<std::int16_t> clamp_object;
    bool clamps_move = false;  ///< a clamp node belongs to a moving boundary (else no motion upload)
    /// physics::predictorForceUsed; false: two passes per sub-step (three with start_sums,
    /// physics::startSumsUsed), whose odd sub-steps keep their half positions in pos_half_alt
    /// (empty otherwise; SolidSubCycle)
    bool predictor_force = true, start_sums = true;
    Buf<physics::Double3> pos_half_alt;
    Buf<double> clamp_sum;
    double t0 = 0, span = 0;  ///< the current sub-cycle's start time and length
    physics::SolidKeepBox keep;

    void init(const SolidSetup& s) {
        const physics::Double3 zero3{0, 0, 0};
        n = s.nsolid;
        nclamp = s.nclamp;
        first = s.first_solid;
        keep = s.keep;
        assignFrom(count, s.count);
        assignFrom(partner, s.partner);
        assignFrom(rest, s.rest);
        assignFrom(flags, s.flags);
        assignFrom(kfac, s.kfac);
        assignFrom(vw, s.vw);
        assignFrom(vw_partner, s.vw_partner);
        row_axes = s.row_slot.empty() ? 0 : s.row_axes;
        assignFrom(row_slot, s.row_slot);
        assignFrom(row_d, std::vector<physics::Double3>(std::size_t(row_axes) * n, zero3));
        assignFrom(broken, std::vector<std::uint8_t>(s.flags.size(), 0));
        assignFrom(broken_saved, std::vector<std::uint8_t>(s.flags.size(), 0));
        assignFrom(body, s.body);
        assignFrom(materials, s.materials);
        assignFrom(pos, s.pos);
        assignFrom(pos_half, s.pos);
        assignFrom(pos_saved, s.pos);
        assignFrom(vel, s.vel);
        assignFrom(vel_saved, s.vel);
        assignFrom(vel0, s.vel);
        assignFrom(fluid_force, std::vector<physics::Double3>(n, zero3));
        assignFrom(sum, std::vector<double>(n, 0.0));
        assignFrom(impulse, std::vector<physics::Double3>(n, zero3));
        assignFrom(work, std::vector<double>(n, 0.0));
        assignFrom(alarm, std::vector<physics::SolidAlarm>(n));
        contact_on = s.contact_on;
        predictor_force = physics::predictorForceUsed(s.materials.data(), s.materials.size(), s.contact_on);
        start_sums = physics::startSumsUsed(s.materials.data(), s.materials.size());
        if (!predictor_force) assignFrom(pos_half_alt, s.pos);
        if (contact_on) {
            contact = s.contact;
            contact_cap = s.contact_cap;
            assignFrom(contact_count, std::vector<std::uint32_t>(n, 0u));
            assignFrom(contact_entry, std::vector<std::uint32_t>(std::size_t(contact_cap) * n, 0u));
            assignFrom(clamp_pid, s.clamp_id.empty() ? std::vector<std::uint32_t>(1, 0u) : s.clamp_id);
            assignFrom(contact_force, std::vector<physics::Double3>(n, zero3));
            assignFrom(contact_pos0, s.pos);
            assignFrom(contact_impulse, std::vector<physics::Double3>(n, zero3));
            assignFrom(contact_impulse_saved, std::vector<physics::Double3>(n, zero3));
            assignFrom(contact_work, std::vector<double>(n, 0.0));
            assignFrom(contact_work_saved, std::vector<double>(n, 0.0));
        }
        assignFrom(slot, std::vector<std::uint32_t>(n, 0));
        assignFrom(clamp_count, s.clamp_count);
        assignFrom(clamp_partner, s.clamp_partner);
        assignFrom(clamp_slot, s.clamp_slot);
        assignFrom(clamp_pos_initial, s.clamp_pos);
        assignFrom(clamp_start, s.clamp_pos);
        assignFrom(clamp_end, s.clamp_pos);
        assignFrom(clamp_object, s.clamp_object);
        clamps_move = false;
        for (std::int16_t o : s.clamp_object) clamps_move = clamps_move || o >= 0;
        assignFrom(clamp_sum, std::vector<double>(nclamp, 0.0));
        assignFrom(load_force, s.load_force);
        assignFrom(load_rate, s.load_rate);
    }

    physics::SolidState state() {
        physics::SolidState st;
        st.pos = pos.data();
        st.pos_half = pos_half.data();
        st.vel = vel.data();
        st.vel0 = vel0.data();
        st.sum = sum.data();
        st.fluid_force = fluid_force.data();
        st.body = body.data();
        st.material = materials.data();
        st.load_force = load_force.empty() ? nullptr : load_force.data();
        st.load_rate = load_rate.empty() ? nullptr : load_rate.data();
        st.t0 = t0;
        st.span = span;
        st.keep = keep;
        st.alarm = alarm.data();
        if (contact_on) {
            st.contact_force = contact_force.data();
            st.contact_impulse = contact_impulse.data();
            st.contact_work = contact_work.data();
        }
        return st;
    }

    physics::SolidBonds bonds() {
        physics::SolidBonds b;
        b.n = n;
        b.count = count.data();
        b.partner = partner.data();
        b.rest = rest.data();
        b.flags = flags.data();
        b.broken = broken.data();
        b.kfac = kfac.empty() ? nullptr : kfac.data();
        b.vw = vw.empty() ? nullptr : vw.data();
        b.vw_partner = vw_partner.empty() ? nullptr : vw_partner.data();
        if (row_axes > 0) {
            b.row_slot = row_slot.data();
            b.row_d = row_d.data();
            b.row_axes = row_axes;
        }
        return b;
    }

    physics::ContactList contactList() {
        physics::ContactList l;
        if (!contact_on) return l;
        l.n = n;
        l.cap = contact_cap;
        l.count = contact_count.data();
        l.entry = contact_entry.data();
        l.pos0 = contact_pos0.data();
        return l;
    }

    physics::ClampNodes clamps() {
        physics::ClampNodes c;
        c.n = nclamp;
        c.count = clamp_count.data();
        c.partner = clamp_partner.data();
        c.slot = clamp_slot.data();
        c.pos_start = clamp_start.data();
        c.pos_end = clamp_end.data();
        c.sum = clamp_sum.data();
        return c;
    }

    /// Calls f(name, buffer) for every array a run changes (the restart state; the others
    /// come from the SolidSetup again).
    template <class F>
    void forEachState(F&& f) {
        f("pos", pos);
        f("pos_half", pos_half);
        f("vel", vel);
        f("vel0", vel0);
        f("fluid_force", fluid_force);
        f("sum", sum);
        f("impulse", impulse);
        f("work", work);
        f("broken", broken);
        f("slot", slot);
        f("clamp_start", clamp_start);
        f("clamp_end", clamp_end);
        f("clamp_sum", clamp_sum);
        f("contact_impulse", contact_impulse);  // empty without contact
        f("contact_work", contact_work);
    }

    /// The midpoint coupling's snapshot, one pass over [0, snapshotRange()) each way: the
    /// state into the saved arrays (savePass), and back from them and on into the boundary
    /// block (restorePass; `boundary` the copy into it, which reads the restored arrays).
    std::uint32_t snapshotRange() const { return std::max<std::uint32_t>(n, std::uint32_t(broken.size())); }
    SolidSnapshotPass savePass() { return snapshot(false, SolidToBoundaryPass{}); }
    SolidSnapshotPass restorePass(const SolidToBoundaryPass& boundary) { return snapshot(true, boundary); }

    /// The solid part of HostState (solid-index order, slot-major bond states).
    void download(HostState& out) const {
        copyToHost(vel, out.solid_vel);
        copyToHost(fluid_force, out.solid_force);
        copyToHost(broken, out.bond_broken);
        copyToHost(impulse, out.solid_impulse);
        copyToHost(work, out.solid_work);
        copyToHost(alarm, out.solid_alarm);
        if (contact_on) {
            copyToHost(contact_impulse, out.contact_impulse);
            copyToHost(contact_work, out.contact_work);
        }
    }

private:
    SolidSnapshotPass snapshot(bool restore, const SolidToBoundaryPass& boundary) {
        SolidSnapshotPass p{};
        p.n = n;
        p.slots = std::uint32_t(broken.size());
        p.pos_from = restore ? pos_saved.data() : pos.data();
        p.pos_to = restore ? pos.data() : pos_saved.data();
        p.vel_from = restore ? vel_saved.data() : vel.data();
        p.vel_to = restore ? vel.data() : vel_saved.data();
        p.broken_from = restore ? broken_saved.data() : broken.data();
        p.broken_to = restore ? broken.data() : broken_saved.data();
        if (contact_on) {
            p.contact_impulse_from = restore ? contact_impulse_saved.data() : contact_impulse.data();
            p.contact_impulse_to = restore ? contact_impulse.data() : contact_impulse_saved.data();
            p.contact_work_from = restore ? contact_work_saved.data() : contact_work.data();
            p.contact_work_to = restore ? contact_work.data() : contact_work_saved.data();
        }
        p.to_boundary = restore;
        p.boundary = boundary;
        return p;
    }
};

}  // namespace seaspring::solver
