"""Zenoh key expressions of the workbench bus.

Graph names are encoded into one key chunk each by replacing ``/`` with
``%`` (ROS names never contain ``%``), so every key has a fixed number of
chunks and can be matched with single-chunk wildcards:

=================================================  ===========================================
``wb/t/<md5>/<pkg>/<Name>/<topic>/<node>``         message data (ROS 1 serialized bytes) from the
                                                   publishing node (ROS's ``callerid``)
``wb/l/<md5>/<pkg>/<Name>/<topic>/<node>/<session>``
                                                   latched message of one publisher (queryable)
``wb/b/<session>``                                 delivery barrier of a session (queryable): it
                                                   answers once everything sent to it before the
                                                   query has been handed to its subscriptions
``wb/s/<md5>/<pkg>/<Name>/<service>``              service queryable (request/response bytes)
``wb/g/<session>/<pid>/n/<node>``                  liveliness: a node
``wb/g/<session>/<pid>/<kind>/<node>/<md5>/<pkg>/<Name>/<name>``
                                                   liveliness: a pub/sub/srv of a node
``wb/k/<node>``                                    "shut down": a newer node took this name
``wb/p/<op>``                                      parameter server of the core (queryable)
``wb/core``                                        liveliness: the core
=================================================  ===========================================

A type-agnostic subscriber has md5 and type ``_`` / ``_/_``.
"""

from __future__ import annotations

from dataclasses import dataclass


def enc(name: str) -> str:
    """``/turtle1/cmd_vel`` -> ``%turtle1%cmd_vel``."""
    return name.replace("/", "%")


def dec(chunk: str) -> str:
    return chunk.replace("%", "/")


def type_chunks(type_name: str, md5: str) -> str:
    if type_name == "*":
        return "_/_/_"
    return f"{md5}/{type_name}"


def chunks_type(md5: str, pkg: str, name: str) -> tuple[str, str]:
    if md5 == "_":
        return "*", "*"
    return f"{pkg}/{name}", md5


def data_key(topic: str, type_name: str, md5: str, node: str) -> str:
    return f"wb/t/{type_chunks(type_name, md5)}/{enc(topic)}/{enc(node)}"


def data_selector(topic: str) -> str:
    return f"wb/t/*/*/*/{enc(topic)}/*"


def latch_key(topic: str, type_name: str, md5: str, node: str, session: str) -> str:
    return f"wb/l/{type_chunks(type_name, md5)}/{enc(topic)}/{enc(node)}/{session}"


def latch_selector(topic: str) -> str:
    return f"wb/l/*/*/*/{enc(topic)}/*/*"


def barrier_key(session: str) -> str:
    return f"wb/b/{session}"


def service_key(service: str, type_name: str, md5: str) -> str:
    return f"wb/s/{type_chunks(type_name, md5)}/{enc(service)}"


def service_selector(service: str) -> str:
    return f"wb/s/*/*/*/{enc(service)}"


def node_token(session: str, pid: int, node: str) -> str:
    return f"wb/g/{session}/{pid}/n/{enc(node)}"


def endpoint_token(
    session: str, pid: int, kind: str, node: str, name: str, type_name: str, md5: str
) -> str:
    return f"wb/g/{session}/{pid}/{kind}/{enc(node)}/{type_chunks(type_name, md5)}/{enc(name)}"


def kill_key(node: str) -> str:
    return f"wb/k/{enc(node)}"


@dataclass(frozen=True)
class Token:
    """A parsed liveliness key."""

    session: str
    pid: int
    kind: str  # n, pub, sub, srv
    node: str
    name: str = ""
    type: str = ""
    md5: str = ""


def parse_token(key: str) -> Token | None:
    parts = key.split("/")
    if len(parts) < 6 or parts[:2] != ["wb", "g"]:
        return None
    try:
        pid = int(parts[3])
    except ValueError:
        return None
    if parts[4] == "n" and len(parts) == 6:
        return Token(parts[2], pid, "n", dec(parts[5]))
    if parts[4] in ("pub", "sub", "srv") and len(parts) == 10:
        type_name, md5 = chunks_type(parts[6], parts[7], parts[8])
        return Token(parts[2], pid, parts[4], dec(parts[5]), dec(parts[9]), type_name, md5)
    return None


def parse_data_key(key: str) -> tuple[str, str, str, str] | None:
    """A data, latch or service key -> (topic, type, md5, publishing node or ``""``)."""
    parts = key.split("/")
    if len(parts) < 6 or parts[0] != "wb" or parts[1] not in ("t", "l", "s"):
        return None
    type_name, md5 = chunks_type(parts[2], parts[3], parts[4])
    node = dec(parts[6]) if len(parts) > 6 and parts[1] != "s" else ""
    return dec(parts[5]), type_name, md5, node
