"""SeaSpring validation: case specs, runs, metrics, plots and the report (tools/validate.py).

Modules: spec (cases/<name>/validation.json), series (gauge, reference and part-file series),
metrics (peak, peak_time, rms, mean, convergence order), runner (gencase + seaspring),
plots (matplotlib), report (docs/validation/*.md), paraview (tools/paraview_check.py).
Needs numpy, h5py and matplotlib from Debian (run with /usr/bin/python3). Schema and usage:
docs/validation.md.
"""
import os

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
