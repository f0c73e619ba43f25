"""The Python module: numpy in and out, scenes in code and from files, cameras, errors."""
import inspect
import os
import pathlib
import re
import threading
import typing

import numpy as np
import pytest

import fastshade

REPO = pathlib.Path(__file__).resolve().parents[2]


def quad_mesh():
    vertices = np.array([[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]], dtype=np.float64)
    faces = np.array([[0, 1, 2], [0, 2, 3]], dtype=np.int64)
    return fastshade.Mesh(vertices, faces)


def lit_scene(mesh, width=64, height=48):
    scene = fastshade.Scene(width, height, background=(0.1, 0.2, 0.3), ambient=(0.05, 0.05, 0.05))
    scene.add_object(mesh, fastshade.Material(diffuse=(0.8, 0.6, 0.4), specular=(0.5, 0.5, 0.5), shininess=40))
    scene.add_light((0.3, 0.5, 1.0))
    scene.camera = fastshade.Camera.fit()
    return scene


def test_mesh_arrays_round_trip():
    mesh = quad_mesh()
    assert mesh.vertices.dtype == np.float32 and mesh.vertices.shape == (4, 3)
    assert mesh.faces.dtype == np.uint32 and mesh.faces.tolist() == [[0, 1, 2], [0, 2, 3]]
    # Area-weighted normals of a quad facing +Z.
    np.testing.assert_allclose(mesh.normals, np.tile([0.0, 0.0, 1.0], (4, 1)), atol=1e-7)


def test_render_returns_colour_and_stats():
    frame = fastshade.render(lit_scene(quad_mesh()), threads=2)
    assert frame.color.shape == (48, 64, 3) and frame.color.dtype == np.uint8
    background = np.array([26, 51, 77])  # 0.1, 0.2, 0.3 quantised
    assert (frame.color[0, 0] == background).all()
    assert (frame.color != background).any(axis=2).sum() == frame.stats["covered_pixels"] > 0
    assert frame.stats["triangles_in"] == 2 and frame.stats["method"] == "auto"


def grid_mesh(n):
    """A bumpy n x n grid of quads over [-1, 1]^2: 2 n^2 triangles."""
    u = np.linspace(-1.0, 1.0, n + 1)
    x, y = np.meshgrid(u, u)
    vertices = np.stack([x, y, 0.1 * np.sin(6 * x) * np.cos(6 * y)], axis=-1).reshape(-1, 3)
    i = np.arange(n)[:, None] * (n + 1) + np.arange(n)[None, :]
    quads = np.stack([i, i + 1, i + n + 2, i + n + 1], axis=-1).reshape(-1, 4)
    faces = np.concatenate([quads[:, [0, 1, 2]], quads[:, [0, 2, 3]]])
    return fastshade.Mesh(vertices.astype(np.float64), faces.astype(np.int64))


def test_auto_draws_a_frame_of_tiny_triangles_as_phong():
    # 80,000 triangles in 64 x 48 pixels: far below any ISA's threshold (docs/CLASSIFIER.md).
    scene = lit_scene(grid_mesh(200))
    frame = fastshade.render(scene, threads=2)
    assert frame.stats["method"] == "auto" and frame.stats["drawn_as"] == "phong"
    assert np.array_equal(frame.color, fastshade.render(scene, threads=2, method="phong").color)
    classified = fastshade.render(scene, threads=2, classifier="bound")
    assert classified.stats["drawn_as"] == "auto" and classified.stats["paths"]


def read_ppm(path):
    data = path.read_bytes()
    header = re.match(rb"P6\s+(\d+)\s+(\d+)\s+255\s", data)  # one whitespace byte before the pixels
    width, height = int(header[1]), int(header[2])
    return np.frombuffer(data[header.end():], dtype=np.uint8).reshape(height, width, 3)


def test_colour_matches_the_command_line(tmp_path):
    binary = pathlib.Path(os.environ.get("FASTSHADE_BINARY", REPO / "build" / "fastshade"))
    if not binary.exists():
        pytest.skip(f"needs the command line at {binary} (bash tools/dev.sh render builds it)")
    import subprocess
    scene_file = REPO / "scenes" / "spheres.json"
    for method in ("auto", "phong", "gouraud"):
        out = tmp_path / f"{method}.ppm"
        subprocess.run([str(binary), "render", str(scene_file), "-o", str(out), "--method", method, "--threads", "2"],
                       check=True, capture_output=True)
        frame = fastshade.render(fastshade.Scene.from_file(scene_file), threads=2, method=method)
        assert np.array_equal(frame.color, read_ppm(out)), method


