"""Message types for bags: md5sums and definitions in, message objects out.

Types workbench knows come from :mod:`workbench.msgs`. A bag recorded
elsewhere may carry types workbench lacks; those are decoded from the full
definition stored in the bag's connection record (rosbags' typestore
parses it), so any valid bag can be read.
"""

from __future__ import annotations

from functools import lru_cache
from typing import Any

from workbench.bag.reader import BagConnection
from workbench.errors import MessageError


def type_info(typename: str) -> tuple[str, str]:
    """``(md5sum, full definition)`` of a workbench message type.

    Raises:
        MessageError: unknown type (names close matches).
    """
    from workbench.msgs import definition, md5sum

    return md5sum(typename), definition(typename)


@lru_cache(maxsize=256)
def _foreign_store(typename: str, definition: str):
    from rosbags.typesys import Stores, get_types_from_msg, get_typestore

    store = get_typestore(Stores.EMPTY)
    store.register(get_types_from_msg(definition, typename))
    return store


def decode(conn: BagConnection, data: bytes) -> Any:
    """Deserialize one message of ``conn``.

    Known types with the same md5sum become ``workbench.msgs`` objects; any
    other type is decoded from the bag's own definition (a rosbags dataclass).
    """
    from workbench import msgs

    try:
        if msgs.md5sum(conn.typename) == conn.md5sum:
            return msgs.deserialize(data, conn.typename)
    except MessageError:
        pass
    store = _foreign_store(conn.typename, conn.definition)
    name = conn.typename.replace("/", "/msg/", 1) if "/msg/" not in conn.typename else conn.typename
    return store.deserialize_ros1(data, name)
