"""What Drake must never see: checked before a URDF or SDF reaches its parser.

Drake aborts the whole process (``Failure at ...``) or crashes on some input
instead of raising: NaN joint limits, a robot name of tens of thousands of
characters, ``inf`` where a vector is read. Every name and number of a model is
checked here first, and the first problem is raised as one line naming the file,
the line and the element.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

from workbench.errors import ModelError
from workbench.model.limits import (
    MAX_LINKS,
    MAX_MODEL_BYTES,
    MAX_SHAPE_SIZE,
    check_input_file,
    name_problem,
    shown_name,
    uri_problem,
)

#: Numbers URDF and SDF share: sizes, inertia, joint limits and dynamics.
_SHARED_NUMBERS: tuple[str, ...] = (
    "xyz",
    "size",
    "radius",
    "length",
    "scale",
    "lower",
    "upper",
    "effort",
)
_SHARED_NUMBERS += ("velocity", "ixx", "ixy", "ixz", "iyy", "iyz", "izz", "damping", "friction")
#: URDF attributes that hold numbers (anything Drake or ROS reads as a number).
URDF_NUMBERS = frozenset(
    _SHARED_NUMBERS
    + ("rpy", "value", "rgba", "multiplier", "offset", "soft_lower_limit", "soft_upper_limit")
    + ("k_position", "k_velocity", "rising", "falling", "reference_position")
)
#: URDF elements whose ``name`` is a name Drake keeps (materials reach Drake without one).
URDF_NAMED = ("robot", "link", "joint", "visual", "collision", "transmission")
#: Elements whose name may be blank: ROS reads ``name=""``, and Drake is given none
#: (:mod:`workbench.model.urdf_for_drake`) and names them itself.
_MAY_BE_EMPTY = ("visual", "collision", "transmission")
#: SDF elements whose ``name`` is a name Drake keeps.
SDF_NAMED = ("model", "link", "joint", "visual", "collision", "frame", "world", "include")
#: SDF elements whose text is numbers.
SDF_NUMBERS = frozenset(
    _SHARED_NUMBERS
    + ("pose", "mass", "spring_reference", "spring_stiffness", "stiffness", "dissipation")
    + ("mu", "mu2", "radii")
)
#: SDF elements whose text names another element (a joint's links).
SDF_REFERENCES = ("parent", "child")
#: SDF shapes and the sizes that must be above zero (sphere radius may be zero).
SDF_SIZES = {"box": ("size",), "cylinder": ("radius", "length"), "capsule": ("radius", "length")}
SDF_SIZES |= {"ellipsoid": ("radii",), "sphere": ()}
#: URDF shapes and their size attributes (each at most :data:`MAX_SHAPE_SIZE`).
URDF_SIZES = {"box": ("size",), "cylinder": ("radius", "length"), "sphere": ("radius",)}
URDF_SIZES |= {"capsule": ("radius", "length"), "mesh": ("scale",)}


class ModelInputError(ModelError):
    """A name or number in a model that Drake cannot be given."""


def _not_finite(label: str, shown: str, token: str) -> str:
    if shown.strip() == token:
        return f"{label}: {_cut(token)} is not a finite number"
    return f"{label}: {_cut(shown)} holds {_cut(token)}, which is not a finite number"


def _cut(text: str, length: int = 60) -> str:
    """``text`` as a message shows it: at most ``length`` characters."""
    return text if len(text) <= length else text[: length - 3] + "..."


def _non_finite(text: str) -> str | None:
    for token in text.replace(",", " ").split():
        try:
            value = float(token)
        except ValueError:
            continue
        if not math.isfinite(value):
            return token
    return None


def _label(element: Any, kinds: tuple[str, ...]) -> str:
    """``joint 'j' <limit>``: the nearest named element and the path below it."""
    path: list[str] = []
    node = element
    while node is not None and isinstance(node.tag, str):
        if node.tag in kinds and node.get("name") is not None:
            head = f"{node.tag} '{shown_name(node.get('name'))}'"
            return " ".join([head, *reversed(path)])
        path.append(f"<{node.tag}>")
        node = node.getparent()
    return " ".join(reversed(path))


def _fail(message: str, path: Path | None, element: Any, hint: str) -> ModelInputError:
    return ModelInputError(message, path=path, line=element.sourceline, hint=hint)


def _check_names(root: Any, kinds: tuple[str, ...], path: Path | None) -> None:
    counts = {"link": 0, "joint": 0}
    for element in root.iter(*kinds):
        name = element.get("name")
        if element.tag in counts:
            counts[element.tag] += 1
        if name is None or (not name.strip() and element.tag in _MAY_BE_EMPTY):
            continue
        problem = name_problem(name)
        if problem is not None:
            raise _fail(
                f"<{element.tag}> name '{shown_name(name)}' {problem}",
                path,
                element,
                "give it a short name of printable characters",
            )
    for kind, count in counts.items():
        if count > MAX_LINKS:
            raise ModelInputError(
                f"the model has {count:,} {kind}s; workbench loads at most {MAX_LINKS:,}",
                path=path,
                hint="see 'Limits on input' in the README",
            )


def check_urdf_element(root: Any, path: Path | None) -> None:
    """Check a URDF ``<robot>`` element's names and numbers before Drake parses it.

    Raises:
        ModelInputError: A name too long or with control characters, too many links,
            or a number that is NaN or infinite (file, line and element named).
    """
    _check_names(root, URDF_NAMED, path)
    for element in root.iter():
        if not isinstance(element.tag, str) or element.tag == "gazebo":
            continue
        for attribute, text in element.attrib.items():
            if attribute not in URDF_NUMBERS:
                continue
            token = _non_finite(text)
            if token is not None:
                raise _fail(
                    _not_finite(_label(element, URDF_NAMED), f'{attribute}="{text}"', token),
                    path,
                    element,
                    "write finite numbers (a joint without bounds is continuous)",
                )
        parent = element.getparent()
        if element.tag in URDF_SIZES and parent is not None and parent.tag == "geometry":
            _check_urdf_shape(element, path)


def _too_big(label: str, what: str, value: float) -> str:
    largest = f"{MAX_SHAPE_SIZE:g} m, the largest shape workbench takes"
    return f"{label}: {what} {value:g} is more than {largest}"


def _check_urdf_shape(shape: Any, path: Path | None) -> None:
    for attribute in URDF_SIZES[shape.tag]:
        for token in (shape.get(attribute) or "").split():
            try:
                value = abs(float(token))
            except ValueError:
                continue
            if value > MAX_SHAPE_SIZE:
                raise _fail(
                    _too_big(_label(shape, URDF_NAMED), attribute, value),
                    path,
                    shape,
                    "give the shape's real size in metres",
                )


def check_sdf_file(path: Path) -> None:
    """Check an SDF file's names, numbers and shape sizes before Drake parses it.

    Raises:
        ModelInputError: A bad name, too many links, a NaN or infinite number, a shape
            size that is not above zero, or joint limits that are reversed.
        ModelError: The file cannot be read or is not XML.
    """
    from workbench.model.sdf_xml import read_sdf_text

    check_input_file(path, "model file", MAX_MODEL_BYTES)
    check_sdf_element(read_sdf_text(path), path)


def check_sdf_element(root: Any, path: Path | None) -> None:
    """:func:`check_sdf_file` for a parsed element (an SDF root, a world's ``<model>``).

    Args:
        root: The element; everything below it is checked.
        path: The file it was read from, for messages (None: text with no file).

    Raises:
        ModelInputError: As :func:`check_sdf_file`.
    """
    _check_names(root, SDF_NAMED, path)
    for element in root.iter():
        if not isinstance(element.tag, str) or element.tag == "plugin":
            continue
        if any(ancestor.tag == "plugin" for ancestor in element.iterancestors()):
            continue
        if element.tag in SDF_NUMBERS and element.text:
            token = _non_finite(element.text)
            if token is not None:
                raise _fail(
                    _not_finite(_label(element, SDF_NAMED), element.text.strip(), token),
                    path,
                    element,
                    "write finite numbers",
                )
        if element.tag in SDF_REFERENCES and element.text and element.getparent().tag == "joint":
            problem = name_problem(element.text.strip())
            if problem is not None:
                raise _fail(
                    f"{_label(element, SDF_NAMED)}: the name '{shown_name(element.text.strip())}' "
                    f"{problem}",
                    path,
                    element,
                    "give it a short name of printable characters",
                )
        if element.tag == "uri" and element.text:
            problem = uri_problem(element.text.strip())
            if problem is not None:
                raise _fail(
                    f"{_label(element, SDF_NAMED)}: '{shown_name(element.text.strip())}' {problem}",
                    path,
                    element,
                    "give the model's folder name or file path",
                )
        if element.tag in SDF_SIZES:
            _check_sdf_shape(element, path)
        elif element.tag == "plane":
            _check_sdf_plane(element, path)
        elif element.tag == "mesh":
            _check_sdf_scale(element, path)
        if element.tag == "limit":
            _check_sdf_limits(element, path)


def _numbers(element: Any) -> list[float]:
    try:
        return [float(token) for token in (element.text or "").split()]
    except ValueError:
        return []


def _check_sdf_shape(shape: Any, path: Path | None) -> None:
    for field in SDF_SIZES[shape.tag]:
        child = shape.find(field)
        if child is None:
            continue
        for value in _numbers(child):
            if not math.isfinite(value):
                continue  # reported as not finite where the number is
            if not value > 0:
                raise _fail(
                    f"{_label(child, SDF_NAMED)}: {field} {value:g} must be more than zero",
                    path,
                    child,
                    "give the shape's real size in metres",
                )
            if value > MAX_SHAPE_SIZE:
                raise _fail(
                    _too_big(_label(child, SDF_NAMED), field, value),
                    path,
                    child,
                    "give the shape's real size in metres",
                )
    radius = shape.find("radius") if shape.tag == "sphere" else None
    if radius is not None and any(value < 0 for value in _numbers(radius)):
        raise _fail(
            f"{_label(radius, SDF_NAMED)}: the radius must be zero or more",
            path,
            radius,
            "give the shape's real size in metres",
        )
    if radius is not None and any(value > MAX_SHAPE_SIZE for value in _numbers(radius)):
        raise _fail(
            _too_big(_label(radius, SDF_NAMED), "radius", max(_numbers(radius))),
            path,
            radius,
            "give the shape's real size in metres",
        )


def _check_sdf_plane(plane: Any, path: Path | None) -> None:
    normal = plane.find("normal")
    values = _numbers(normal) if normal is not None else []
    if normal is not None and len(values) == 3 and not any(values):
        raise _fail(
            f"{_label(normal, SDF_NAMED)}: the plane's normal is 0 0 0, which points nowhere",
            path,
            normal,
            "give the direction the plane faces, e.g. 0 0 1",
        )
    size = plane.find("size")
    values = [v for v in _numbers(size) if math.isfinite(v)] if size is not None else []
    if any(abs(value) > MAX_SHAPE_SIZE for value in values):
        raise _fail(
            _too_big(_label(size, SDF_NAMED), "size", max(map(abs, values))),
            path,
            size,
            "give the plane's real size in metres",
        )


def _check_sdf_scale(mesh: Any, path: Path | None) -> None:
    scale = mesh.find("scale")
    values = _numbers(scale) if scale is not None else []
    if any(abs(value) > MAX_SHAPE_SIZE for value in values):
        raise _fail(
            f"{_label(scale, SDF_NAMED)}: scale {max(map(abs, values)):g} is larger than "
            f"{MAX_SHAPE_SIZE:g}",
            path,
            scale,
            "scale the mesh by its real factor (1 keeps its size)",
        )


def _check_sdf_limits(limit: Any, path: Path | None) -> None:
    lower, upper = limit.find("lower"), limit.find("upper")
    if lower is None or upper is None:
        return
    low, high = _numbers(lower), _numbers(upper)
    if low and high and low[0] > high[0]:
        raise _fail(
            f"{_label(limit, SDF_NAMED)}: lower {low[0]:g} is above upper {high[0]:g}",
            path,
            limit,
            "swap them",
        )
