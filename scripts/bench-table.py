#!/usr/bin/env python3
"""Turns Google Benchmark JSON (--benchmark_format=json) into the markdown table of
docs/performance.md: one row per benchmark family, one column per frame, median ms."""
import json
import sys
from collections import OrderedDict


def main(path):
    with open(path) as f:
        data = json.load(f)
    rows = OrderedDict()
    frames = []
    for b in data["benchmarks"]:
        if b.get("run_type") == "aggregate" and b.get("aggregate_name") != "median":
            continue
        family = b["name"].split("/")[0]
        label = b.get("label", b["name"].split("/")[-1].split("_")[0])
        if label not in frames:
            frames.append(label)
        ms = b["real_time"] if b.get("time_unit") == "ms" else b["real_time"] / 1e6
        extra = {k: v for k, v in b.items() if k in ("planes", "coverage", "median_err_deg", "detected")}
        rows.setdefault(family, {})[label] = (ms, extra)
    ctx = data.get("context", {})
    print(f"Measured {ctx.get('date', '?')} on {ctx.get('num_cpus', '?')} CPUs at "
          f"{ctx.get('mhz_per_cpu', '?')} MHz, load average {ctx.get('load_avg', '?')}; "
          f"median ms per VGA frame, one thread.\n")
    print("| stage | " + " | ".join(frames) + " |")
    print("|---|" + "---|" * len(frames))
    for family, cells in rows.items():
        out = []
        for fr in frames:
            if fr not in cells:
                out.append("")
                continue
            ms, extra = cells[fr]
            note = ", ".join(f"{k} {v:.3g}" for k, v in extra.items())
            out.append(f"{ms:.2f}" + (f" ({note})" if note else ""))
        print(f"| {family} | " + " | ".join(out) + " |")


if __name__ == "__main__":
    main(sys.argv[1])
