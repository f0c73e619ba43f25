#!/usr/bin/env python3
"""pyrender's peer of `fastshade batch`: every mesh of a folder to PNG, one Python process.

    PYOPENGL_PLATFORM=osmesa build/pyrender-venv/bin/python bench/peers/pyrender_batch.py \
        ../shared/models OUTDIR [--size 256x256] [--scene scenes/batch.json]

What it measures: the throughput a user gets from the usual Python stack for "render each mesh
of a folder to an image" on a machine without a GPU: trimesh loads, pyrender draws through
OSMesa (Mesa's llvmpipe, headless) and Pillow writes the PNG. tools/pyrender_peer.sh times this
whole process against `fastshade batch` (docs/BATCH.md) on the same meshes and sizes.

What is the same as `fastshade batch` (so the images can be compared):
- the meshes: .obj .off .ply .stl (any case) found recursively, sorted by path in byte order,
  and the output names STEM-HASH.png (FNV-1a 64 of the path as found);
- the framing: the fit camera of src/io/scene_camera.cpp. Centre = centre of the vertices'
  bounding box, r = the farthest vertex from it, the eye at centre + (0, 0, distance * r)
  looking down -Z with +Y up, the template's fovy, near/far at (distance -/+ 1.1) * r;
- the template (scenes/batch.json): size, background, the lights (view-space lights are
  children of the camera node), diffuse colour and ambient.

What pyrender cannot do the same way, left at its defaults:
- shading is its metallic-roughness PBR, not Blinn-Phong. The light intensity is pi and the
  base colour is kd / 0.96, so the diffuse term equals fastshade's kd * color * max(N.L, 0)
  (times 1 - Fresnel). The specular lobe is GGX with F0 = 0.04, and the roughness is chosen
  so that its width is close to shininess n: alpha = sqrt(2 / (n + 2)). The template's
  specular strength has no counterpart;
- pyrender encodes its output with gamma 1/2.2 (only the background is written linear),
  so lit pixels are brighter than fastshade's linear ones;
- it culls back faces and lights one side only (no `two_sided`), so meshes wound inside out
  (horse.ply) show their far inner side. On OSMesa it draws straight into OSMesa's buffer
  (no MSAA, as fastshade) and reads back depth as well as colour;
- vertex normals are trimesh's (it welds vertices on load), not fastshade's.

Timed phases: setup (the OSMesa context), load (trimesh load, vertex normals, framing), render
(pyrender's upload, draw and read-back) and encode (PNG writing). images/s counts all of them.
"""
import argparse
import json
import math
import os
import pathlib
import sys
import time

import numpy as np

os.environ.setdefault("PYOPENGL_PLATFORM", "osmesa")
import pyrender  # noqa: E402  (reads PYOPENGL_PLATFORM when imported)
import trimesh  # noqa: E402
from OpenGL import GL  # noqa: E402
from PIL import Image  # noqa: E402

MESH_EXTENSIONS = {".obj", ".off", ".ply", ".stl"}
FIT_MARGIN = 1.1  # near/far sit 1.1 radii in front of/behind the centre (scene_camera.cpp)
DIELECTRIC_F0 = 0.04  # pyrender's diffuse colour is base_color * (1 - 0.04)
DEFAULT_TEMPLATE = pathlib.Path(__file__).resolve().parents[2] / "scenes" / "batch.json"


def find_meshes(root):
    """Mesh files below root, as fastshade batch finds and sorts them (paths as found)."""
    found = []
    for dirpath, _, files in os.walk(root):
        for name in files:
            path = os.path.normpath(os.path.join(dirpath, name))
            if os.path.splitext(name)[1].lower() in MESH_EXTENSIONS and os.path.isfile(path):
                found.append(path)
    return sorted(found, key=os.fsencode)


def output_name(path):
    """STEM-HASH as src/batch/batch_inputs.cpp names it: the safe stem and FNV-1a 64 of the path."""
    kept = b"._-0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
    stem = bytes(c if c in kept else ord("_") for c in os.fsencode(pathlib.Path(path).stem)[:100]).decode()
    digest = 14695981039346656037
    for byte in os.fsencode(path):
        digest = ((digest ^ byte) * 1099511628211) & 0xFFFFFFFFFFFFFFFF
    return f"{stem}-{digest:016x}"


def rgb(value):
    """A template colour: a number means the same value for r, g and b."""
    return np.full(3, float(value)) if np.isscalar(value) else np.asarray(value, dtype=float)


def light_pose(toward):
    """A pose whose -Z (pyrender's direction of travel) points away from `toward` (the light)."""
    z = np.asarray(toward, dtype=float) / np.linalg.norm(toward)
    helper = np.array([0.0, 1.0, 0.0]) if abs(z[1]) < 0.9 else np.array([1.0, 0.0, 0.0])
    x = np.cross(helper, z)
    x /= np.linalg.norm(x)
    pose = np.eye(4)
    pose[:3, :3] = np.column_stack([x, np.cross(z, x), z])
    return pose


