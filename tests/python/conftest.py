"""Shared by the batch tests: small meshes on disk and a way to compare output folders."""
import pytest

OCTAHEDRON = ("OFF\n6 8 0\n1 0 0\n-1 0 0\n0 1 0\n0 -1 0\n0 0 1\n0 0 -1\n"
              "3 0 2 4\n3 2 1 4\n3 1 3 4\n3 3 0 4\n3 2 0 5\n3 1 2 5\n3 3 1 5\n3 0 3 5\n")
TETRAHEDRON = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"


@pytest.fixture
def meshes(tmp_path):
    folder = tmp_path / "m"
    (folder / "sub").mkdir(parents=True)
    (folder / "oct.off").write_text(OCTAHEDRON)
    (folder / "sub" / "tet.obj").write_text(TETRAHEDRON)
    (folder / "broken.ply").write_text("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n")
    return folder


def files(folder):
    return {p.name: p.read_bytes() for p in folder.iterdir() if p.name != "results.jsonl"}
