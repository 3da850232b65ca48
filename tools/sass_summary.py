#!/usr/bin/env python3
"""Summarises Nsight Compute's SASS source page (tools/device_sass.sh's sass.csv): executed warp
instructions by opcode, their thread instructions, and the share of each opcode class.
Usage: sass_summary.py sass.csv [top]"""
import csv
import sys
from collections import Counter


def main():
    path = sys.argv[1]
    top = int(sys.argv[2]) if len(sys.argv) > 2 else 30
    lines = open(path, newline="").read().splitlines()
    # Nsight Compute writes a "Kernel Name" line before the header (the line naming "Source").
    start = next((i for i, l in enumerate(lines) if '"Source"' in l), 0)
    rows = list(csv.DictReader(lines[start:]))
    if not rows:
        sys.exit(f"{path}: no rows")
    keys = rows[0].keys()
    src = next(k for k in keys if k.strip().lower() == "source")
    warp = next((k for k in keys if "Instructions Executed" in k and "Thread" not in k and "Predicated" not in k), None)
    thr = next((k for k in keys if "Thread Instructions Executed" in k and "Predicated" not in k), None)
    if warp is None:
        sys.exit(f"{path}: no executed-instruction column among {list(keys)}")
    byop, byop_t = Counter(), Counter()
    total = total_t = 0
    for r in rows:
        text = r[src].strip()
        if not text:
            continue
        op = text.split()[0]
        if op.startswith("@"):
            op = text.split()[1]
        op = op.split(".")[0]
        try:
            n = float(r[warp].replace(",", "") or 0)
            t = float(r[thr].replace(",", "") or 0) if thr else 0.0
        except ValueError:
            continue
        byop[op] += n
        byop_t[op] += t
        total += n
        total_t += t
    print(f"warp instructions {total:.4g}, thread instructions {total_t:.4g}, "
          f"active lanes {total_t / total if total else 0:.2f}")
    for op, n in byop.most_common(top):
        print(f"{op:10s} {n:12.4g} {100 * n / total:6.2f}%  lanes {byop_t[op] / n if n else 0:5.2f}")


if __name__ == "__main__":
    main()
