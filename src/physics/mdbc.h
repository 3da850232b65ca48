// SeaSpring — MIT licence.
/// \file mdbc.h
/// \brief Modified dynamic boundary conditions (mDBC: English et al. 2022, as DualSPHysics 5.4;
///        `<parameter key="Boundary" value="2">`), one source for both backends.
///
/// Every boundary particle b with a ghost vector n_b (gencase's normals: from b to its ghost
/// node, twice the distance to the boundary interface) takes its density, and with SlipMode 2
/// and 3 its velocity, from the fluid around its ghost node g = x_b + n_b before every force
/// evaluation. Over the fluid neighbours j of g (r = g - x_j, V_j = m_j / rho_j):
///   rho_s = sum m_j W,  grad_s = sum m_j grad W,
///   A = sum V_j [ W   r^T W   ]        (3x3 in 2D over (1, x, z); 4x4 in 3D)
///               [ gW  r^T gW  ]        (gW = grad W = F(r) r)
/// and A [rho_g, -G]^T = [rho_s, grad_s]^T gives the first-order (kernel-gradient corrected)
/// density rho_g at the ghost node and its gradient G; Shepard's rho_s / A11 is the zeroth-order
/// fallback.
///  - SlipMode 1 (DualSPHysics' original mDBC, "DBC vel=0"): rho_b = rho_g + G . (x_b - g) when
///    |det A| >= 1e-3; rho_s / A11 when only A11 > 0; rho0 without fluid in reach or with A11
///    below MDbcThreshold. The velocity stays the wall's (DBC).
///  - SlipMode 2 (no-slip) and 3 (free-slip), DualSPHysics' mDBC2: a ghost node without fluid
///    (submerged = -sum V_j r.grad W <= 0) switches the particle off: rho0 and the wall velocity.
///    Otherwise rho_g is first order when A11 >= 0.1, |det A| >= 1e-3 and the scaled condition
///    number dp^2 |A|inf |A^-1|inf <= 50, else Shepard (at least rho0 when A11 < 0.1); the
///    pressure is cloned to the particle with the hydrostatic jump of the wall-normal distance,
///      p_b = c0^2 (rho_g - rho0) + rho0 (g - a_wall) . n^ ((x_b - g) . n^),  rho_b = rho0 + p_b / c0^2,
///    and, as DualSPHysics 5.4 does, the particle carries two velocities: the wall's own motion
///    velocity (in velrho: the continuity equation and everything else see the wall), and for
///    the viscous terms alone the tangential part of v_2 = 2 v_wall - v_g (no-slip) or v_2 = v_g
///    (free-slip), v_g the ghost node's Shepard velocity (DualSPHysics' `tangenvel`;
///    MdbcInputs::visc_vel, InteractionInputs::bound_visc_vel). An earlier version put the
///    whole mirrored velocity in velrho, so the continuity equation saw it too: the 3D still tank
///    with no-slip walls then drifted (its lowest row's pressure 0.977 of hydrostatic at 1 s) and
///    diverged by 3 s, and free-slip had to mirror the normal velocity to keep the water from
///    sinking through the floor (docs/validation.md).
/// Sums run in float in the neighbour order of the force loops (forEachCandidateRow), the
/// matrix is inverted in double with plain IEEE operations: the same bits on both backends.
#pragma once

#include <cstdint>

#include "physics/cell_grid.h"
#include "physics/fluid_constants.h"
#include "physics/neighbour_rows.h"
#include "physics/mdbc_solid.h"
#include "physics/particle_updates.h"
#include "physics/sph_types.h"

