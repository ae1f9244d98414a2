#!/usr/bin/env python3
"""Data behind the figure pipeline's plots and table (pipelines/figures.mk).

  figure_data.py assets SCENE_FILE          the meshes and images a scene names (make prerequisites)
  figure_data.py ledger FRAMES_DIR           per-frame water ledger as a gnuplot table on stdout
  figure_data.py table1 OUT.md NAME=STATS_DIR ...   our Table-1 timings next to the paper's

Python standard library only (CI installs Debian's python3).
"""
import datetime
import json
import os
import platform
import subprocess
import sys

# Paper Table 1 (Hochstetter & Kolb 2017), ms per step; None where the paper has '-'.
PAPER = {
    "drop_notex": ("Drop (no tex)", "1207", "5108", "64^3", "-", 18, 65, 2, 6, 1, 4),
    "drop": ("Drop", "1207", "5108", "64^3", "512^2", 18, 65, 11, 6, 26, 4),
    "sca_logo_tex": ("SCA Logo Tex", "-", "28 K", "64^3", "1024^2", None, 60, None, 16, 15, 5),
    "sca_logo": ("SCA Logo", "135", "28 K", "64^3", "1024^2", 13, 60, 8, 17, 31, 5),
    "glass": ("Glass", "174 K", "89 K", "64^3", "1024^2", 210, 31, 32, 23, 40, 2),
}
COLUMNS = ["Ptcl", "Grid", "Neigh", "Heat", "Eva", "dtau"]


def seconds_per_simulated_second(step_ms, dtau_ms):
    """Wall seconds per simulated second: the step's parts over the time step
    (for ours the means, so the ratio is total step time over simulated time;
    the paper gives one figure per column)."""
    if dtau_ms is None or dtau_ms <= 0 or any(v is None for v in step_ms):
        return None
    return sum(step_ms) / dtau_ms


def shot_seconds(frames_dir):
    """Simulated seconds of the scene's whole shot as its file gives it
    (without a preset): the shot and, where it settles first, the settling."""
    with open(os.path.join(frames_dir, "manifest.json")) as f:
        scene_file = json.load(f).get("scene_file")
    if not scene_file or not os.path.exists(scene_file):
        return None
    with open(scene_file) as f:
        sim = json.load(f).get("simulation", {})
    return sim.get("duration_s", 0) + sim.get("settle", {}).get("duration_s", 0)


def minutes(rate, seconds):
    return None if rate is None or seconds is None else rate * seconds / 60


