"""Reading SDF text as libsdformat's XML parser (TinyXML2) reads it.

TinyXML2 is more forgiving than libxml2 in two ways real model files rely on
(osrf/gazebo_models has both): an XML declaration after blank lines, and
``--`` inside a comment. Both are accepted here; every other XML error is
refused as before. Line numbers stay those of the file.
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

from lxml import etree

from workbench.errors import ModelError
from workbench.model.limits import xml_error_text

_LATE_DECLARATION = re.compile(r"^(\s+)<\?xml[^>]*\?>")
#: libxml2 errors TinyXML2 does not raise.
_FORGIVEN = {"ERR_HYPHEN_IN_COMMENT"}


def parse_sdf_text(text: str, path: Path | None = None) -> Any:
    """The root element of SDF ``text``, parsed as libsdformat would accept it.

    Raises:
        ModelError: Not well-formed XML (file and line in the error).
    """
    # blank out a declaration after leading blank lines (keeping the line count)
    text = _LATE_DECLARATION.sub(
        lambda m: m.group(1) + " " * (len(m.group(0)) - len(m.group(1))), text
    )
    data = text.encode()
    strict = etree.XMLParser(resolve_entities=False, no_network=True, huge_tree=True)
    try:
        return etree.fromstring(data, strict)
    except etree.XMLSyntaxError as error:
        # the parser's own log holds this parse's errors only (the exception's may hold
        # earlier ones of the thread)
        if {entry.type_name for entry in strict.error_log} <= _FORGIVEN:
            lenient = etree.XMLParser(
                resolve_entities=False, no_network=True, huge_tree=True, recover=True
            )
            root = etree.fromstring(data, lenient)
            if root is not None:
                return root
        raise ModelError(
            f"not well-formed XML: {xml_error_text(str(error.msg))}",
            path=path,
            line=error.lineno,
            hint="fix the XML syntax at that line",
        ) from None


def read_sdf_text(path: Path) -> Any:
    """:func:`parse_sdf_text` of a file (its size already checked by the caller).

    Raises:
        ModelError: Unreadable, not UTF-8, or not well-formed XML.
    """
    try:
        text = path.read_text(encoding="utf-8")
    except UnicodeDecodeError:
        raise ModelError("the file is not UTF-8 text", path=path) from None
    except OSError as error:
        raise ModelError(f"cannot read the file: {error.strerror}", path=path) from None
    return parse_sdf_text(text, path)
