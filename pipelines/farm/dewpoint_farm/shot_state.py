"""What of a shot's output folder is done and sound, frame by frame.

A stage's frame counts as done when its files are whole (PLY sizes match
their headers, EXR/PNG read to the last pixel by oiiotool, JSON parses) and
are newer than the input they were made from, as make would judge it."""
import json
import os
import subprocess
from concurrent.futures import ThreadPoolExecutor

from .ply_check import ply_element_counts


def _frame_file(kind, frame, ext):
    return f"{kind}.{frame:04d}.{ext}"


def _load_json(path):
    try:
        with open(path, encoding="utf-8") as f:
            doc = json.load(f)
        return doc if isinstance(doc, dict) else None
    except (OSError, ValueError):
        return None


def _mtime(path):
    try:
        return os.stat(path).st_mtime_ns
    except OSError:
        return None


def images_readable(*paths):
    """oiiotool reads every pixel for --printstats, so a truncated EXR or PNG
    fails here even when its header is intact (one process for all: its
    start-up costs more than reading a frame)."""
    if not all(os.path.isfile(p) for p in paths):
        return False
    command = ["oiiotool"]
    for p in paths:
        command += [p, "--printstats"]
    result = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False)
    return result.returncode == 0


def contact_sheet_file(out, frames):
    """Named after its frame range, as contact-sheet.sbatch names it."""
    return os.path.join(out, "figures", f"contact-sheet.{frames[0]:04d}-{frames[-1]:04d}.png")


class ShotState:
    """Which frames of OUT are simulated, meshed and rendered soundly."""

    def __init__(self, scene_file, out, frames):
        self.scene_file = os.path.abspath(scene_file)
        self.frames_dir = os.path.join(out, "frames")
        self.meshes_dir = os.path.join(out, "meshes")
        self.images_dir = os.path.join(out, "images")
        self.frames = frames
        self.manifest = _load_json(os.path.join(self.frames_dir, "manifest.json"))
        self.simulation_problem = self._simulation_problem()
        if self.simulation_problem is None:
            self.meshed = {f for f in frames if self._mesh_sound(f)}
            with ThreadPoolExecutor(max_workers=os.cpu_count() or 2) as pool:
                rendered = list(pool.map(self._render_sound, frames))
            self.rendered = {f for f, ok in zip(frames, rendered) if ok}
        else:
            self.meshed, self.rendered = set(), set()
        self.sheet_current = self._sheet_current(out)

    def _sheet_current(self, out):
        """The contact sheet of these frames exists, lacks no frame and is
        newer than every image on it."""
        sheet = contact_sheet_file(out, self.frames)
        if not images_readable(sheet) or os.path.exists(sheet.replace(".png", ".missing.txt")):
            return False
        if len(self.rendered) != len(self.frames):
            return False
        newest = max(_mtime(os.path.join(self.images_dir, _frame_file("beauty", f, "png"))) for f in self.frames)
        return _mtime(sheet) >= newest

    # -- simulation -------------------------------------------------------
    def _simulation_problem(self):
        """None when every requested frame of the simulation is sound, else why not."""
        manifest_file = os.path.join(self.frames_dir, "manifest.json")
        m = self.manifest
        if m is None:
            return f"{manifest_file} missing or unreadable"
        if m.get("format") != "dewpoint-frames":
            return f"{manifest_file}: not a dewpoint-frames manifest"
        recorded = m.get("scene_file")
        if not isinstance(recorded, str) or not os.path.exists(recorded) or not os.path.samefile(recorded, self.scene_file):
            return f"{manifest_file} was written for scene {recorded!r}, not {self.scene_file}"
        if _mtime(self.scene_file) > _mtime(manifest_file):
            return f"{self.scene_file} changed after the simulation"
        rigid = m.get("rigid_particles")
        if not isinstance(rigid, str) or ply_element_counts(os.path.join(self.frames_dir, rigid)) is None:
            return f"rigid particles file {rigid!r} missing or not whole"
        listed = m.get("frames")
        if not isinstance(listed, list):
            return f"{manifest_file}: key 'frames' is not a list"
        entries = {e.get("index"): e for e in listed if isinstance(e, dict)}
        for frame in self.frames:
            problem = self._frame_problem(entries.get(frame), frame)
            if problem:
                return f"frame {frame}: {problem}"
        return None

    def _frame_problem(self, entry, frame):
        if entry is None:
            return "not in the manifest"
        files = entry.get("files", {})
        particles = files.get("particles") if isinstance(files, dict) else None
        if not isinstance(particles, str):
            return "the manifest names no particles file"
        counts = ply_element_counts(os.path.join(self.frames_dir, particles))
        if counts is None or counts.get("vertex") != entry.get("liquid_particles"):
            return f"{particles} missing, not whole, or not the manifest's particle count"
        surfaces = files.get("surfaces") or {}
        if not isinstance(surfaces, dict):
            return "the manifest's surfaces entry is not an object"
        for name, surface in surfaces.items():
            if not images_readable(os.path.join(self.frames_dir, surface)):
                return f"surface texture {surface} of rigid {name} unreadable"
        air = files.get("air")
        if air is not None:
            path = os.path.join(self.frames_dir, str(air))
            if not os.path.isfile(path) or os.path.getsize(path) == 0:
                return f"air grid {air} missing or empty"
        return None

    def particles_file(self, frame):
        return os.path.join(self.frames_dir, _frame_file("particles", frame, "ply"))

    # -- meshes and images ------------------------------------------------
    def mesh_file(self, frame):
        return os.path.join(self.meshes_dir, _frame_file("liquid", frame, "ply"))

    def _mesh_sound(self, frame):
        mesh = self.mesh_file(frame)
        if not os.path.isfile(mesh):
            return False
        counts = ply_element_counts(mesh)
        sidecar = _load_json(os.path.join(self.meshes_dir, _frame_file("liquid", frame, "json")))
        if counts is None or sidecar is None or sidecar.get("format") != "dewpoint-mesh-sidecar":
            return False
        if sidecar.get("vertices") != counts.get("vertex", 0) or sidecar.get("triangles") != counts.get("face", 0):
            return False
        return _mtime(mesh) >= _mtime(self.particles_file(frame))

    def _render_sound(self, frame):
        if frame not in self.meshed:
            return False
        exr = os.path.join(self.images_dir, _frame_file("beauty", frame, "exr"))
        png = os.path.join(self.images_dir, _frame_file("beauty", frame, "png"))
        if _load_json(os.path.join(self.images_dir, _frame_file("beauty", frame, "json"))) is None:
            return False
        if not images_readable(exr, png):
            return False
        return _mtime(exr) >= _mtime(self.mesh_file(frame))
