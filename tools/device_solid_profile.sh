#!/usr/bin/env bash
# Runs ON the GPU machine (device tool) with build-dev carried: where the solids' single-block
# sub-cycle kernel (sequenceBlockKernel) of the Antoci gate 2D spends its time. Nsight Compute
# over a few launches after the start (--cache-control none: warm caches, as in a run), its warp
# state statistics, and the SASS instructions with the most stall samples, grouped by opcode.
# Env: SS_BIN (default build-dev/bin), W (work folder, default /tmp/wsp), SKIP (launches
# skipped, default 200), COUNT (launches profiled, default 6), OUT (copies of the reports).
set -u
export LD_LIBRARY_PATH=$PWD/build-dev/lib
b=${SS_BIN:-build-dev/bin}; w=${W:-/tmp/wsp}; mkdir -p $w
nvidia-smi --query-gpu=name --format=csv,noheader
[[ -f $w/ant.h5 ]] || $b/gencase cases/antoci_gate2d/AntociGate2D_Def.xml $w/ant >/dev/null
rm -f $w/sub.ncu-rep
ncu --clock-control none --cache-control none --kernel-name regex:sequenceBlockKernel \
  --launch-skip "${SKIP:-200}" --launch-count "${COUNT:-6}" --set full --import-source no -o $w/sub \
  $b/seaspring -overwrite -gpu -sv:none -progress:0 -nsteps:300 $w/ant $w/o_p >/dev/null 2>&1
ncu -i $w/sub.ncu-rep --page details --section WarpStateStats --section LaunchStats --section Occupancy \
  --section SpeedOfLight 2>/dev/null | grep -E "Duration|Registers|Threads|Stall|Warp Cycles|Issued|Eligible|Active Warps|Elapsed|Theoretical Occ|Achieved Occ" | sort | uniq -c | head -40
ncu -i $w/sub.ncu-rep --page raw --csv 2>/dev/null | python3 -c '
import csv, sys
rows = list(csv.reader(sys.stdin))
hdr = rows[0]
want = [i for i, h in enumerate(hdr) if h.startswith("smsp__average_warp_latency_issue_stalled") or h.startswith("smsp__pcsamp_warps_issue_stalled")]
tot = {}
for r in rows[2:]:
    for i in want:
        try: tot[hdr[i]] = tot.get(hdr[i], 0.0) + float(r[i].replace(",", ""))
        except ValueError: pass
for k, v in sorted(tot.items(), key=lambda kv: -kv[1])[:14]: print("  %-70s %12.1f" % (k, v))
'
ncu -i $w/sub.ncu-rep --page source --csv --print-source sass 2>/dev/null > $w/sass.csv
python3 - "$w/sass.csv" <<'EOF'
import csv, sys, collections
rows = list(csv.reader(open(sys.argv[1], errors="replace")))
hdr = None
for i, r in enumerate(rows):
    if any("Source" == c for c in r) and any("Sampling" in c for c in r):
        hdr, body = r, rows[i + 1:]
        break
if hdr is None:
    print("no SASS table; first lines:"); [print(" ", r[:6]) for r in rows[:5]]; sys.exit()
print("  columns:", [h for h in hdr if "Sampling" in h or h.startswith("Instructions Executed")][:6])
src = hdr.index("Source")
samp = [i for i, h in enumerate(hdr) if "Sampling (All" in h] or [i for i, h in enumerate(hdr) if "Sampling" in h]
exe = [i for i, h in enumerate(hdr) if h.startswith("Instructions Executed")]
s_i = samp[0]
def num(x):
    try: return float(x.replace(",", ""))
    except ValueError: return 0.0
need = max([src, s_i] + exe[:1])
ins = []
for r in body:  # the first launch's table (the next header ends it)
    if "Source" in r: break
    if len(r) > need: ins.append((num(r[s_i]), num(r[exe[0]]) if exe else 0, r[src].strip()))
total = sum(x[0] for x in ins) or 1
print("  SASS instructions: %d, stall samples: %d, executed warp instructions: %d" % (len(ins), total, sum(x[1] for x in ins)))
by = collections.Counter()
cnt = collections.Counter()
for s, e, t in ins:
    op = t.split()[0] if t else "?"
    if op.startswith("@"): op = t.split()[1]
    op = op.split(".")[0]
    by[op] += s; cnt[op] += e
print("  by opcode (share of stall samples, executed):")
for op, s in by.most_common(18): print("    %-10s %5.1f%%  %10d" % (op, 100 * s / total, cnt[op]))
print("  top instructions:")
for k, (s, e, t) in enumerate(sorted(ins, key=lambda x: -x[0])[:30]): print("    %5.1f%%  %8d  %s" % (100 * s / total, e, t[:90]))
EOF
[[ -n "${OUT:-}" ]] && cp $w/sub.ncu-rep $w/sass.csv "$OUT/" 2>/dev/null
true