namespace seaspring::physics {

/// DualSPHysics' SlipMode values.
enum class SlipMode : int { Vel0 = 1, NoSlip = 2, FreeSlip = 3 };

/// The constants of the mDBC pass.
struct MdbcConstants {
    float threshold = 0;    ///< MDbcThreshold: SlipMode 1 needs A11 >= this (0..1)
    float dp2 = 0;          ///< dp^2, scales the condition number
    float cs02 = 0;         ///< c0^2: the linear equation of state of the pressure cloning
    float gx = 0, gy = 0, gz = 0;  ///< gravity [m/s^2]
};

constexpr double kMdbcDetLimit = 1e-3;     ///< |det A| below this: Shepard (DualSPHysics)
constexpr float kMdbcMinKernelSum = 0.1f;  ///< mDBC2: A11 below this: Shepard, at least rho0
constexpr float kMdbcMaxCondition = 50.f;  ///< mDBC2: scaled condition number limit

/// The kernel sums at a ghost node. Axes: 2D (x, z), 3D (x, y, z); matrix row/column 0 is the
/// kernel value, k + 1 axis k.
struct MdbcSums {
    float rho = 0;                 ///< sum m W
    float grad[3] = {0, 0, 0};     ///< sum m grad W, per axis
    float a[4][4] = {};            ///< the correction matrix (kDim + 1 square)
    float vx = 0, vy = 0, vz = 0;  ///< sum V W v
    float submerged = 0;           ///< -sum V r . grad W
};

/// The sums over the fluid block around the ghost node whose PosCell is `gpc`.
template <class Kernel, int kDim>
SEASPRING_HD inline MdbcSums mdbcGhostSums(const Float4& gpc, const std::uint32_t* cell_start_fluid,
                                           const Float4* poscell, const Float4* velrho, const FluidConstants& c,
                                           const CellGrid& g) {
    MdbcSums s;
    forEachCandidateRow<kDim>(gpc, cell_start_fluid, c, g, [&](std::uint32_t pb, std::uint32_t pe, const Float4& par,
                                                               int cax) {
        for (std::uint32_t j = pb; j < pe; ++j) {
            float drx, dry, drz;
            const float rr2 = pairOffset<kDim>(par, poscell[j], cax, g, drx, dry, drz);
            if (!(rr2 <= c.ker.kernelsize2)) continue;  // r = 0 counts: the node is not a particle
            const float w = Kernel::value(rr2, c.ker);
            const float fac = Kernel::gradFactor(rr2, c.ker);
            const float frx = fac * drx, fry = fac * dry, frz = fac * drz;
            const Float4 vj = velrho[j];
            const float vol = c.massfluid / vj.w;
            s.submerged -= vol * (drx * frx + dry * fry + drz * frz);
            s.rho += c.massfluid * w;
            const float vw = w * vol;
            s.vx += vw * vj.x;
            s.vy += vw * vj.y;
            s.vz += vw * vj.z;
            const float r[3] = {drx, kDim == 3 ? dry : drz, drz};
            const float fr[3] = {frx, kDim == 3 ? fry : frz, frz};
            s.a[0][0] += vw;
            for (int q = 0; q < kDim; ++q) s.a[0][q + 1] += r[q] * vw;
            for (int k = 0; k < kDim; ++k) {
                s.grad[k] += c.massfluid * fr[k];
                const float vf = fr[k] * vol;
                s.a[k + 1][0] += vf;
                for (int q = 0; q < kDim; ++q) s.a[k + 1][q + 1] += r[q] * vf;
            }
        }
    });
    return s;
}

/// Inverts the n x n matrix `a` (n = 3 or 4) in double by Gauss-Jordan elimination with partial
/// pivoting (fixed operation order); `det` receives the determinant. False when it is singular.
template <int n>
SEASPRING_HD inline bool mdbcInvert(const float (&a)[4][4], double (&inv)[4][4], double& det) {
    double m[4][8];
    for (int r = 0; r < n; ++r)
        for (int q = 0; q < n; ++q) {
            m[r][q] = double(a[r][q]);
            m[r][n + q] = r == q ? 1.0 : 0.0;
        }
    det = 1.0;
    for (int col = 0; col < n; ++col) {
        int piv = col;
        for (int r = col + 1; r < n; ++r)
            if (fabs(m[r][col]) > fabs(m[piv][col])) piv = r;
        if (m[piv][col] == 0.0) {
            det = 0.0;
            return false;
        }
        if (piv != col) {
            for (int q = 0; q < 2 * n; ++q) {
                const double t = m[col][q];
                m[col][q] = m[piv][q];
                m[piv][q] = t;
            }
            det = -det;
        }
        const double p = m[col][col];
        det *= p;
        const double ovp = 1.0 / p;
        for (int q = 0; q < 2 * n; ++q) m[col][q] *= ovp;
        for (int r = 0; r < n; ++r) {
            if (r == col) continue;
            const double f = m[r][col];
            if (f == 0.0) continue;
            for (int q = 0; q < 2 * n; ++q) m[r][q] -= f * m[col][q];
        }
    }
    for (int r = 0; r < n; ++r)
        for (int q = 0; q < n; ++q) inv[r][q] = m[r][n + q];
    return true;
}

/// The infinity norm (largest absolute row sum) of an n x n matrix.
template <int n, typename T>
SEASPRING_HD inline double mdbcInfNorm(const T (&a)[4][4]) {
    double best = 0.0;
    for (int r = 0; r < n; ++r) {
        double s = 0.0;
        for (int q = 0; q < n; ++q) s += fabs(double(a[r][q]));
        best = s > best ? s : best;
    }
    return best;
}

/// What the mDBC correction sets on a boundary particle.
struct MdbcResult {
    float rho;
    float vx, vy, vz;     ///< the wall's velocity (velrho)
    float tvx, tvy, tvz;  ///< SlipMode 2/3: the velocity of the viscous terms (tangential)
    bool set_velocity;    ///< SlipMode 2/3: the velocities too
};

/// The tangential part of (vx, vy, vz) for the unit normal (ux, uy, uz).
SEASPRING_HD inline void mdbcTangential(float vx, float vy, float vz, float ux, float uy, float uz, float& tx,
                                        float& ty, float& tz) {
    const float vn = vx * ux + vy * uy + vz * uz;
    tx = vx - vn * ux;
    ty = vy - vn * uy;
    tz = vz - vn * uz;
}

/// The density (and velocity) of a boundary particle with ghost vector (nx, ny, nz) from the
/// sums at its ghost node. (wx, wy, wz): the wall's own velocity, (ax, ay, az) its acceleration.
template <int kDim>
SEASPRING_HD inline MdbcResult mdbcCorrect(const MdbcSums& s, SlipMode slip, float nx, float ny, float nz,
                                           float wx, float wy, float wz, float ax, float ay, float az,
                                           const FluidConstants& c, const MdbcConstants& m) {
    constexpr int n = kDim + 1;
    const float rho0 = c.rhop0;
    const float a11 = s.a[0][0];
    MdbcResult out{rho0, wx, wy, wz, wx, wy, wz, slip != SlipMode::Vel0};
    if (slip == SlipMode::Vel0) {
        if (!(a11 > 0.f) || a11 < m.threshold) return out;
        double inv[4][4], det;
        if (mdbcInvert<n>(s.a, inv, det) && fabs(det) >= kMdbcDetLimit) {
            // The solution is (rho_g, -G); rho_b = rho_g + G . (x_b - g) = rho_g - G . n.
            const double b[4] = {double(s.rho), double(s.grad[0]), double(s.grad[1]), double(s.grad[2])};
            double sol[4] = {0, 0, 0, 0};
            for (int r = 0; r < n; ++r)
                for (int q = 0; q < n; ++q) sol[r] += inv[r][q] * b[q];
            const float rhog = float(sol[0]);
            const float nax[3] = {nx, kDim == 3 ? ny : nz, nz};
            float jump = 0.f;
            for (int k = 0; k < kDim; ++k) jump += float(-sol[k + 1]) * -nax[k];
            out.rho = rhog + jump;
        } else {
            out.rho = float(double(s.rho) / double(a11));
        }
        return out;
    }
    // The unit normal (the ghost vector's direction).
    const float len = sqrtf(nx * nx + ny * ny + nz * nz);
    const float ux = nx / len, uy = ny / len, uz = nz / len;
    if (!(s.submerged > 0.f)) {  // a dry ghost node: rho0, the wall velocity (its tangential part for viscosity)
        mdbcTangential(wx, wy, wz, ux, uy, uz, out.tvx, out.tvy, out.tvz);
        return out;
    }
    float rhog;
    if (a11 < kMdbcMinKernelSum) {
        const float shep = float(double(s.rho) / double(a11));
        rhog = shep > rho0 ? shep : rho0;
    } else {
        double inv[4][4], det;
        rhog = float(double(s.rho) / double(a11));
        if (mdbcInvert<n>(s.a, inv, det) && fabs(det) >= kMdbcDetLimit) {
            const double cond = double(m.dp2) * mdbcInfNorm<n>(s.a) * mdbcInfNorm<n>(inv);
            if (cond <= double(kMdbcMaxCondition)) {
                const double b[4] = {double(s.rho), double(s.grad[0]), double(s.grad[1]), double(s.grad[2])};
                double r0 = 0.0;
                for (int q = 0; q < n; ++q) r0 += inv[0][q] * b[q];
                rhog = float(r0);
            }
        }
    }
    // Pressure cloning along the unit normal: (x_b - g) . n^ = -|n|.
    const float normpos = -nx * ux - ny * uy - nz * uz;
    const float normforce = rho0 * ((m.gx - ax) * ux + (m.gy - ay) * uy + (m.gz - az) * uz);
    const float pressure = m.cs02 * (rhog - rho0) + normforce * normpos;
    out.rho = rho0 + pressure / m.cs02;
    const float gvx = float(double(s.vx) / double(a11));
    const float gvy = kDim == 3 ? float(double(s.vy) / double(a11)) : 0.f;
    const float gvz = float(double(s.vz) / double(a11));
    if (slip == SlipMode::NoSlip)  // v_2 = 2 v_wall - v_g
        mdbcTangential(wx + wx - gvx, wy + wy - gvy, wz + wz - gvz, ux, uy, uz, out.tvx, out.tvy, out.tvz);
    else  // free-slip: v_2 = v_g
        mdbcTangential(gvx, gvy, gvz, ux, uy, uz, out.tvx, out.tvy, out.tvz);
    return out;
}

/// The inputs of the mDBC pass over the boundary block.
struct MdbcInputs {
    const Float4* normal0 = nullptr;  ///< per boundary id: the ghost vector at t = 0 (w unused)
    Float4* visc_vel = nullptr;       ///< SlipMode 2/3: per boundary particle (sorted), the viscous terms' velocity
    std::uint32_t first_moving = 0, nmoving = 0;
    const Double3* moving_pos0 = nullptr;          ///< per moving particle: initial position
    const std::uint16_t* moving_object = nullptr;  ///< per moving particle: its motion
    const RigidMotionGpu* motions = nullptr;       ///< the current poses
    const std::uint32_t* cell_start_fluid = nullptr;
    const std::uint8_t* near = nullptr;  ///< per cell kNearFluid (null: always search)
    /// VCPM solids (nsolid = 0: none): their ghost vectors follow the lattice (mdbc_solid.h),
    /// their wall velocity is the solid's.
    std::uint32_t first_solid = 0, nsolid = 0;
    const Double3* solid_pos = nullptr;   ///< current, solid-index order
    const Double3* solid_pos0 = nullptr;  ///< initial
    const Double3* solid_vel = nullptr;
    SolidBonds bonds;
};

/// Boundary particle i (sorted index): its ghost vector now (a moving boundary rotates its
/// initial one with its pose, a solid particle's follows the lattice's deformation), its wall
/// velocity (0, the motion's over the coming interval as motionAt, or the solid's), the sums at
/// the ghost node and the correction. Particles without a ghost vector keep DBC (with SlipMode
/// 2/3 their own velocity is their viscous velocity). The wall acceleration of the pressure
/// cloning is taken as 0.
template <class Kernel, int kDim>
SEASPRING_HD inline void mdbcBoundaryAt(std::uint32_t i, const ParticleView& v, const MdbcInputs& in, SlipMode slip,
                                        const FluidConstants& c, const MdbcConstants& m, const CellGrid& g) {
    const std::uint32_t id = v.id[i];
    const Float4 n0 = in.normal0[id];
    if (n0.x == 0.f && n0.y == 0.f && n0.z == 0.f) {  // DBC: its own velocity in the viscous terms too
        if (in.visc_vel) {
            const Float4 vr = v.velrho[i];
            in.visc_vel[i] = Float4{vr.x, vr.y, vr.z, 0.f};
        }
        return;
    }
    Double3 n{double(n0.x), double(n0.y), double(n0.z)};
    float wx = 0.f, wy = 0.f, wz = 0.f;
    const std::uint32_t k = id - in.first_moving;
    const std::uint32_t sidx = id - in.first_solid;
    if (id >= in.first_solid && sidx < in.nsolid) {
        n = solidGhostVector<kDim>(sidx, n, in.solid_pos, in.solid_pos0, in.bonds);
        const Double3 u = in.solid_vel[sidx];
        wx = float(u.x);
        wy = float(u.y);
        wz = float(u.z);
    } else if (id >= in.first_moving && k < in.nmoving) {
        const RigidMotionGpu& mo = in.motions[in.moving_object[k]];
        const double zero[3] = {0.0, 0.0, 0.0};
        n = applyRigid(mo.r, zero, n);
        const Double3 a = applyRigid(mo.r, mo.t, in.moving_pos0[k]);
        const Double3 b = applyRigid(mo.r_next, mo.t_next, in.moving_pos0[k]);
        wx = float((b.x - a.x) * mo.inv_dt);
        wy = float((b.y - a.y) * mo.inv_dt);
        wz = float((b.z - a.z) * mo.inv_dt);
    }
    const Double3 p = v.pos[i];
    const Double3 gp{p.x + n.x, p.y + n.y, p.z + n.z};
    std::uint32_t lin;
    const Float4 gpc = makePosCell(g, gp, lin);
    // A node outside the grid (normals pointing out of the domain) has no fluid around it, as a
    // gauge point outside the domain; no fluid in reach of the node's cell: the empty sums too.
    const bool inside = gp.x >= g.minx && gp.x < g.minx + double(g.ncx) * g.cellsize && gp.z >= g.minz &&
                        gp.z < g.minz + double(g.ncz) * g.cellsize &&
                        (kDim == 2 || (gp.y >= g.miny && gp.y < g.miny + double(g.ncy) * g.cellsize));
    MdbcSums s;
    if (inside && (in.near == nullptr || (in.near[lin] & kNearFluid) != 0))
        s = mdbcGhostSums<Kernel, kDim>(gpc, in.cell_start_fluid, v.poscell, v.velrho, c, g);
    const MdbcResult res =
        mdbcCorrect<kDim>(s, slip, float(n.x), float(n.y), float(n.z), wx, wy, wz, 0.f, 0.f, 0.f, c, m);
    if (res.set_velocity) {
        v.velrho[i] = Float4{res.vx, res.vy, res.vz, res.rho};
        in.visc_vel[i] = Float4{res.tvx, res.tvy, res.tvz, 0.f};
    } else {
        v.velrho[i].w = res.rho;
    }
}

}  // namespace seaspring::physics