class Template:
    """The parts of a fastshade batch template (scenes/batch.json) that pyrender can follow."""

    def __init__(self, path):
        scene = json.loads(pathlib.Path(path).read_text())
        image, camera = scene.get("image", {}), scene.get("camera", {})
        self.size = (image.get("width", 640), image.get("height", 480))
        self.background = [*rgb(image.get("background", 0.0)), 1.0]
        self.distance = float(camera.get("distance", 3.0))
        self.fovy_deg = float(camera.get("fovy_deg", 45.0))
        materials = scene.get("materials", {"default": {}})
        chosen = scene.get("objects", [{}])[0].get("material") or next(iter(materials))
        material = materials[chosen]
        kd = rgb(material.get("diffuse", 0.7))
        shininess = float(material.get("shininess", 32))
        self.base_color = kd / (1.0 - DIELECTRIC_F0)
        self.roughness = (2.0 / (shininess + 2.0)) ** 0.25  # pyrender squares it into GGX alpha
        self.ambient = rgb(scene.get("ambient", 0.0)) / np.maximum(self.base_color, 1e-6)
        self.lights = [(rgb(light.get("color", 1.0)), light["direction"], light.get("space", "view"))
                       for light in scene.get("lights", [])]

    def scene_for(self, mesh, width, height):
        """A pyrender scene of the mesh alone, framed by fastshade's fit camera."""
        vertices = np.asarray(mesh.vertices, dtype=np.float64)
        lo, hi = vertices.min(axis=0), vertices.max(axis=0)
        centre = 0.5 * (lo + hi)
        radius = math.sqrt(np.max(np.sum((vertices - centre) ** 2, axis=1)))
        if not radius > 0.0 or not math.isfinite(radius):
            raise ValueError("the mesh has no extent to frame")

        material = pyrender.MetallicRoughnessMaterial(
            baseColorFactor=[*self.base_color, 1.0], metallicFactor=0.0, roughnessFactor=self.roughness)
        primitive = pyrender.Primitive(positions=mesh.vertices, normals=mesh.vertex_normals,
                                       indices=mesh.faces, material=material)
        scene = pyrender.Scene(bg_color=self.background, ambient_light=self.ambient)
        scene.add(pyrender.Mesh([primitive]))
        camera = pyrender.PerspectiveCamera(
            yfov=math.radians(self.fovy_deg), aspectRatio=width / height,
            znear=(self.distance - FIT_MARGIN) * radius, zfar=(self.distance + FIT_MARGIN) * radius)
        eye = np.eye(4)
        eye[:3, 3] = centre + [0.0, 0.0, self.distance * radius]
        camera_node = scene.add(camera, pose=eye)
        for color, direction, space in self.lights:
            # Intensity pi cancels the 1/pi of pyrender's Lambert term.
            light = pyrender.DirectionalLight(color=color, intensity=math.pi)
            if space == "view":
                scene.add(light, pose=light_pose(direction), parent_node=camera_node)
            else:
                scene.add(light, pose=light_pose(direction))
        return scene


def parse_size(text):
    width, _, height = text.lower().partition("x")
    return int(width), int(height)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("models", help="directory searched recursively for meshes")
    parser.add_argument("outdir", help="created if missing; STEM-HASH.png go here")
    parser.add_argument("--size", type=parse_size, help="WxH (default: the template's)")
    parser.add_argument("--scene", default=DEFAULT_TEMPLATE, help="fastshade batch template")
    args = parser.parse_args()

    template = Template(args.scene)
    width, height = args.size or template.size
    meshes = find_meshes(args.models)
    if not meshes:
        sys.exit(f"{args.models}: no mesh files (.obj, .off, .ply, .stl) found")
    os.makedirs(args.outdir, exist_ok=True)

    seconds = dict.fromkeys(["setup", "load", "render", "encode"], 0.0)
    failed = []
    start = time.perf_counter()
    renderer = pyrender.OffscreenRenderer(width, height)
    seconds["setup"] = time.perf_counter() - start
    gl_renderer = GL.glGetString(GL.GL_RENDERER).decode()
    for path in meshes:
        t0 = time.perf_counter()
        try:
            mesh = trimesh.load(path, force="mesh")
            scene = template.scene_for(mesh, width, height)
        except Exception as error:  # noqa: BLE001  (a broken mesh is reported, the batch goes on)
            failed.append(f"{path}: {error}")
            print(f"pyrender: FAILED {path}: {error}", file=sys.stderr)
            continue
        t1 = time.perf_counter()
        color, _ = renderer.render(scene)
        t2 = time.perf_counter()
        Image.fromarray(color).save(os.path.join(args.outdir, output_name(path) + ".png"))
        t3 = time.perf_counter()
        seconds["load"] += t1 - t0
        seconds["render"] += t2 - t1
        seconds["encode"] += t3 - t2
    renderer.delete()
    wall = time.perf_counter() - start

    images = len(meshes) - len(failed)
    phases = ", ".join(f"{name} {value:.2f} s" for name, value in seconds.items())
    print(f"pyrender: {images} images in {wall:.2f} s ({images / wall:.2f} images/s, {width}x{height}, "
          f"{gl_renderer}): {images} ok, {len(failed)} failed; {phases}")
    for line in failed:
        print(f"failed: {line}")
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
