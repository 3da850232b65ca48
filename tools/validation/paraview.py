"""Runs tools/paraview_check.py with ParaView's pvpython (under xvfb-run when there is no
display) on a run folder, to check what ParaView reads and render the case's picture."""
import os
import shutil
import subprocess

from . import ROOT


def pvpython_command():
    """The command prefix, or None (with the reason) when pvpython is missing."""
    pv = shutil.which("pvpython")
    if not pv:
        return None, "pvpython not found (Debian: apt-get install paraview python3-paraview xvfb xauth)"
    if not os.environ.get("DISPLAY"):
        xvfb = shutil.which("xvfb-run")
        if not xvfb:
            return None, "no DISPLAY and no xvfb-run (Debian: xvfb xauth)"
        return [xvfb, "-a", "-s", "-screen 0 1920x1200x24", pv], ""
    return [pv], ""


def run_pvpython(cmd, timeout=300):
    """Runs a pvpython command (output captured as text), again up to twice when xvfb-run -a
    lost the race for an X server to another one starting on this machine."""
    for _ in range(3):
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
        if p.returncode == 0 or "bad X server connection" not in p.stdout + p.stderr:
            break
    return p


def seaspring_binaries():
    """(gencase, seaspring, seaspring-post, None), or (None, None, None, why) when one is missing:
    SEASPRING_BIN names their folder (default build/bin), SEASPRING_POST seaspring-post."""
    bindir = os.environ.get("SEASPRING_BIN", os.path.join(ROOT, "build", "bin"))
    gencase, seaspring = (os.path.join(bindir, b) for b in ("gencase", "seaspring"))
    post = os.environ.get("SEASPRING_POST") or os.path.join(bindir, "seaspring-post")
    if not all(os.access(b, os.X_OK) for b in (gencase, seaspring, post)):
        return None, None, None, f"no gencase/seaspring/seaspring-post in {bindir} (set SEASPRING_BIN)"
    return gencase, seaspring, post, None


def run_still_tank(gencase, seaspring, tmp):
    """The 2D still tank of tests/data/gauges run for 0.2 s on 2 CPU threads into TMP/run (part
    files at 0, 0.1 and 0.2 s); returns the run folder."""
    xml = os.path.join(ROOT, "tests", "data", "gauges", "StillTank_Def.xml")
    case, run = os.path.join(tmp, "StillTank"), os.path.join(tmp, "run")
    subprocess.run([gencase, xml, case], check=True, stdout=subprocess.DEVNULL, timeout=120)
    subprocess.run([seaspring, "-cpu", "-threads:2", "-tmax:0.2", "-tout:0.1", "-quiet", case, run],
                   check=True, stdout=subprocess.DEVNULL, timeout=300)
    return run


def render(rundir, png, title, time=None, timeout=600):
    """Checks RUNDIR's parts.xdmf and vtk/*.vtu with ParaView and renders PNG. Returns
    (ok, message)."""
    prefix, why = pvpython_command()
    if prefix is None:
        return None, why
    script = os.path.join(ROOT, "tools", "paraview_check.py")
    cmd = prefix + [script, rundir, "--png", os.path.abspath(png), "--title", title]
    if time is not None:
        cmd += ["--time", f"{time:g}"]
    log = os.path.join(rundir, "paraview.log")
    for attempt in range(3):        # xvfb-run -a can race with another X server starting
        with open(log, "w", encoding="utf-8") as f:
            f.write("$ " + " ".join(cmd) + "\n")
            f.flush()
            try:
                p = subprocess.run(cmd, stdout=f, stderr=subprocess.STDOUT, timeout=timeout)
            except subprocess.TimeoutExpired:
                return False, f"pvpython timed out after {timeout} s (log: {log})"
        with open(log, encoding="utf-8", errors="replace") as f:
            lines = [ln.strip() for ln in f if ln.strip() and not ln.startswith("$ ")]
        if p.returncode == 0 or not any("bad X server connection" in ln for ln in lines):
            break
    summary = [ln for ln in lines if ln.startswith(("xdmf:", "vtu:", "picture:", "FAIL"))]
    if p.returncode != 0 and not any(ln.startswith("FAIL") for ln in summary):
        err = [ln for ln in lines if "ERR|" in ln or "Error" in ln]
        summary.append(f"pvpython exited with {p.returncode}" + (f": {err[-1][-160:]}" if err else "") + f" (log: {log})")
    msg = "; ".join(summary) or " | ".join(lines[-3:])
    return p.returncode == 0, msg