def test_threads_and_tiles_give_identical_colour():
    scene = lit_scene(quad_mesh(), 96, 80)
    reference = fastshade.render(scene, threads=1, tile=64).color
    for threads in (1, 2, 4):
        for tile in (8, 64, 256):
            assert np.array_equal(fastshade.render(scene, threads=threads, tile=tile).color, reference)


def test_renderers_in_python_threads():
    scene = lit_scene(quad_mesh(), 128, 96)
    expected = fastshade.render(scene, threads=1).color
    results = [None] * 4

    def work(i):
        results[i] = fastshade.Renderer(scene, threads=1, isa=fastshade_isas()[i % len(fastshade_isas())]).render().color

    workers = [threading.Thread(target=work, args=(i,)) for i in range(4)]
    for w in workers:
        w.start()
    for w in workers:
        w.join()
    for color in results:
        assert np.array_equal(color, expected)


def fastshade_isas():
    isas = []
    for isa in ("scalar", "sse4", "avx2", "avx512"):
        try:
            fastshade.Renderer(lit_scene(quad_mesh(), 8, 8), isa=isa)
            isas.append(isa)
        except fastshade.InputError:
            pass
    return isas


def test_aovs_are_numpy_arrays_of_the_visible_surface():
    # Two quads facing the camera, the second nearer and smaller: ids say which one each pixel
    # shows, depth is the distance along the axis (2.0 and 1.5 here), normals face +Z.
    near = fastshade.Mesh(np.array([[-0.3, -0.3, 0.5], [0.3, -0.3, 0.5], [0.3, 0.3, 0.5], [-0.3, 0.3, 0.5]]),
                          [[0, 1, 2], [0, 2, 3]])
    scene = lit_scene(quad_mesh())
    assert scene.add_object(near) == 1
    scene.camera = fastshade.Camera.look_at((0, 0, 2), (0, 0, 0))
    plain = fastshade.render(scene, threads=2)
    frame = fastshade.render(scene, aovs=fastshade.AOVS, threads=2)
    assert np.array_equal(frame.color, plain.color) and plain.depth is None
    assert frame.depth.shape == (48, 64) and frame.depth.dtype == np.float32
    assert frame.normal.shape == (48, 64, 3) and frame.normal.dtype == np.float32
    assert frame.triangle_id.dtype == np.int32 and frame.object_id.dtype == np.int32
    drawn = frame.object_id >= 0
    assert drawn.sum() == frame.stats["covered_pixels"]
    assert set(np.unique(frame.object_id)) == {-1, 0, 1} and set(np.unique(frame.triangle_id)) == {-1, 0, 1}
    np.testing.assert_allclose(frame.depth[frame.object_id == 0], 2.0, rtol=1e-5)
    np.testing.assert_allclose(frame.depth[frame.object_id == 1], 1.5, rtol=1e-5)
    assert (frame.depth[~drawn] == 0).all() and (frame.normal[~drawn] == 0).all()
    np.testing.assert_allclose(frame.normal[drawn], np.tile([0, 0, 1], (drawn.sum(), 1)), atol=1e-6)
    assert frame.object_id[24, 32] == 1 and frame.object_id[24, 8] == 0 and frame.object_id[24, 0] == -1
    only_depth = fastshade.Renderer(scene, threads=1, tile=8).render(aovs="depth")
    assert np.array_equal(only_depth.depth, frame.depth) and only_depth.triangle_id is None


def test_frames_own_their_buffers_and_released_ones_are_reused():
    renderer = fastshade.Renderer(lit_scene(quad_mesh()), threads=1)
    first = renderer.render(aovs=fastshade.AOVS)
    kept = first.color.copy(), first.depth.copy()
    second = renderer.render(aovs=fastshade.AOVS)
    assert not np.shares_memory(first.color, second.color) and not np.shares_memory(first.depth, second.depth)
    assert np.array_equal(first.color, kept[0]) and np.array_equal(first.depth, kept[1])
    # Once Python lets a frame go, the next frame renders into its buffers (no fresh allocation).
    address = second.color.ctypes.data
    del second
    assert renderer.render().color.ctypes.data == address


