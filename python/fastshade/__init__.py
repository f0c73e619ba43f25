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

import inspect
import json
from dataclasses import dataclass, field
from typing import Literal

import numpy as np

from ._fastshade import Camera, InputError, Material, Mesh, Scene, _methods, _Renderer, load_mesh

__all__ = ["AOVS", "Camera", "Classifier", "Frame", "GouraudMode", "HiddenFaces", "InputError", "Isa", "Material", "Mesh",
           "Method", "Normals", "Renderer", "Scene", "SpecMethod", "batch", "load_mesh", "methods", "render"]


# The spellings of the render options that name a choice: the library's own
# (include/fastshade/options.h; tests/python/test_render.py checks they agree).
Method = Literal["auto", "reference", "phong", "hybrid", "gouraud"]
Isa = Literal["scalar", "sse4", "avx2", "avx512", "best"]
Normals = Literal["normalize", "adaptive", "equal-angle"]
GouraudMode = Literal["increments", "sierpinski"]
HiddenFaces = Literal["skip", "draw"]
SpecMethod = Literal["hybrid", "phong"]
Classifier = Literal["cost", "bound", "paper"]


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

    The options are the command line's `render` flags, Python-named (docs/PIPELINE.md,
    docs/KERNELS.md): threads (0: all cores), method (fastshade.methods() says what each does),
    max_error (the error budget of auto, hybrid and normals="adaptive", in 8-bit steps), tile
    (pixels, a power of two in [8, 256], or 0: sized from the image), isa (this renderer's own
    SIMD target), srgb (encode with the sRGB curve), brdf ("exact", "cosk:K" with K in 1..8,
    "schlick", "schlick-pow2", "quadratic", "quadratic-fit", "poly2", "poly3"), normals
    (phong's per-pixel normals), gouraud ("sierpinski" splits large triangles), hidden_faces
    ("skip" culls back faces a closed mesh provably hides), and auto's spec_threshold,
    spec_method, classifier ("cost": classify where it pays on this frame and ISA, else draw as
    phong; "bound": always; "paper": the paper's rule) and classify_min_px. Frame.stats says
    which method drew ("drawn_as"). An unknown option or a bad value raises
    InputError naming it. The scene is copied: changing it later changes nothing here. The GIL
    is released while a frame renders.
    """

    def __init__(self, scene: Scene, *, threads: int = 0, method: Method = "auto", max_error: float = 1.0,
                 tile: int = 64, isa: Isa = "best", srgb: bool = False, brdf: str = "exact",
                 normals: Normals = "normalize", gouraud: GouraudMode = "increments",
                 hidden_faces: HiddenFaces = "skip", spec_threshold: float = 1.0 / 510.0,
                 spec_method: SpecMethod = "hybrid", classifier: Classifier = "cost",
                 classify_min_px: float = 80.0, **unknown):
        options = {name: value for name, value in locals().items() if name in _OPTIONS}
        self._renderer = _Renderer(scene, _checked_options(dict(options, **unknown)))

    def render(self, aovs=("color",)) -> Frame:
        """One frame with the outputs `aovs` names (of fastshade.AOVS; colour always comes).

        The colour is byte for byte the one rendered without AOVs; the AOVs are the same for
        any thread count and tile size. Arrays are the renderer's buffers, not copies.
        """
        color, stats, depth, normal, triangle_id, object_id = self._renderer.render(*_aov_flags(aovs))
        return Frame(color=color, stats=json.loads(stats), depth=depth, normal=normal,
                     triangle_id=triangle_id, object_id=object_id)


# Every render option with its default, in Renderer's order: its keyword-only parameters.
_OPTIONS = {p.name: p.default for p in inspect.signature(Renderer.__init__).parameters.values()
            if p.kind is inspect.Parameter.KEYWORD_ONLY}


def render(scene: Scene, aovs=("color",), **options) -> Frame:
    """Renderer(scene, **options).render(aovs) in one call; the options are Renderer's."""
    return Renderer(scene, **options).render(aovs)


from ._batch import batch  # noqa: E402  (it uses the helpers above)


def methods() -> dict[str, str]:
    """The shading methods, each with one line on what it does."""
    return dict(_methods())
