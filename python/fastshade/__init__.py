"""fastshade: a multicore, tiled CPU renderer for Gouraud and Phong shading, no GPU or GL needed.

    import fastshade, numpy as np
    scene = fastshade.Scene(640, 480, ambient=(0.05, 0.05, 0.05))
    scene.add_object(fastshade.load_mesh("bunny.ply"), fastshade.Material(shininess=50))
    scene.add_light((0.3, 0.5, 1.0))
    scene.camera = fastshade.Camera.fit()
    frame = fastshade.render(scene, aovs=("color", "depth", "triangle_id"), method="auto")
    frame.color        # (480, 640, 3) uint8
    frame.depth        # (480, 640) float32, distance along the viewing axis, 0 where empty
    frame.triangle_id  # (480, 640) int32, the face in its object's mesh, -1 where empty
    frame.stats        # the keys of `fastshade render --stats`

Every bad input raises fastshade.InputError (a ValueError) with the command line's one-line message.
"""
from __future__ import annotations

import json
from dataclasses import dataclass, field

import numpy as np

from ._fastshade import Camera, InputError, Material, Mesh, Scene, _methods, _Renderer, load_mesh

__all__ = ["AOVS", "Camera", "Frame", "InputError", "batch", "Material", "Mesh", "Renderer", "Scene", "load_mesh", "methods", "render"]


# Every render option with its default, in the order the module takes them (README.md's
# `render` flags, Python-named).
_OPTIONS = {
    "threads": 0, "method": "auto", "max_error": 1.0, "tile": 64, "isa": "best", "srgb": False,
    "brdf": "exact", "normals": "normalize", "gouraud": "increments", "hidden_faces": "skip",
    "spec_threshold": 1.0 / 510.0, "spec_method": "hybrid", "classifier": "bound", "classify_min_px": 80.0,
}


# The outputs a render can return beside colour (docs/PYTHON.md, "Outputs").
AOVS = ("color", "depth", "normal", "triangle_id", "object_id")


@dataclass
class Frame:
    """One rendered frame and the outputs asked for (None where not asked).

    color: (H, W, 3) uint8, always. depth: (H, W) float32, the distance along the camera's
    viewing axis in scene units, 0 where nothing is drawn. normal: (H, W, 3) float32, the
    shading normal as interpolated and normalised, world space, 0 where nothing is drawn.
    triangle_id: (H, W) int32, the face's index in its object's mesh, -1 where nothing is
    drawn. object_id: (H, W) int32, the object's index in the scene (add_object's return), -1
    where nothing is drawn. stats: the keys of `fastshade render --stats`.
    """

    color: np.ndarray
    stats: dict = field(default_factory=dict)
    depth: np.ndarray | None = None
    normal: np.ndarray | None = None
    triangle_id: np.ndarray | None = None
    object_id: np.ndarray | None = None


def _checked_options(options: dict) -> dict:
    """Every render option by name, defaults filled in, each of its option's type."""
    unknown = sorted(set(options) - set(_OPTIONS))
    if unknown:
        raise InputError(f"{unknown[0]}: unknown option (expected one of: {', '.join(_OPTIONS)})")
    checked = {}
    for name, default in _OPTIONS.items():
        value = options.get(name, default)
        kind = type(default)
        if kind is float and isinstance(value, (int, np.integer)) and not isinstance(value, bool):
            value = float(value)
        if kind is int and isinstance(value, np.integer):
            value = int(value)
        if not isinstance(value, kind) or (kind is int and isinstance(value, bool)):
            raise InputError(f"{name}: expected {kind.__name__}, got {type(value).__name__} {value!r}")
        checked[name] = value
    return checked


def _aov_flags(aovs) -> tuple[bool, bool, bool, bool]:
    names = (aovs,) if isinstance(aovs, str) else tuple(aovs)
    for name in names:
        if name not in AOVS:
            raise InputError(f"aovs: unknown output {name!r} (expected some of: {', '.join(AOVS)})")
    return tuple(name in names for name in AOVS[1:])


class Renderer:
    """Renders one scene with fixed options, keeping its buffers between frames.

    The options are the command line's (docs/KERNELS.md, README.md): method ("auto", "reference",
    "phong", "hybrid", "gouraud"), max_error (8-bit steps), threads (0: all), tile (pixels, a power
    of two in [8, 256], or 0: sized from the image), isa ("scalar", "sse4", "avx2", "avx512",
    "best": this renderer's own), srgb, brdf, normals, gouraud, hidden_faces, spec_threshold,
    spec_method, classifier, classify_min_px. The scene is copied: changing it later changes
    nothing here. The GIL is released while a frame renders.
    """

    def __init__(self, scene: Scene, **options):
        self._renderer = _Renderer(scene, _checked_options(options))

    def render(self, aovs=("color",)) -> Frame:
        """One frame with the outputs `aovs` names (of fastshade.AOVS; colour always comes).

        The colour is byte for byte the one rendered without AOVs; the AOVs are the same for
        any thread count and tile size. Arrays are the renderer's buffers, not copies.
        """
        color, stats, depth, normal, triangle_id, object_id = self._renderer.render(*_aov_flags(aovs))
        return Frame(color=color, stats=json.loads(stats), depth=depth, normal=normal,
                     triangle_id=triangle_id, object_id=object_id)


def render(scene: Scene, aovs=("color",), **options) -> Frame:
    """Renderer(scene, **options).render(aovs) in one call."""
    return Renderer(scene, **options).render(aovs)


from ._batch import batch  # noqa: E402  (it uses the helpers above)


def methods() -> dict[str, str]:
    """The shading methods, each with one line on what it does."""
    return dict(_methods())
