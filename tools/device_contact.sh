#!/usr/bin/env bash
# Runs ON the GPU machine (device tool), from the repository root, with build-dev carried
# (tools/device_build.sh). Contact of VCPM solids and solids leaving the domain (issues 13, 14):
#  1. parity: state hashes on 1, 2 and 16 CPU threads and the GPU for contact cases (two blocks
#     on a floor; the PMMA collapse with contact) and the free-falling beam that freezes below
#     the domain;
#  2. the Liao 2015 plate at dp 2 mm with contact (without it the 2-particle plate folds 35 mm
#     through the floor by 0.32 s): the lowest solid particle over every part file to 0.45 s;
#  3. the PMMA collapse to 3 s with and without contact: pairs of solid particles closer than
#     dp/2 at the end (interpenetrating fragments);
#  4. the cost of the per-step solid checks: the Antoci gate 2D, this build against the base
#     binaries (build-dev/base, carried as base.tar.xz), back to back.
# Writes $OUT/contact.txt (the table) and logs. Usage: tools/device_contact.sh [parity|liao|pmma|cost]...
set -uo pipefail
parts=("$@")
[[ ${#parts[@]} -eq 0 ]] && parts=(parity liao pmma cost)
WORK_NAME=seaspring_dev_contact TABLE_NAME=contact.txt
# shellcheck source=tools/device_env.sh
source "$(dirname "${BASH_SOURCE[0]}")/device_env.sh"
with_contact() {  # definition in, definition out: VcpmContact 1 (and friction) added
  sed 's|<parameters>|<parameters><parameter key="VcpmContact" value="1" /><parameter key="VcpmContactFriction" value="0.3" />|' "$1" >"$2"
}

if want parity; then
  echo "== parity (contact on; the freezing beam)" | tee -a "$table"
  "$bin/gencase" "$root/tests/data/phases/ContactBlocks2D_Def.xml" "$work/blocks" >/dev/null
  parity contact_blocks2d "$work/blocks" 3000
  with_contact "$root/cases/pmma_collapse2d/PmmaCollapse2D_Def.xml" "$work/PmmaC_Def.xml"
  "$bin/gencase" "$work/PmmaC_Def.xml" "$work/pmmac" >/dev/null
  parity pmma2d_contact "$work/pmmac" 800
  sed 's|mkclamp="0" density="2500" youngmod="3e6" poissratio="0.3" damping="1"|density="2500" youngmod="3e5" poissratio="0.3"|' \
    "$root/cases/hanging_beam/HangingBeam_Def.xml" >"$work/Fall_Def.xml"
  "$bin/gencase" "$work/Fall_Def.xml" "$work/fall" >/dev/null
  parity beam_falls_and_freezes "$work/fall" 400000 -tmax:0.5
fi

lowest_solid() {  # OUTDIR: the lowest solid particle over all part files, and when
  "$py" - "$1" <<'EOF'
import glob, sys, h5py, numpy as np
best, floor, n = (1e9, -1.0), None, 0
for f in sorted(glob.glob(sys.argv[1] + "/data/part_*.h5")):
    with h5py.File(f, "r") as h:
        t = float(h.attrs["time"])
        typ = h["type"][...].ravel()
        pos = h["pos"][...].reshape(-1, 3)
        if floor is None:  # the floor's top row: the highest fixed particle at or below z = 0
            zf = pos[(typ == 0) & (pos[:, 2] <= 1e-9)][:, 2]
            floor = float(zf.max())
        z = pos[typ == 2][:, 2]
        n += 1
        if z.size and z.min() < best[0]:
            best = (float(z.min()), t)
print("%.6f m at t=%.3f s (floor's top row z=%.6f; %d part files)%s" % (best[0], best[1], floor, n,
      "  CROSSED THE FLOOR" if best[0] < floor else ""))
EOF
}

if want liao; then
  echo "== Liao 2015 plate, dp 2 mm (2 particles thick), GPU, without and with contact" | tee -a "$table"
  cp "$root/cases/liao2015_plate/DambreakGateTimeSeries.csv" "$work/"
  cp "$root/cases/liao2015_plate/Liao2015Plate2D_Def.xml" "$work/Liao_Def.xml"
  with_contact "$root/cases/liao2015_plate/Liao2015Plate2D_Def.xml" "$work/LiaoC_Def.xml"
  for c in liao liaoc; do
    def="$work/Liao_Def.xml"; [[ $c == liaoc ]] && def="$work/LiaoC_Def.xml"
    "$bin/gencase" "$def" "$work/$c" -dp:0.002 >"$work/${c}_gencase.log" 2>&1 || { echo "gencase failed"; tail -2 "$work/${c}_gencase.log"; }
    start=$(date +%s)
    "$bin/seaspring" -gpu -overwrite -tmax:0.45 -tout:0.005 -progress:0 "$work/$c" "$work/o_$c" >"$work/$c.log" 2>&1
    echo "  $c: rc=$? wall $(( $(date +%s) - start )) s; $(grep -E 'Stopped|Finished' "$work/$c.log" | head -1)" | tee -a "$table"
    echo "  $c: lowest plate particle $(lowest_solid "$work/o_$c")" | tee -a "$table"
  done
  grep -E "contact:|Solids:" "$work/liaoc.log" | sed 's/^/  /' | tee -a "$table"
fi

close_pairs() {  # OUTDIR DP: solid particle pairs closer than dp/2 in the last part file
  "$py" - "$1" "$2" <<'EOF'
import glob, sys, h5py, numpy as np
f = sorted(glob.glob(sys.argv[1] + "/data/part_*.h5"))[-1]
dp = float(sys.argv[2])
with h5py.File(f, "r") as h:
    typ = h["type"][...].ravel()
    pos = h["pos"][...].reshape(-1, 3)[typ == 2]
n, close, best = len(pos), 0, 1e9
for i in range(0, n, 512):
    d = np.sqrt(((pos[i:i + 512, None, :] - pos[None, :, :]) ** 2).sum(-1))
    for k in range(d.shape[0]):
        d[k, i + k] = 1e9
    close += int((d < 0.5 * dp).sum())
    best = min(best, float(d.min()))
print("%d solid particles, %d pairs closer than dp/2, closest %.3f dp (%s)" % (n, close // 2, best / dp, f.split("/")[-1]))
EOF
}

if want pmma; then
  echo "== PMMA collapse 2D to 3 s, GPU: fragments" | tee -a "$table"
  "$bin/gencase" "$root/cases/pmma_collapse2d/PmmaCollapse2D_Def.xml" "$work/pmma" >/dev/null
  [[ -f "$work/pmmac.h5" ]] || { with_contact "$root/cases/pmma_collapse2d/PmmaCollapse2D_Def.xml" "$work/PmmaC_Def.xml"; "$bin/gencase" "$work/PmmaC_Def.xml" "$work/pmmac" >/dev/null; }
  for c in pmma pmmac; do
    start=$(date +%s)
    "$bin/seaspring" -gpu -overwrite -tmax:3 -tout:0.5 -progress:0 "$work/$c" "$work/o_$c" >"$work/$c.log" 2>&1
    echo "  $c: rc=$? wall $(( $(date +%s) - start )) s; $(grep -o '[0-9]* broken' "$work/$c.log" | head -1) ; $(close_pairs "$work/o_$c" 1.0)" | tee -a "$table"
  done
fi

if want cost; then
  echo "== cost of the per-step solid checks (Antoci gate 2D, 4000 steps, GPU, back to back)" | tee -a "$table"
  [[ -d "$root/build-dev/base" ]] || tar -xJf "$root/build-dev/base.tar.xz" -C "$root/build-dev"
  for b in base bin; do  # each build's own gencase: the resolved case lists its parameters
    "$root/build-dev/$b/gencase" "$root/cases/antoci_gate2d/AntociGate2D_Def.xml" "$work/ant_$b" >/dev/null
  done
  for r in 1 2; do
    for b in base bin; do
      "$root/build-dev/$b/seaspring" -gpu -overwrite -nsteps:4000 -sv:none -progress:0 "$work/ant_$b" "$work/o_ant_$b" >"$work/ant_$b.log" 2>&1
      echo "  $b run $r: $(grep -o 'in [0-9.]* s wall (loop [0-9.]* s)' "$work/ant_$b.log") $(grep -o 'State hash: [0-9a-f]*' "$work/ant_$b.log")" | tee -a "$table"
    done
  done
fi
(cd "$work" && tar czf "$out/logs.tgz" ./*.log) 2>/dev/null
cat "$table"
