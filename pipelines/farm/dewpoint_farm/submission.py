"""The sbatch commands for a shot: which stages and frames to (re)do and how
the jobs depend on each other (docs/farm.md)."""
import shlex
import subprocess

from .frame_range import slurm_index_list


class Job:
    """One sbatch call; `after` names earlier jobs of this submission."""

    def __init__(self, stage, script, script_args, frames=None, array=False, after=None, describe=""):
        self.stage = stage
        self.script = script
        self.script_args = script_args
        self.frames = frames or []
        self.array = array
        self.after = after  # (dependency type, [Job, ...]) or None
        self.describe = describe
        self.job_id = None

    def dependency(self, placeholder):
        if not self.after:
            return None
        kind, jobs = self.after
        return kind + ":" + ":".join(j.job_id or placeholder(j) for j in jobs)


def plan_jobs(state, frames, scripts, paths, stage_args):
    """The jobs that bring the shot up to date, and what is skipped.

    The simulation reruns whole when any requested frame of it is unsound
    (its frames depend on each other), and then every mesh and image is
    redone. Otherwise only unsound meshes are redone, each image after its
    own mesh (aftercorr), and images whose mesh is sound run in a separate
    array without a dependency: aftercorr judges a task without a
    counterpart by the whole other array."""
    scene, out = paths
    jobs, skipped = [], []
    span = slurm_index_list(frames)
    simulate = None
    if state.simulation_problem:
        simulate = Job("simulate", scripts["simulate"], [scene, out] + stage_args["simulate"], frames,
                       describe=state.simulation_problem)
        jobs.append(simulate)
        meshes, renders_alone = list(frames), []
    else:
        skipped.append(("simulate", f"frames {span} sound"))
        meshes = [f for f in frames if f not in state.meshed]
        renders_alone = [f for f in frames if f not in state.rendered and f not in meshes]

    mesh_job = None
    if meshes:
        mesh_job = Job("mesh", scripts["mesh"], [out] + stage_args["mesh"], meshes, array=True,
                       after=("afterok", [simulate]) if simulate else None,
                       describe="after simulate" if simulate else "")
        jobs.append(mesh_job)
        render_job = Job("render", scripts["render"], [scene, out] + stage_args["render"], meshes, array=True,
                         after=("aftercorr", [mesh_job]), describe="each task after its mesh task")
        jobs.append(render_job)
    kept_meshes = [f for f in frames if f not in meshes]
    if kept_meshes:
        skipped.append(("mesh", f"frames {slurm_index_list(kept_meshes)} sound"))
    if renders_alone:
        jobs.append(Job("render", scripts["render"], [scene, out] + stage_args["render"], renders_alone, array=True,
                        describe="meshes sound"))
    kept_renders = [f for f in frames if f in state.rendered]
    if kept_renders:
        skipped.append(("render", f"frames {slurm_index_list(kept_renders)} sound"))

    renders = [j for j in jobs if j.stage == "render"]
    if renders or not state.sheet_current:
        jobs.append(Job("contact-sheet", scripts["contact-sheet"], [out, str(frames[0]), str(frames[-1])], frames,
                        after=("afterany", renders) if renders else None,
                        describe="after the renders however they end; fails naming missing frames" if renders else ""))
    else:
        skipped.append(("contact-sheet", "up to date"))
    return jobs, skipped


def sbatch_command(job, common, logs, job_name, placeholder):
    cmd = ["sbatch", "--parsable", f"--job-name={job_name}"]
    if job.array:
        cmd += [f"--array={slurm_index_list(job.frames)}", f"--output={logs}/%x.%A_%a.log"]
    else:
        cmd += [f"--output={logs}/%x.%j.log"]
    dependency = job.dependency(placeholder)
    if dependency:
        # A dependency that can never be met cancels the job instead of
        # leaving it pending forever (what a failed frame's successors need).
        cmd += [f"--dependency={dependency}", "--kill-on-invalid-dep=yes"]
    return cmd + common + [job.script] + job.script_args


def submit(job, cmd):
    """Runs sbatch; returns the job id it printed."""
    result = subprocess.run(cmd, capture_output=True, text=True, check=False)
    if result.returncode != 0:
        raise RuntimeError(f"sbatch failed for the {job.stage} job (exit {result.returncode}): "
                           f"{result.stderr.strip()}\n  command: {shlex.join(cmd)}")
    # --parsable prints "jobid" or "jobid;cluster".
    return result.stdout.strip().split(";")[0]
