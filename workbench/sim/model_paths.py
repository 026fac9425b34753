"""Where ``model://NAME`` is found: see :mod:`workbench.model.gazebo_models`."""

from __future__ import annotations

from workbench.model.gazebo_models import (
    BUILT_IN_MODELS,
    find_model_dir,
    find_model_file,
    model_search_path,
    resolve_model_uri,
)

__all__ = [
    "BUILT_IN_MODELS",
    "find_model_dir",
    "find_model_file",
    "model_search_path",
    "resolve_model_uri",
]