def test_calibrated_camera_puts_the_quad_where_k_says():
    vertices = np.array([[-0.02, -0.02, 0], [0.02, -0.02, 0], [0.02, 0.02, 0], [-0.02, 0.02, 0]]) + [0.1, -0.05, 2.0]
    mesh = fastshade.Mesh(vertices, [[0, 1, 2], [0, 2, 3]])
    scene = fastshade.Scene(256, 192, ambient=(0.5, 0.5, 0.5))
    scene.add_object(mesh)
    K = np.array([[500.0, 0, 120.3], [0, 450.0, 90.7], [0, 0, 1]])
    scene.camera = fastshade.Camera.from_intrinsics(K, np.eye(4), convention="opencv")
    color = fastshade.render(scene, threads=2).color
    v, u = np.nonzero(color.any(axis=2))
    assert abs(u.mean() - (500 * 0.1 / 2 + 120.3)) < 0.5
    assert abs(v.mean() - (450 * -0.05 / 2 + 90.7)) < 0.5


@pytest.mark.parametrize("make", [
    lambda: fastshade.Mesh(np.zeros((4, 2)), [[0, 1, 2]]),
    lambda: fastshade.Mesh(np.zeros((4, 3)), [[0, 1, 4]]),
    lambda: fastshade.Mesh(np.zeros((4, 3)), [[0, 1, -1]]),
    lambda: fastshade.Mesh(np.zeros((4, 3)), [[0.0, 1.0, 2.0]]),
    lambda: fastshade.Mesh(np.full((3, 3), np.nan), [[0, 1, 2]]),
    lambda: fastshade.Mesh("not an array", [[0, 1, 2]]),
    lambda: fastshade.Material(shininess=0.5),
    lambda: fastshade.Material(diffuse=(-1, 0, 0)),
    lambda: fastshade.Scene(0, 10),
    lambda: fastshade.Camera.look_at((0, 0, 1), (0, 0, 1)),
    lambda: fastshade.Camera.from_intrinsics(np.array([[0.0, 0, 1], [0, 1, 1], [0, 0, 1]])),
    lambda: fastshade.Camera.from_intrinsics(np.eye(3), 2 * np.eye(4)),
    lambda: fastshade.Renderer(lit_scene(quad_mesh()), method="nope"),
    lambda: fastshade.Renderer(lit_scene(quad_mesh()), no_such_option=1),
    lambda: fastshade.Renderer(lit_scene(quad_mesh()), threads="two"),
    lambda: fastshade.Renderer(lit_scene(quad_mesh())).render(aovs=("color", "albedo")),
    lambda: fastshade.load_mesh("/no/such/mesh.obj"),
    lambda: fastshade.Scene.from_file("/no/such/scene.json"),
])
def test_bad_input_is_an_input_error(make):
    with pytest.raises(fastshade.InputError) as error:
        make()
    assert isinstance(error.value, ValueError)
    assert "\n" not in str(error.value) and str(error.value)


@pytest.mark.parametrize("keyword, value", [
    ("method", "nope"), ("isa", "neon"), ("brdf", "cosk:9"), ("normals", "unit"), ("gouraud", "fast"),
    ("hidden_faces", "maybe"), ("spec_method", "gouraud"), ("classifier", "magic"),
])
def test_a_misspelt_option_names_its_keyword(keyword, value):
    with pytest.raises(fastshade.InputError) as error:
        fastshade.Renderer(lit_scene(quad_mesh()), **{keyword: value})
    assert str(error.value).startswith(keyword + ": ") and repr(value) in str(error.value)


def test_the_spellings_renderer_declares_are_the_library_s():
    hints = typing.get_type_hints(fastshade.Renderer.__init__)
    choices = {name: typing.get_args(hint) for name, hint in hints.items() if typing.get_origin(hint) is typing.Literal}
    assert set(choices) == {"method", "isa", "normals", "gouraud", "hidden_faces", "spec_method", "classifier"}
    for name, spellings in choices.items():
        with pytest.raises(fastshade.InputError) as error:
            fastshade.Renderer(lit_scene(quad_mesh()), **{name: "?"})
        accepted = str(error.value).split("(expected ")[1].rstrip(")")  # "a, b or c"
        assert accepted.replace(" or ", ", ").split(", ") == list(spellings), name


def test_renderer_keywords_are_every_option_with_its_default():
    renderer = fastshade.Renderer(lit_scene(quad_mesh()), method="phong", tile=32)
    assert renderer.render().stats["method"] == "phong" and renderer.render().stats["tile"] == 32
    defaults = {name: p.default for name, p in inspect.signature(fastshade.Renderer).parameters.items()
                if p.kind is inspect.Parameter.KEYWORD_ONLY}
    assert defaults["method"] == "auto" and defaults["tile"] == 64 and len(defaults) == 14
