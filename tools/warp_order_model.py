#!/usr/bin/env python3
# SeaSpring — MIT licence.
"""A cost model of the GPU's masked fluid pair walk (physics::fluidPairsInRowMasked) for a warp of
32 particles, used to judge a re-ordering of the threads before building it
(docs/performance-large.md, twenty-ninth session).

Particles on a 3D lattice of spacing dp, each moved by a uniform random offset of up to
AMP dp per axis (a stand-in for the disordered flow after an impact), h = 1.5 dp, cells of 2h/3
(the 3D sluice gate's), sorted by (cell, id). Every particle's rows of cells (dy, dz in
[-3, 3]) are tested against the rows' particle extents as the GPU's walk does; per row a thread
tests its candidates (cost CT each) and runs the pair arithmetic for its neighbours (CP each);
a row costs CR when any thread of the warp visits it. A warp's row costs its threads' maxima
(they run in step); efficiency = the threads' own work / 32 x the warp's.

Mappings compared: warps of 32 consecutive particles (what runs now), and the particles of each
segment of S consecutive ones grouped by their offset inside their cell (BINS per axis) before
being cut into warps. Last, the same warps with a ring of found pairs per thread (the thirtieth
session's queue: modelled 0.76 of the masked walk after the impacts, 1.02 on the lattice;
measured 1.34 and 1.22: the ring's bookkeeping cost twice the 16 instructions a pair assumed and
the lanes rose far less). Usage: /usr/bin/python3 tools/warp_order_model.py [AMP]
"""
import sys

import numpy as np

CT, CP, CR = 15, 140, 40  # instructions: a candidate test, a laminar+SPS pair, a row's set-up


