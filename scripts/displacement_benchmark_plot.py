#!/usr/bin/python3
"""Turns BenchDisplacementMapFilter's JSON into the BENCHMARKS.md tables and a plot.

    build/bin/BenchDisplacementMapFilter --benchmark_repetitions=5 \
        --benchmark_report_aggregates_only=true \
        --benchmark_out=displacement.json --benchmark_out_format=json
    /usr/bin/python3 scripts/displacement_benchmark_plot.py displacement.json \
        Documentation/displacement_time_vs_error.png

Prints three Markdown tables (wall time against the VTK chain; single-thread CPU time
against it; run time and error per normal mode and resolution) and draws normal-angle error against run time, one line per mode
(needs python3-matplotlib).
"""

import json
import re
import sys

MODES = {"0": "VTK chain", "1": "Approximate", "2": "Exact", "3": "Mesh"}


def load(path):
    with open(path) as f:
        data = json.load(f)
    rows = {}
    for b in data["benchmarks"]:
        if b.get("aggregate_name") != "median":
            continue
        m = re.match(r"BM_(\w+)/U:(\d+)/mode:(\d+)/threads:(\d+)", b["run_name"])
        if not m:
            continue
        kind, u, mode, threads = m.group(1), int(m.group(2)), m.group(3), m.group(4)
        label = "VTK chain" if kind == "VTKChain" else MODES[mode]
        if kind != "VTKChain" and threads == "1":
            label += " (1 thread)"
        rows[(label, u)] = {
            "ms": b["real_time"],
            "cpu": b["cpu_time"],
            "points": int(b["points"]),
            "angle": b["angle_deg"],
            "position": b["position"],
        }
    return data.get("context", {}), rows


def main():
    context, rows = load(sys.argv[1])
    sizes = sorted({u for (_, u) in rows})
    labels = ["Approximate", "Exact", "Mesh", "Approximate (1 thread)", "Exact (1 thread)",
              "Mesh (1 thread)", "VTK chain"]

    print("Machine: %s cores, %s; load average at start %s\n" % (
        context.get("num_cpus"), context.get("mhz_per_cpu"), context.get("load_avg")))
    print("| points | VTK chain (ms) | " + " | ".join("%s (ms) | x" % l for l in labels[:6]) + " |")
    print("|---:|---:|" + "---:|---:|" * 6)
    for u in sizes:
        chain = rows.get(("VTK chain", u))
        if not chain:
            continue
        cells = ["%d" % chain["points"], "%.1f" % chain["ms"]]
        for label in labels[:6]:
            r = rows.get((label, u))
            cells += ["%.1f" % r["ms"], "%.1f" % (chain["ms"] / r["ms"])] if r else ["", ""]
        print("| " + " | ".join(cells) + " |")

    # Single-thread CPU time, which the other users of a shared machine disturb least.
    one = ["Approximate (1 thread)", "Exact (1 thread)", "Mesh (1 thread)"]
    print("\n| points | VTK chain CPU (ms) | " +
          " | ".join("%s CPU (ms) | x" % l.replace(" (1 thread)", "") for l in one) + " |")
    print("|---:|---:|" + "---:|---:|" * 3)
    for u in sizes:
        chain = rows.get(("VTK chain", u))
        if not chain:
            continue
        cells = ["%d" % chain["points"], "%.1f" % chain["cpu"]]
        for label in one:
            r = rows.get((label, u))
            cells += ["%.1f" % r["cpu"], "%.1f" % (chain["cpu"] / r["cpu"])] if r else ["", ""]
        print("| " + " | ".join(cells) + " |")

    print("\n| method | points | time (ms) | max normal error (deg) | max vertex error |")
    print("|---|---:|---:|---:|---:|")
    for label in labels:
        for u in sizes:
            r = rows.get((label, u))
            if r:
                print("| %s | %d | %.2f | %.3g | %.3g |" % (
                    label, r["points"], r["ms"], r["angle"], r["position"]))

    if len(sys.argv) > 2:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(7, 4.5), dpi=120)
        # One line per normal mode at the default thread count, and the VTK chain.
        for label, marker in zip(["Approximate", "Exact", "Mesh", "VTK chain"], "osDx"):
            pts = [rows[(label, u)] for u in sizes if (label, u) in rows]
            ax.loglog([p["ms"] for p in pts], [p["angle"] for p in pts], marker=marker,
                      label=label)
            for p in pts:
                ax.annotate("%dk" % round(p["points"] / 1000), (p["ms"], p["angle"]),
                            fontsize=7, xytext=(3, 3), textcoords="offset points")
        ax.set_xlabel("run time (ms, median of 5)")
        ax.set_ylabel("max normal angle error (degrees)")
        ax.set_title("Displaced torus: run time against normal error (labels: points)")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend()
        fig.tight_layout()
        fig.savefig(sys.argv[2])


if __name__ == "__main__":
    main()
