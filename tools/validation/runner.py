"""Generates and runs one case at one resolution: gencase, seaspring, run.json.

Layout: OUT/<case>/<resolution>/ holds NAME.xml and NAME.h5 (gencase), the run's part files,
gauges/, run.json, and the logs gencase.log and seaspring.log.
"""
import json
import os
import shutil
import subprocess
import time


def case_stem(xml):
    """DualSPHysics naming: Foo_Def.xml -> Foo."""
    stem = os.path.splitext(os.path.basename(xml))[0]
    return stem[:-4] if stem.endswith("_Def") else stem


def _last_lines(path, n=3):
    try:
        with open(path, encoding="utf-8", errors="replace") as f:
            lines = [ln.strip() for ln in f if ln.strip() and not ln.startswith("$ ")]
    except OSError:
        return ""
    return " | ".join(lines[-n:])


def _env(bin_dir):
    env = dict(os.environ)
    lib = os.path.join(os.path.dirname(os.path.abspath(bin_dir)), "lib")
    if os.path.isdir(lib):      # device builds carry their shared libraries (tools/device_build.sh)
        env["LD_LIBRARY_PATH"] = lib + os.pathsep + env.get("LD_LIBRARY_PATH", "")
    return env


def _call(cmd, log_path, timeout, env):
    """Runs CMD with its output in LOG_PATH. Returns (ok, reason, seconds)."""
    t0 = time.monotonic()
    with open(log_path, "w", encoding="utf-8") as log:
        log.write("$ " + " ".join(cmd) + "\n")
        log.flush()
        try:
            proc = subprocess.run(cmd, stdout=log, stderr=subprocess.STDOUT, timeout=timeout, env=env)
        except FileNotFoundError:
            return False, f"{cmd[0]}: not found (build it, or pass --bin DIR)", 0.0
        except subprocess.TimeoutExpired:
            return False, f"{os.path.basename(cmd[0])}: timed out after {timeout:g} s", time.monotonic() - t0
    dt = time.monotonic() - t0
    if proc.returncode != 0:
        return False, (f"{os.path.basename(cmd[0])} exited with {proc.returncode}: "
                       f"{_last_lines(log_path)} (log: {log_path})"), dt
    return True, "", dt


def read_run_json(path):
    """The fields of run.json the report uses (either naming: wall_time_s or wall_time,
    particles.total or np)."""
    with open(path, encoding="utf-8") as f:
        j = json.load(f)
    parts = j.get("particles")
    np_ = j.get("np", parts.get("total") if isinstance(parts, dict) else parts)
    return {"wall_time_s": j.get("wall_time_s", j.get("wall_time")), "particles": np_,
            "device": j.get("device"), "backend": j.get("backend"), "threads": j.get("threads"),
            "steps": j.get("steps"), "state_hash": j.get("state_hash"),
            "physical_time_s": j.get("physical_time_s"), "stop_reason": j.get("stop_reason"),
            "ns_per_particle_step": j.get("ns_per_particle_step")}


def commands(spec, res, opts, rundir):
    name = case_stem(spec.xml)
    gen = [os.path.join(opts.bin, "gencase"), spec.xml_path, os.path.join(rundir, name), f"-dp:{res.dp:g}"]
    run = [os.path.join(opts.bin, "seaspring")] + (["-" + opts.backend] if opts.backend else [])
    if opts.backend != "gpu" and opts.threads:
        run.append(f"-threads:{opts.threads}")
    run += [f"-tmax:{res.tmax:g}", "-sv:h5,vtk" if opts.vtk else "-sv:h5", "-progress:0"]
    if res.tout:
        run.append(f"-tout:{res.tout:g}")
    run += list(res.args) + [os.path.join(rundir, name), rundir]
    return gen, run


def run_resolution(spec, res, opts, say=print):
    """Runs SPEC at resolution RES (unless opts.reuse finds a finished run). Returns a record:
    resolution, dp, tmax, rundir, ok, reason, run.json fields, total_time_s."""
    rundir = os.path.join(os.path.abspath(opts.out), spec.name, res.name)
    rec = {"resolution": res.name, "dp": res.dp, "tmax": res.tmax, "rundir": rundir,
           "ok": False, "reason": ""}
    gen, run = commands(spec, res, opts, rundir)
    rec["commands"] = [" ".join(gen), " ".join(run)]
    rj = os.path.join(rundir, "run.json")
    if opts.dry_run:
        say("  " + rec["commands"][0] + "\n  " + rec["commands"][1])
        rec["reason"] = "dry run"
        return rec
    if opts.reuse and os.path.isfile(rj):
        say(f"  {res.name}: reusing {rj}")
    else:
        if opts.reuse:
            say(f"  {res.name}: no {rj}, running")
        if os.path.isdir(rundir):
            shutil.rmtree(rundir)
        os.makedirs(rundir)
        timeout = res.timeout or opts.timeout
        env = _env(opts.bin)
        say(f"  {res.name}: gencase dp={res.dp:g}")
        ok, why, t_gen = _call(gen, os.path.join(rundir, "gencase.log"), timeout, env)
        if ok:
            say(f"  {res.name}: seaspring {opts.backend or ''} tmax={res.tmax:g}")
            ok, why, t_run = _call(run, os.path.join(rundir, "seaspring.log"), timeout, env)
            rec["total_time_s"] = t_gen + t_run
        if not ok:
            rec["reason"] = why
            return rec
    try:
        rec.update(read_run_json(rj))
    except (OSError, ValueError) as e:
        rec["reason"] = f"{rj}: cannot read run.json ({e})"
        return rec
    pt = rec.get("physical_time_s")
    if pt is not None and pt < res.tmax * (1 - 1e-6):
        rec["reason"] = f"stopped at t = {pt:.4g} s before tmax {res.tmax:g} s ({rec.get('stop_reason')})"
        return rec
    rec["ok"] = True
    return rec
