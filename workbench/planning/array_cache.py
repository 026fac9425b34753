"""Arrays that take a while to compute and never change for the same inputs, kept on disk.

Sphere covers of a robot's shapes and exact distance tables of its close body
pairs are the same on every run; computing them costs seconds. They are kept
as ``.npz`` files under ``<cache>/<kind>/`` (see :func:`workbench.paths.cache_root`),
named by a digest of everything they depend on. A file that cannot be read or
written is simply recomputed: the cache only ever saves time.
"""

from __future__ import annotations

import hashlib
import os
from collections.abc import Callable

import numpy as np

_MEMORY: dict[tuple[str, str], dict[str, np.ndarray]] = {}


def digest(*parts) -> str:
    """A short hex digest of arrays, strings and numbers (arrays by dtype, shape and bytes)."""
    h = hashlib.sha256()
    for part in parts:
        if isinstance(part, np.ndarray):
            h.update(f"{part.dtype}{part.shape}".encode())
            h.update(np.ascontiguousarray(part).tobytes())
        else:
            h.update(repr(part).encode())
        h.update(b"\0")
    return h.hexdigest()[:32]


def cached_arrays(
    kind: str, key: str, compute: Callable[[], dict[str, np.ndarray]]
) -> dict[str, np.ndarray]:
    """The arrays stored under ``kind``/``key``, computing and storing them when missing."""
    from workbench.paths import cache_root

    if (kind, key) in _MEMORY:
        return _MEMORY[kind, key]
    path = cache_root() / kind / f"{key}.npz"
    try:
        with np.load(path) as stored:
            arrays = {name: stored[name] for name in stored.files}
    except (OSError, ValueError, EOFError):
        arrays = {name: np.asarray(value) for name, value in compute().items()}
        try:
            path.parent.mkdir(parents=True, exist_ok=True)
            partial = path.with_name(f"{key}.{os.getpid()}.tmp.npz")
            np.savez(partial, **arrays)
            os.replace(partial, path)
        except OSError:
            pass
    _MEMORY[kind, key] = arrays
    return arrays
