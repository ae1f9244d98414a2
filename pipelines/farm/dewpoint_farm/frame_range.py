"""Frame indices: the scene's frames, a requested A-B range, Slurm's list syntax."""
import math


class UsageError(Exception):
    """A bad argument or input file; the message names it."""


def parse_frame_range(text):
    """'A-B', 'A-' or 'A' -> (first, last or None), as the executables read --frames."""
    first, sep, last = text.partition("-")
    try:
        lo = int(first)
        hi = (int(last) if last else None) if sep else lo
    except ValueError:
        raise UsageError(f"--frames: expected A-B, A- or A with whole numbers, found '{text}'") from None
    if lo < 0 or (hi is not None and hi < lo):
        raise UsageError(f"--frames: expected 0 <= A <= B, found '{text}'")
    return lo, hi


def scene_last_frame(scene, scene_file):
    """The last frame dewpoint-simulate writes for a scene document: the
    frame at duration_s, frames being 1/frame_rate_hz apart from frame 0."""
    sim = scene.get("simulation") if isinstance(scene, dict) else None
    if not isinstance(sim, dict):
        raise UsageError(f"{scene_file}: key 'simulation': expected an object")
    values = {}
    for key in ("duration_s", "frame_rate_hz"):
        value = sim.get(key)
        if not isinstance(value, (int, float)) or isinstance(value, bool) or value <= 0:
            raise UsageError(f"{scene_file}: key 'simulation.{key}': expected a positive number, found {value!r}")
        values[key] = value
    # The same rounding as simulate/main.cpp, so both agree on the last frame.
    return math.floor(values["duration_s"] * values["frame_rate_hz"] + 1e-9)


def frames_to_process(scene_last, requested):
    """The requested range clipped to the scene's frames."""
    first, last = requested if requested else (0, None)
    last = scene_last if last is None else min(last, scene_last)
    if first > last:
        raise UsageError(f"--frames: first frame {first} is past the scene's last frame {scene_last}")
    return list(range(first, last + 1))


def slurm_index_list(indices):
    """[1, 2, 3, 7] -> '1-3,7' (sbatch --array syntax)."""
    parts = []
    run_start = prev = None
    for i in sorted(indices):
        if prev is not None and i == prev + 1:
            prev = i
            continue
        if run_start is not None:
            parts.append(str(run_start) if run_start == prev else f"{run_start}-{prev}")
        run_start = prev = i
    if run_start is not None:
        parts.append(str(run_start) if run_start == prev else f"{run_start}-{prev}")
    return ",".join(parts)
