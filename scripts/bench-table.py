#!/usr/bin/env python3
"""Turns Google Benchmark JSON (tunnelmap_bench --benchmark_format=json, with repetitions) into
the markdown of docs/performance.md: a peer table (TunnelMap vs PCL vs OpenCV per frame: median
ms, ratio peer / TunnelMap, plane recall and precision on simulated frames) and the full
stage-by-stage table. Times are the median over repetitions of CPU time (the benchmarks are
single-threaded, so on a quiet machine this equals wall time, and on a busy one it is the
steadier figure); pass --real-time for wall time."""
import argparse
import json
from collections import OrderedDict

# (column title, benchmark family) for the peer table; the first is the reference.
PEERS = [
    ("TunnelMap plane extraction (default, 8 px cells)", "BM_PlaneExtraction"),
    ("TunnelMap detection (default)", "BM_Detection"),
    ("TunnelMap plane extraction without the edge-on pass", "BM_PlaneExtractionNoEdgeOnPass"),
    ("TunnelMap pixel-grid plane extraction (grow.cell_px=0)", "BM_PlaneExtractionPixelGrid"),
    ("TunnelMap pixel-grid detection", "BM_DetectionPixelGrid"),
    ("TunnelMap every-pixel plane extraction (grid step 1)", "BM_PlaneExtractionEveryPixel"),
    ("TunnelMap every-pixel detection", "BM_DetectionEveryPixel"),
    ("PCL IINE + OMPS", "BM_PclTotal"),
    ("OpenCV FALS + RgbdPlane", "BM_OpenCvTotal_FALS"),
    ("OpenCV FALS + RgbdPlane incl. depthTo3d", "BM_OpenCvTotalWithCloud_FALS"),
    ("OpenCV SRI + RgbdPlane", "BM_OpenCvTotal_SRI"),
]
REFERENCE = "BM_PlaneExtraction"
# Keys of a Google Benchmark JSON entry that are not user counters.
NOT_COUNTERS = {"name", "family_index", "per_family_instance_index", "run_name", "run_type",
                "repetitions", "repetition_index", "threads", "aggregate_name", "aggregate_unit",
                "iterations", "real_time", "cpu_time", "time_unit", "label", "error_occurred",
                "error_message"}


def load(path, real_time):
    """Per-frame benchmarks (labelled with the frame name) go to `rows`; the others (e.g.
    BM_Sequence, whole sequences on several threads, timed in wall time) to `others`."""
    with open(path) as f:
        data = json.load(f)
    rows = OrderedDict()  # family -> frame -> (ms, counters)
    others = OrderedDict()  # run name -> (ms, counters)
    frames = []
    for b in data["benchmarks"]:
        if b.get("run_type") == "aggregate" and b.get("aggregate_name") != "median":
            continue
        run_name = b.get("run_name", b["name"])
        wall = real_time or "/real_time" in run_name  # UseRealTime() benchmarks
        t = b["real_time"] if wall else b["cpu_time"]
        scale = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}[b.get("time_unit", "ns")]
        counters = {k: b[k] for k in b if k not in NOT_COUNTERS}
        if not b.get("label"):
            others[run_name] = (t * scale, counters)
            continue
        label = b["label"]
        if label not in frames:
            frames.append(label)
        rows.setdefault(run_name.split("/")[0], {})[label] = (t * scale, counters)
    return data.get("context", {}), rows, others, frames


def quality(counters):
    if "recall" not in counters:
        return ""
    return f" · R {counters['recall']:.2f} P {counters['precision']:.2f}"


def peer_table(rows, frames):
    present = [(title, fam) for title, fam in PEERS if fam in rows]
    print("| frame | " + " | ".join(t for t, _ in present) + " |")
    print("|---|" + "---|" * len(present))
    for fr in frames:
        ref = rows.get(REFERENCE, {}).get(fr)
        cells = []
        for _, fam in present:
            cell = rows[fam].get(fr)
            if cell is None:
                cells.append("")
                continue
            ms, counters = cell
            text = f"{ms:.1f} ms"
            if fam != REFERENCE and ref and ref[0] > 0 and not fam.startswith("BM_Detection"):
                text += f" ({ms / ref[0]:.2f}×)"
            if not fam.startswith("BM_Detection"):
                text += quality(counters)
            cells.append(text)
        print(f"| {fr} | " + " | ".join(cells) + " |")


def stage_table(rows, frames):
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


def other_table(others):
    print("| benchmark | ms per run (wall) | counters |")
    print("|---|---|---|")
    for name, (ms, extra) in others.items():
        note = ", ".join(f"{k} {v:.3g}" for k, v in extra.items())
        print(f"| {name} | {ms:.1f} | {note} |")


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("json")
    ap.add_argument("--real-time", action="store_true", help="wall time instead of CPU time")
    args = ap.parse_args()
    ctx, rows, others, frames = load(args.json, args.real_time)
    reps = ctx.get("executable", "tunnelmap_bench").split("/")[-1]
    kind = "wall" if args.real_time else "CPU"
    print(f"Measured {ctx.get('date', '?')} by {reps} on {ctx.get('num_cpus', '?')} CPUs at "
          f"{ctx.get('mhz_per_cpu', '?')} MHz, load average "
          f"{', '.join(f'{x:.2f}' for x in ctx.get('load_avg', []))}; median {kind} ms per VGA "
          f"frame over the repetitions, one thread (OpenCV threads "
          f"{ctx.get('opencv_threads', '?')}, OMP_NUM_THREADS=1).\n")
    print("**TunnelMap vs PCL vs OpenCV.** (N×) = ms / TunnelMap's default plane-extraction ms; "
          "R / P = plane recall / precision against the simulator's true surfaces "
          "(simulated frames only).\n")
    peer_table(rows, frames)
    print("\n**Every benchmark, stage by stage** (median ms; counters in brackets).\n")
    stage_table(rows, frames)
    if others:
        print("\n**Other benchmarks** (median over the repetitions; wall time).\n")
        other_table(others)


if __name__ == "__main__":
    main()
