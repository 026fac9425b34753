"""A flat image in Meshcat: a textured rectangle as an embedded glTF file.

Meshcat draws glTF with its textures; one quad with a PNG texture carries a
whole occupancy grid in a few hundred kilobytes, where one coloured triangle
per cell would carry millions of vertices.
"""

from __future__ import annotations

import base64
import hashlib
import io
import json
from pathlib import Path

import numpy as np


def png_bytes(grey: np.ndarray) -> bytes:
    """PNG of a greyscale (rows, cols) or RGBA (rows, cols, 4) image (uint8, or floats in
    [0, 1]); row 0 is the image's top."""
    from PIL import Image

    if grey.dtype != np.uint8:
        grey = np.clip(grey * 255.0 + 0.5, 0, 255).astype(np.uint8)
    mode = "RGBA" if grey.ndim == 3 else "L"
    image = Image.fromarray(np.ascontiguousarray(grey), mode=mode)
    out = io.BytesIO()
    image.save(out, format="PNG", compress_level=1)
    return out.getvalue()


def textured_quad_gltf(png: bytes, width: float, height: float, blend: bool = False) -> str:
    """glTF 2.0 text of the rectangle (0, 0)-(width, height) in z = 0 showing ``png``.

    The image's first row is drawn at y = height (the rectangle's top), so a
    grid whose row 0 is at y = 0 should be flipped before it is encoded. With
    ``blend`` the texture's alpha blends with what is behind (glTF ``BLEND``).
    """
    # glTF is y-up and Drake turns it z-up (a quarter turn about x): the rectangle
    # (x, y) of the z = 0 plane is written as (x, 0, -y).
    positions = np.array(
        [[0, 0, 0], [width, 0, 0], [width, 0, -height], [0, 0, -height]], np.float32
    )
    texcoords = np.array([[0, 1], [1, 1], [1, 0], [0, 0]], np.float32)
    indices = np.array([0, 1, 2, 0, 2, 3], np.uint16)
    blob = positions.tobytes() + texcoords.tobytes() + indices.tobytes()
    uri = "data:application/octet-stream;base64," + base64.b64encode(blob).decode()
    image_uri = "data:image/png;base64," + base64.b64encode(png).decode()
    document = {
        "asset": {"version": "2.0"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0}],
        "meshes": [
            {"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": 2, "material": 0}]}
        ],
        "materials": [
            {
                "pbrMetallicRoughness": {"baseColorTexture": {"index": 0}, "metallicFactor": 0.0},
                "doubleSided": True,
                "extensions": {"KHR_materials_unlit": {}},
                "alphaMode": "BLEND" if blend else "OPAQUE",
            }
        ],
        "extensionsUsed": ["KHR_materials_unlit"],
        "textures": [{"source": 0, "sampler": 0}],
        "samplers": [{"magFilter": 9728, "minFilter": 9728}],  # nearest: crisp cells
        "images": [{"uri": image_uri}],
        "buffers": [{"byteLength": len(blob), "uri": uri}],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": 48},
            {"buffer": 0, "byteOffset": 48, "byteLength": 32},
            {"buffer": 0, "byteOffset": 80, "byteLength": 12},
        ],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
             "min": [0.0, 0.0, -float(height)], "max": [float(width), 0.0, 0.0]},
            {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC2"},
            {"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"},
        ],
    }  # fmt: skip
    return json.dumps(document)


def write_quad(
    folder: Path, grey: np.ndarray, width: float, height: float, blend: bool = False
) -> Path:
    """The glTF file of a greyscale or RGBA grid (row 0 at y = 0), written once per content."""
    png = png_bytes(grey[::-1])
    text = textured_quad_gltf(png, width, height, blend)
    digest = hashlib.sha1(text.encode()).hexdigest()[:16]
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / f"grid_{digest}.gltf"
    if not path.exists():
        partial = path.with_suffix(".partial")
        partial.write_text(text, encoding="utf-8")
        partial.replace(path)
    return path
