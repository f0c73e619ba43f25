"""fastshade.batch(engine="ray"): the same files as the local engine, and no image lost when a task dies."""
import json
import os
import sys

import pytest

import fastshade
from fastshade import _batch
from conftest import files

ray = pytest.importorskip("ray", reason="engine='ray' tests need Ray: pip install '.[ray]'")


@pytest.fixture(scope="module")
def ray_cluster():
    # Ray's workers cannot import this test module: its functions travel by value.
    ray.cloudpickle.register_pickle_by_value(sys.modules[__name__])
    ray.init(num_cpus=2, include_dashboard=False, log_to_driver=False)
    yield
    ray.shutdown()


def test_ray_batch_writes_the_same_files_as_local(meshes, tmp_path, ray_cluster):
    local = fastshade.batch(meshes, tmp_path / "local", size=(40, 30), views=2, aovs=fastshade.AOVS)
    remote = fastshade.batch(meshes, tmp_path / "ray", size=(40, 30), views=2, aovs=fastshade.AOVS,
                             engine="ray", threads_per_task=1)
    assert files(tmp_path / "ray") == files(tmp_path / "local") and len(files(tmp_path / "local")) == 8
    strip = ("load_ms", "render_ms", "write_ms", "time_ms")
    assert [{k: v for k, v in r.items() if k not in strip} for r in remote] == \
           [{k: v for k, v in r.items() if k not in strip} for r in local]


def _dies_on_the_tetrahedron(spec, job):
    if job["mesh"]["key"].endswith("tet.obj"):
        os._exit(1)  # the worker process dies mid-task
    return _batch._render_mesh_task(spec, job)


def test_a_ray_task_whose_worker_dies_becomes_failed_records(meshes, tmp_path, ray_cluster):
    spec_results = []
    jobs, _ = fastshade._fastshade._batch_plan(_spec(meshes, tmp_path / "out"))
    _batch._ray_lines(_spec(meshes, tmp_path / "out"), jobs, None, 1,
                      lambda lines: spec_results.extend(json.loads(x) for x in lines), _dies_on_the_tetrahedron)
    assert len(spec_results) == 3
    tet = [r for r in spec_results if r["mesh"].endswith("tet.obj")]
    assert len(tet) == 1 and tet[0]["status"] == "failed" and tet[0]["error"].startswith("ray: ")
    assert [r["status"] for r in spec_results if r["mesh"].endswith("oct.off")] == ["ok"]


def _spec(meshes, out):
    return {"inputs": [str(meshes)], "outdir": str(out), "scene": "", "width": 32, "height": 24, "views": 1,
            "shard_index": 0, "shard_count": 1, "format": "png", "depth": False, "normal": False,
            "triangle_id": False, "object_id": False, "options": fastshade._checked_options({"threads": 1})}
