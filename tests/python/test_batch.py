"""fastshade.batch(engine="local"): the command line's batch from Python."""
import json
import os
import pathlib
import subprocess

import pytest

import fastshade
from conftest import files

REPO = pathlib.Path(__file__).resolve().parents[2]


def test_local_batch_records_every_image_and_resumes(meshes, tmp_path):
    out = tmp_path / "out"
    results = fastshade.batch(meshes, out, size=(40, 30), views=2, aovs=("color", "depth", "object_id"))
    assert len(results) == 6
    by_status = {}
    for r in results:
        by_status.setdefault(r["status"], []).append(r)
    assert len(by_status["ok"]) == 4 and len(by_status["failed"]) == 2
    assert all("broken.ply" in r["mesh"] and r["error"] for r in by_status["failed"])
    for r in by_status["ok"]:
        assert (out / r["output"]).exists() and (out / r["aov_output"]).exists()
        assert r["aov_output"] == pathlib.Path(r["output"]).stem + ".aov.exr"
    logged = [json.loads(line) for line in (out / "results.jsonl").read_text().splitlines()]
    assert sorted(logged, key=lambda r: (r["mesh"], r["view"])) == results
    again = fastshade.batch(meshes, out, size=(40, 30), views=2, aovs=("color", "depth", "object_id"))
    assert [r["status"] for r in again if "broken" not in r["mesh"]] == ["skipped"] * 4


def test_local_batch_writes_what_the_command_line_writes(meshes, tmp_path):
    binary = pathlib.Path(os.environ.get("FASTSHADE_BINARY", REPO / "build" / "fastshade"))
    if not binary.exists():
        pytest.skip(f"needs the command line at {binary} (bash tools/dev.sh render builds it)")
    fastshade.batch(meshes, tmp_path / "py", size=(48, 32), views=3, aovs=("normal", "triangle_id"))
    subprocess.run([str(binary), "batch", str(meshes), "-o", str(tmp_path / "cli"), "--size", "48x32", "--views", "3",
                    "--aov", "normal,triangle_id"], check=False, capture_output=True)
    assert files(tmp_path / "py") == files(tmp_path / "cli") and len(files(tmp_path / "py")) == 12


@pytest.mark.parametrize("call, names", [
    (lambda m, o: fastshade.batch(m, o, engine="spark"), "engine"),
    (lambda m, o: fastshade.batch(m, o, views=0), "views"),
    (lambda m, o: fastshade.batch(m, o, size=(0, 10)), "size"),
    (lambda m, o: fastshade.batch(m, o, format="jpg"), "format"),
    (lambda m, o: fastshade.batch(m, o, aovs=("albedo",)), "aovs"),
    (lambda m, o: fastshade.batch(m, o, method="nope"), "method"),
    (lambda m, o: fastshade.batch(m, o, threads=2), "threads"),
    (lambda m, o: fastshade.batch(m, o, threads_per_task=0), "threads_per_task"),
    (lambda m, o: fastshade.batch(m, o, shard=(2, 2)), "shard"),
    (lambda m, o: fastshade.batch(m / "nothing-here.txt", o), "nothing-here.txt"),
])
def test_bad_batch_arguments_are_input_errors_before_any_output(meshes, tmp_path, call, names):
    with pytest.raises(fastshade.InputError) as error:
        call(meshes, tmp_path / "out")
    where = str(error.value).split(": ")[0]  # the keyword (or file) the one-line message names
    assert "\n" not in str(error.value) and (where == names or where.endswith("/" + names))
    assert not (tmp_path / "out").exists()
