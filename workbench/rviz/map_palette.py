"""The Map display's colour schemes: RViz's ``map``, ``costmap`` and ``raw`` palettes.

RViz (map_display.cpp, ``makeMapPalette``, ``makeCostmapPalette``, ``makeRawPalette``)
colours each occupancy byte through a 256-entry RGBA table, indexed by the byte
(an int8 cell value -1 is byte 255):

- ``map``: 0..100 grey from white to black (``255 - 255 * v / 100``, integer
  division), 101..127 green, 128..254 red to yellow, 255 (unknown, -1) the
  blue-green grey ``#708986``; all opaque.
- ``costmap``: 0 transparent, 1..98 blue to red (red ``255 * v / 100``, blue its
  complement), 99 cyan (costmap_2d's INSCRIBED 253 translated), 100 purple
  (LETHAL 254), then as ``map`` (unknown, NO_INFORMATION 255 -> -1, in ``#708986``).
- ``raw``: the byte as a grey level, opaque.

The display's ``Alpha`` multiplies every entry's alpha; the ``map`` scheme is drawn
opaque when ``Alpha`` is at least 0.9998 (RViz replaces instead of blending then).
"""

from __future__ import annotations

import numpy as np

#: RViz's ``Color Scheme`` options, in its order.
SCHEMES = ("map", "costmap", "raw")
#: Schemes RViz always blends (``color_scheme_transparency_``).
TRANSPARENT_SCHEMES = frozenset({"costmap", "raw"})
#: ``Alpha`` from which an opaque scheme is drawn without blending (RViz's threshold).
OPAQUE_ALPHA = 0.9998
#: RViz's colour for the legal unknown value -1 ("tasteful blueish greenish grayish").
UNKNOWN_RGB = (0x70, 0x89, 0x86)


def _illegal(table: np.ndarray) -> None:
    """Entries 101..254: green for illegal positive values, red to yellow for negative ones."""
    table[101:128] = (0, 255, 0, 255)
    i = np.arange(128, 255)
    table[128:255, 0] = 255
    table[128:255, 1] = (255 * (i - 128)) // (254 - 128)
    table[128:255, 2] = 0
    table[128:255, 3] = 255
    table[255] = (*UNKNOWN_RGB, 255)


def map_palette() -> np.ndarray:
    """RViz's ``map`` scheme: (256, 4) uint8 RGBA indexed by the cell's byte."""
    table = np.zeros((256, 4), np.uint8)
    v = 255 - (255 * np.arange(101)) // 100
    table[:101] = np.stack([v, v, v, np.full(101, 255)], axis=1)
    _illegal(table)
    return table


def costmap_palette() -> np.ndarray:
    """RViz's ``costmap`` scheme: (256, 4) uint8 RGBA indexed by the cell's byte."""
    table = np.zeros((256, 4), np.uint8)  # 0: fully transparent
    v = (255 * np.arange(1, 99)) // 100
    table[1:99] = np.stack([v, np.zeros(98), 255 - v, np.full(98, 255)], axis=1)
    table[99] = (0, 255, 255, 255)  # inscribed
    table[100] = (255, 0, 255, 255)  # lethal
    _illegal(table)
    return table


def raw_palette() -> np.ndarray:
    """RViz's ``raw`` scheme: (256, 4) uint8 RGBA, grey level = byte."""
    i = np.arange(256)
    return np.stack([i, i, i, np.full(256, 255)], axis=1).astype(np.uint8)


PALETTES = {"map": map_palette(), "costmap": costmap_palette(), "raw": raw_palette()}


def _keys(scheme: str) -> np.ndarray:
    """Per byte, ``rank * 256 + byte`` (uint16): a shrunk block keeps its largest key, so the
    most telling cell (walls, high costs) stays."""
    byte = np.arange(256)
    if scheme == "raw":
        rank = byte
    else:
        rank = np.zeros(256, np.int64)
        rank[1:101] = byte[1:101] + 1  # more occupied / costlier first
        rank[255] = 1  # unknown over free
        rank[101:255] = 200  # illegal values show
    return (rank * 256 + byte).astype(np.uint16)


_KEYS = {scheme: _keys(scheme) for scheme in SCHEMES}


def shrink(cells: np.ndarray, factor: int, scheme: str) -> np.ndarray:
    """Shrink a byte grid by ``factor`` keeping each block's most telling cell.

    ``map``/``costmap``: the most occupied (costliest) cell, so walls stay; ``raw``:
    the largest byte. Cells outside the grid count as free.
    """
    rows, cols = cells.shape
    h, w = -(-rows // factor) * factor, -(-cols // factor) * factor
    key = np.zeros((h, w), np.uint16)
    key[:rows, :cols] = _KEYS[scheme][cells]
    # factor^2 strided maxima: far faster than a reduction over a 4-d view
    out = key[0::factor, 0::factor].copy()
    for dr in range(factor):
        for dc in range(factor):
            if dr or dc:
                np.maximum(out, key[dr::factor, dc::factor], out=out)
    return (out & 255).astype(np.uint8)


def colour_cells(cells: np.ndarray, scheme: str, alpha: float) -> np.ndarray:
    """RGBA (rows, cols, 4) uint8 of a byte grid in ``scheme`` under the display's ``alpha``.

    Raises:
        ValueError: An unknown scheme.
    """
    if scheme not in PALETTES:
        raise ValueError(f"unknown Color Scheme '{scheme}' (one of: {', '.join(SCHEMES)})")
    words = PALETTES[scheme].view(np.uint32)[:, 0]  # one gather of 4-byte words
    rgba = words[cells].view(np.uint8).reshape(*cells.shape, 4)
    if scheme in TRANSPARENT_SCHEMES or alpha < OPAQUE_ALPHA:
        rgba[..., 3] = np.round(rgba[..., 3] * float(np.clip(alpha, 0.0, 1.0))).astype(np.uint8)
    else:
        rgba[..., 3] = 255
    return rgba


def is_opaque(scheme: str, alpha: float) -> bool:
    """Whether RViz draws the scheme without blending at this ``alpha``."""
    return scheme not in TRANSPARENT_SCHEMES and alpha >= OPAQUE_ALPHA
