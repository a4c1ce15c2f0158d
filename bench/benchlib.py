"""Helpers shared by the benchmark scripts: machine facts, status files, fitted exponents."""
import datetime
import math
import os
import platform
import subprocess

def read_status(path):
    """status.txt as a dict of text values."""
    status = {}
    with open(path) as f:
        for line in f:
            if "=" in line:
                k, v = line.split("=", 1)
                status[k.strip()] = v.strip()
    return status


def fit_exponent(rows, key, min_n=100):
    """Least-squares exponent b of rows[key] ~ elements^b over the rows with
    elements >= min_n (failed runs left out)."""
    pts = [(math.log(r["elements"]), math.log(r[key])) for r in rows
           if r["elements"] >= min_n and not r["failed"] and r[key] > 0]
    if len(pts) < 2:
        return float("nan")
    mx = sum(p[0] for p in pts) / len(pts)
    my = sum(p[1] for p in pts) / len(pts)
    sxx = sum((p[0] - mx) ** 2 for p in pts)
    sxy = sum((p[0] - mx) * (p[1] - my) for p in pts)
    return sxy / sxx


def machine_facts(rodyn, load_average=False):
    """Machine and versions a measurement was taken on."""
    cpu = "unknown"
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    cpu = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass

    def cmd(args):
        try:
            r = subprocess.run(args, capture_output=True, text=True)
            return (r.stdout or r.stderr).strip().splitlines()[0]
        except (OSError, IndexError):
            return "unknown"
    facts = {
        "date": datetime.datetime.now().astimezone().strftime("%Y-%m-%d %H:%M %Z"),
        "cpu": cpu,
        "cores": str(os.cpu_count()),
        "os": f"{platform.system()} {platform.release()}",
        "rodyn": cmd([rodyn, "--version"]),
        "gfortran": cmd(["gfortran", "--version"]),
    }
    if load_average:
        facts["load average before the run (1/5/15 min)"] = " / ".join(
            f"{x:.2f}" for x in os.getloadavg())
    return facts
