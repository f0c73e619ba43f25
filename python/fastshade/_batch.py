"""fastshade.batch: the command line's batch, from Python, on this machine or as Ray tasks."""
from __future__ import annotations

import json
import os

from typing import TYPE_CHECKING

from ._fastshade import InputError, _batch_failed, _batch_plan, _batch_record, _batch_render_mesh

if TYPE_CHECKING:
    from . import Method

ENGINES = ("local", "ray")


def _render_mesh_task(spec: dict, job: dict) -> list[str]:
    """One Ray task: a mesh loaded once, all its views rendered, written, and their lines."""
    return _batch_render_mesh(spec, job)


def _first_line(error: BaseException) -> str:
    text = str(error).strip().splitlines()
    return f"{type(error).__name__}: {text[-1] if text else 'no message'}"


def _ray_lines(spec: dict, jobs: list[dict], address: str | None, num_cpus: int, record,
               render_task=_render_mesh_task):
    try:
        import ray
    except ImportError:
        raise InputError("engine: 'ray' needs Ray, which is not installed: pip install 'fastshade[ray]' "
                         "(or pip install ray)") from None
    if not ray.is_initialized():
        ray.init(address=address) if address else ray.init()
    task = ray.remote(num_cpus=num_cpus, max_retries=0)(render_task)
    pending = {task.remote(spec, job): job for job in jobs}
    while pending:
        done, _ = ray.wait(list(pending), num_returns=1)
        job = pending.pop(done[0])
        try:
            lines = ray.get(done[0])
        except Exception as error:  # the task raised, or its worker died: every image fails, none is lost
            lines = _batch_failed(spec, job, "ray: " + _first_line(error))
        record(lines)


def batch(inputs, out_dir, size=(256, 256), views=1, scene=None, method: Method = "auto", aovs=("color",),
          engine="local", address=None, threads_per_task=None, format="png", shard=(0, 1), **options) -> list[dict]:
    """Renders every mesh of `inputs` (files, directories searched recursively, list files) as
    `fastshade batch` does (docs/BATCH.md) and returns one dict per image: the keys of a
    results.jsonl line, with "status" ("ok", "failed" with "error", or "skipped": an earlier run
    made it with the same settings) and "output" (and "aov_output" when the AOVs are beside it).

    size: (width, height), or None for the template's. views: K views per mesh, turned 360/K
    degrees about the vertical. scene: a template scene file (its fit camera frames each mesh);
    None: the embedded default. aovs: of fastshade.AOVS, written into an EXR output or beside
    the image as STEM.aov.exr. format: "png", "exr" or "tif". shard: (I, N), part I of N of the
    sorted meshes. Other keywords are render options (fastshade.Renderer).

    engine "local": mesh after mesh in this process, each render on `threads_per_task` threads
    (None: all). engine "ray": one Ray task per mesh with num_cpus=threads_per_task (None: 1),
    rendering on that many threads; Ray is started here unless it runs already or `address`
    names a cluster to join (out_dir must then be on a file system every node sees). A task
    that fails or whose worker dies gives "failed" records for its images. The files are the
    same, byte for byte, whichever the engine.
    """
    from . import _aov_flags, _checked_options

    if engine not in ENGINES:
        raise InputError(f"engine: expected one of {', '.join(ENGINES)}, got {engine!r}")
    if threads_per_task is not None and (isinstance(threads_per_task, bool) or not isinstance(threads_per_task, int)
                                         or threads_per_task < 1):
        raise InputError(f"threads_per_task: expected an int >= 1, got {threads_per_task!r}")
    if "threads" in options:
        raise InputError("threads: a batch's renders take threads_per_task")
    if isinstance(inputs, (str, os.PathLike)):
        inputs = [inputs]
    width, height = (0, 0) if size is None else size
    # Local renders take all cores by default; a Ray task, the one CPU it asks for.
    threads = threads_per_task if threads_per_task is not None else (0 if engine == "local" else 1)
    depth, normal, triangle_id, object_id = _aov_flags(aovs)
    spec = {
        "inputs": [os.fspath(p) for p in inputs], "outdir": os.fspath(out_dir),
        "scene": "" if scene is None else os.fspath(scene), "width": int(width), "height": int(height),
        "views": views, "shard_index": shard[0], "shard_count": shard[1], "format": format,
        "depth": depth, "normal": normal, "triangle_id": triangle_id, "object_id": object_id,
        "options": _checked_options(dict(options, method=method, threads=threads)),
    }
    for key in ("views", "shard_index", "shard_count"):
        if isinstance(spec[key], bool) or not isinstance(spec[key], int):
            raise InputError(f"{key}: expected an int, got {spec[key]!r}")
    jobs, skipped = _batch_plan(spec)
    results = []

    def record(lines):
        _batch_record(spec["outdir"], lines)
        results.extend(json.loads(line) for line in lines)

    record(skipped)
    if engine == "local":
        for job in jobs:
            record(_batch_render_mesh(spec, job))
    else:
        _ray_lines(spec, jobs, address, threads, record)
    return sorted(results, key=lambda r: (r["mesh"], r["view"]))