def commit():
    try:
        root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
        return subprocess.run(["git", "-C", root, "rev-parse", "--short", "HEAD"], capture_output=True, text=True,
                              check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "unknown commit"


def ledger(frames_dir):
    with open(os.path.join(frames_dir, "manifest.json")) as f:
        manifest = json.load(f)
    print("# time_s liquid_kg texels_kg vapor_kg evaporated_from_liquid_kg condensed_into_texels_kg emitted_from_texels_kg drift_kg")
    for frame in manifest["frames"]:
        w = frame.get("water")
        if w is None:
            sys.exit("figure_data: %s: frame %d has no water ledger" % (frames_dir, frame["index"]))
        # texels_to_air is net: condensation into the textures makes it negative.
        print("%.6f %.9e %.9e %.9e %.9e %.9e %.9e %.3e" % (
            frame["time_s"], w["liquid_kg"], w["texels_kg"], w["vapor_kg"], w["liquid_to_air_kg"],
            -w["texels_to_air_kg"], w["texels_to_liquid_kg"], w["drift_kg"]))


def assets(scene_file):
    """The mesh and image files a scene names, in its body or any preset: its
    simulation's inputs besides the file itself (for make's prerequisites)."""
    with open(scene_file) as f:
        doc = json.load(f)
    base = os.path.dirname(os.path.abspath(scene_file))
    found = set()
    for part in [doc] + list(doc.get("presets", {}).values()):
        for rigid in part.get("simulation", {}).get("rigids", []):
            for path in (rigid.get("mesh"), rigid.get("texture", {}).get("max_mass_image")):
                if isinstance(path, str):
                    found.add(os.path.normpath(os.path.join(base, path)))
    print(" ".join(sorted(found)))


def cpu_model():
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown CPU"


def counts(frames_dir):
    """Liquid particles of the first frame, rigid particles, cells, texels."""
    with open(os.path.join(frames_dir, "manifest.json")) as f:
        m = json.load(f)
    liquid = m["frames"][0]["liquid_particles"] if m["frames"] else 0
    rigid = "?"
    with open(os.path.join(frames_dir, m["rigid_particles"]), "rb") as f:
        for raw in f:
            line = raw.decode("ascii", "replace").strip()
            if line.startswith("element vertex"):
                rigid = int(line.split()[2])
            if line == "end_header":
                break
    air = m["scene"]["simulation"].get("air")
    cells = "%d^3" % air.get("resolution", 64) if air else "-"
    texels = ", ".join("%dx%d" % tuple(r["texture_resolution"]) for r in m["rigids"]) or "-"
    return liquid, rigid, cells, texels


def fmt(v):
    return "-" if v is None else ("%.0f" % v if v >= 10 else "%.1f" % v)


def table1(out, runs, note):
    lines = ["# Table 1: run time per step (ms)", "",
             "Ours: `dewpoint-simulate --device cpu` at the paper's resolution, %d threads, %s, %s (%s), commit %s. %s" % (
                 os.cpu_count() or 0, cpu_model(), datetime.date.today().isoformat(), platform.system(), commit(), note),
             "Paper: NVIDIA GeForce GTX Titan, CUDA 8.0 (Hochstetter & Kolb 2017, Table 1).",
             "Ptcl = SPH, Grid = air, Neigh = neighbour searches, Heat = heat transfer, Eva = evaporation and "
             "condensation; medians over the timed steps; dτ in ms (ours: the median CFL step, bounded by the paper's); "
             "s/s = wall seconds per simulated second (ours: the columns' means over the mean dτ; the paper's: its "
             "columns over its dτ, a '-' column counted as 0); shot = s/s times the scene's whole shot (its "
             "duration_s and settling, in simulated seconds), in minutes.", "",
             "| Scene | | #Ptcl | #RigPtcl | #Cell | #Texel | steps | " + " | ".join(COLUMNS) + " | s/s | shot (min) |",
             "|---|---|---|---|---|---|---|" + "---|" * (len(COLUMNS) + 2)]
    for name, stats_dir in runs:
        paper = PAPER.get(name)
        with open(os.path.join(stats_dir, "stats", "timings_summary.json")) as f:
            summary = json.load(f)
        columns = summary.get("columns", {})
        ours = [columns.get(c, {}).get("median") for c in COLUMNS]
        means = [columns.get(c, {}).get("mean") for c in COLUMNS]
        ours_rate = seconds_per_simulated_second(means[:-1], means[-1])
        liquid, rigid, cells, texels = counts(os.path.join(stats_dir, "frames"))
        shot = shot_seconds(os.path.join(stats_dir, "frames"))
        label = paper[0] if paper else name
        lines.append("| %s | ours | %s | %s | %s | %s | %d | %s | %s | %s |" % (
            label, liquid, rigid, cells, texels, summary.get("steps", 0), " | ".join(fmt(v) for v in ours),
            fmt(ours_rate), fmt(minutes(ours_rate, shot))))
        if paper:
            paper_rate = seconds_per_simulated_second([v or 0 for v in paper[5:-1]], paper[-1])
            lines.append("| | paper | %s | %s | %s | %s | | %s | %s | %s |" % (
                paper[1], paper[2], paper[3], paper[4], " | ".join(fmt(v) for v in paper[5:]), fmt(paper_rate),
                fmt(minutes(paper_rate, shot))))
    with open(out, "w") as f:
        f.write("\n".join(lines) + "\n")


def main(argv):
    if len(argv) >= 2 and argv[0] == "assets":
        assets(argv[1])
    elif len(argv) >= 2 and argv[0] == "ledger":
        ledger(argv[1])
    elif len(argv) >= 3 and argv[0] == "table1":
        note = os.environ.get("TABLE1_NOTE", "")
        table1(argv[1], [a.split("=", 1) for a in argv[2:]], note)
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main(sys.argv[1:])
