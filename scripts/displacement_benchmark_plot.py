#!/usr/bin/python3
"""Turns BenchDisplacementMapFilter's JSON into the BENCHMARKS.md table and a plot.

    build/bin/BenchDisplacementMapFilter --benchmark_repetitions=5 \
        --benchmark_report_aggregates_only=true \
        --benchmark_out=displacement.json --benchmark_out_format=json
    /usr/bin/python3 scripts/displacement_benchmark_plot.py displacement.json \
        Documentation/displacement_time_vs_error.png

Prints one Markdown table: per size, the VTK chain and each normal mode and interpolation of
vtkDisplacementMapFilter, with the wall-clock time on every core (threads 0, each side's
default), the CPU time on one thread, both as ratios against the chain in the same run, for
a first execution and (where measured) a re-execution with a new Scale, and the errors
against the exact displaced surface. Then draws normal-angle error against the wall-clock
time of first executions (needs python3-matplotlib).
"""

import json
import re
import sys

MODES = {"1": "Approximate", "2": "Exact", "3": "Mesh"}
INTERPS = {"0": "Nearest", "1": "Linear", "2": "Cubic"}


def load(path):
    with open(path) as f:
        data = json.load(f)
    rows = {}
    for b in data["benchmarks"]:
        if b.get("aggregate_name") != "median":
            continue
        m = re.match(r"BM_(\w+)/U:(\d+)/mode:(\d+)/interp:(\d+)/threads:(\d+)(?:/reexec:(\d+))?",
                     b["run_name"])
        if not m:
            continue
        kind, u, mode, interp, threads, reexec = m.groups()
        method = "VTK chain" if kind == "VTKChain" else MODES[mode]
        if reexec == "1":
            threads += "r"
        rows[(method, INTERPS[interp], int(u), threads)] = {
            "wall": b["real_time"],
            "cpu": b["cpu_time"],
            "points": int(b["points"]),
            "angle": b["angle_deg"],
            "position": b["position"],
        }
    return data.get("context", {}), rows


def methods():
    yield ("VTK chain", "Linear")
    for mode in ("Approximate", "Exact", "Mesh"):
        for interp in ("Nearest", "Linear", "Cubic"):
            yield (mode, interp)


def main():
    context, rows = load(sys.argv[1])
    sizes = sorted({k[2] for k in rows})
    print("Machine: %s cores; load average at start %s\n" % (
        context.get("num_cpus"), context.get("load_avg")))
    print("| points | method | interpolation | first: wall, 2 threads (ms) | x "
          "| first: CPU, 1 thread (ms) | x | re-exec: wall, 2 threads (ms) | x "
          "| re-exec: CPU, 1 thread (ms) | x | max normal error (deg) | max vertex error |")
    print("|---:|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for u in sizes:
        chain_wall = rows.get(("VTK chain", "Linear", u, "0"))
        chain_cpu = rows.get(("VTK chain", "Linear", u, "1"))
        if not chain_wall or not chain_cpu:
            continue
        for method, interp in methods():
            wall = rows.get((method, interp, u, "0"))
            cpu = rows.get((method, interp, u, "1"))
            if not wall or not cpu:
                continue
            rwall = rows.get((method, interp, u, "0r"))
            rcpu = rows.get((method, interp, u, "1r"))
            again = "| | | | "
            if rwall and rcpu:
                again = "| %.1f | %.1f | %.1f | %.1f " % (
                    rwall["wall"], chain_wall["wall"] / rwall["wall"], rcpu["cpu"],
                    chain_cpu["cpu"] / rcpu["cpu"])
            print("| %d | %s | %s | %.1f | %.1f | %.1f | %.1f %s| %.3g | %.3g |" % (
                wall["points"], method, interp, wall["wall"], chain_wall["wall"] / wall["wall"],
                cpu["cpu"], chain_cpu["cpu"] / cpu["cpu"], again, wall["angle"],
                wall["position"]))

    if len(sys.argv) > 2:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(9.5, 5), dpi=120)
        colours = {"Approximate": "tab:blue", "Exact": "tab:orange", "Mesh": "tab:green",
                   "VTK chain": "black"}
        styles = {"Nearest": (":", "v"), "Linear": ("-", "o"), "Cubic": ("--", "s")}
        # One line per method and interpolation, on every core (each side's default).
        for method, interp in methods():
            pts = [rows[(method, interp, u, "0")] for u in sizes
                   if (method, interp, u, "0") in rows]
            if not pts:
                continue
            line, marker = styles[interp]
            label = method if method == "VTK chain" else "%s, %s" % (method, interp)
            ax.loglog([p["wall"] for p in pts], [p["angle"] for p in pts], linestyle=line,
                      marker=marker if method != "VTK chain" else "x", color=colours[method],
                      label=label, markersize=4)
            if method == "VTK chain" or (method, interp) == ("Mesh", "Linear"):
                for p in pts:
                    ax.annotate("%dk" % round(p["points"] / 1000), (p["wall"], p["angle"]),
                                fontsize=7, xytext=(3, 3), textcoords="offset points")
        ax.set_xlabel("wall-clock time of a first execution on 2 threads (ms, median of 5)")
        ax.set_ylabel("max normal angle error (degrees)")
        ax.set_title("Displaced torus: run time against normal error (labels: points)")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0))
        fig.tight_layout()
        fig.savefig(sys.argv[2])


if __name__ == "__main__":
    main()