def main():
    rng = np.random.default_rng(1)
    dp = 1.0
    h = 1.5 * dp
    reach = 2 * h
    cs = 2 * h / 3
    nx, ny, nz = 96, 24, 24
    amp = float(sys.argv[1]) if len(sys.argv) > 1 else 0.5
    lattice = np.stack(np.meshgrid(np.arange(nx), np.arange(ny), np.arange(nz), indexing="ij"), -1)
    lattice = lattice.reshape(-1, 3).astype(float)
    box = np.array([nx, ny, nz]) * dp
    pos = np.clip((lattice + 0.5) * dp + rng.uniform(-amp, amp, lattice.shape) * dp, 1e-6, box - 1e-6)
    cell = np.floor(pos / cs).astype(int)
    ncx, ncy, ncz = [int(np.ceil(n * dp / cs)) for n in (nx, ny, nz)]
    lin = cell[:, 0] + ncx * (cell[:, 1] + ncy * cell[:, 2])
    order = np.lexsort((np.arange(len(pos)), lin))
    pos, cell, lin = pos[order], cell[order], lin[order]
    n = len(pos)
    off = pos - cell * cs
    row_of = cell[:, 1] + ncy * cell[:, 2]
    lo = np.full((ncy * ncz, 3), np.inf)
    hi = np.full((ncy * ncz, 3), -np.inf)
    np.minimum.at(lo, row_of, off)
    np.maximum.at(hi, row_of, off)
    cstart = np.searchsorted(lin, np.arange(ncx * ncy * ncz + 1))
    inner = np.nonzero(np.all((cell >= 4) & (cell < np.array([ncx, ncy, ncz]) - 4), axis=1))[0]
    rows = [(dy, dz) for dz in range(-3, 4) for dy in range(-3, 4)]
    cand = np.zeros((n, len(rows)), int)
    nb = np.zeros((n, len(rows)), int)
    visits = np.zeros((n, len(rows)), bool)
    px, py, pz = pos[inner, 0], pos[inner, 1], pos[inner, 2]
    for k, (dy, dz) in enumerate(rows):
        y = cell[inner, 1] + dy
        z = cell[inner, 2] + dz
        r = y + ncy * z
        gy = np.maximum(0, np.maximum(y * cs + lo[r, 1] - py, py - (y * cs + hi[r, 1])))
        gz = np.maximum(0, np.maximum(z * cs + lo[r, 2] - pz, pz - (z * cs + hi[r, 2])))
        d2 = gy * gy + gz * gz
        ok = d2 <= reach * reach
        rx = np.sqrt(np.maximum(reach * reach - d2, 0))
        x0 = np.clip(np.ceil((px - rx - hi[r, 0]) / cs).astype(int), 0, ncx - 1)
        x1 = np.clip(np.floor((px + rx - lo[r, 0]) / cs).astype(int), 0, ncx - 1)
        pb = cstart[r * ncx + x0]
        pe = cstart[r * ncx + x1 + 1]
        c = np.where(ok, pe - pb, 0)
        cand[inner, k] = c
        visits[inner, k] = ok & (c > 0)
        for t, i in enumerate(inner):
            if ok[t]:
                q = pos[pb[t]:pe[t]] - pos[i]
                nb[i, k] = np.count_nonzero((q * q).sum(1) < reach * reach)

    def efficiency(warps):
        warp_cost = work = 0
        for w in warps:
            warp_cost += 32 * (CT * cand[w].max(0).sum() + CP * nb[w].max(0).sum() + CR * visits[w].any(0).sum())
            work += CT * cand[w].sum() + CP * nb[w].sum() + CR * visits[w].sum()
        return work / warp_cost, warp_cost / len(warps) / 32

    print(f"offsets up to {amp} dp: {cand[inner].sum(1).mean():.1f} candidates, {nb[inner].sum(1).mean():.1f} "
          f"neighbours per particle")
    consecutive = [inner[i:i + 32] for i in range(0, len(inner) - 31, 32)]
    print("warps of 32 consecutive particles: efficiency %.3f, cost per particle %.0f" % efficiency(consecutive))
    for seg in (128, 256, 512):
        for bins in (2, 3, 4):
            warps = []
            for s in range(0, len(inner) - seg + 1, seg):
                part = inner[s:s + seg]
                f = np.minimum((off[part] / cs * bins).astype(int), bins - 1)
                part = part[np.argsort(f[:, 2] * bins * bins + f[:, 1] * bins + f[:, 0], kind="stable")]
                warps += [part[i:i + 32] for i in range(0, seg, 32)]
            print("segments of %d grouped by offset (%d bins per axis): efficiency %.3f, cost per particle %.0f"
                  % ((seg, bins) + efficiency(warps)))

    def ring(warps, cap, keep, extra):
        """A ring of `cap` found neighbours per thread (thirtieth session, physics code not kept): rows
        walked in step; at each row's end the warp evaluates the least count its threads hold (at
        least one pair when any thread holds more than `keep`), each pair `extra` instructions dearer;
        a row that would overflow a ring first drains what the fullest thread needs."""
        warp_cost = work = 0
        for w in warps:
            c = 32 * (CT * cand[w].max(0).sum() + CR * visits[w].any(0).sum())
            n = np.zeros(len(w), int)
            for k in range(nb.shape[1]):
                add = nb[w, k]
                if (n + add > cap).any():
                    p = (n + add - cap).max()
                    c += 32 * (CP + extra) * p
                    n = np.maximum(n - p, 0)
                n += add
                if n.max() >= keep:
                    p = max(1, n.min())
                    c += 32 * (CP + extra) * p
                    n = np.maximum(n - p, 0)
            warp_cost += c + 32 * (CP + extra) * n.max()
            work += CT * cand[w].sum() + CP * nb[w].sum() + CR * visits[w].sum()
        return work / warp_cost, warp_cost / len(warps) / 32

    print("a ring of 32 found pairs per thread (24 kept), 16 instructions more a pair: efficiency %.3f, "
          "cost per particle %.0f" % ring(consecutive, 32, 24, 16))


if __name__ == "__main__":
    main()
