"""``workbench param``: rosparam (list, get, set, delete, dump, load)."""

from __future__ import annotations

import argparse
import contextlib
from collections.abc import Iterator
from typing import Any


def configure(parser: argparse.ArgumentParser) -> None:
    verbs = parser.add_subparsers(dest="verb", metavar="VERB", required=True)
    listing = verbs.add_parser("list", help="list parameter names")
    listing.add_argument("namespace", nargs="?", default="/")
    get = verbs.add_parser("get", help="print a parameter (or a namespace) as YAML")
    get.add_argument("name")
    set_ = verbs.add_parser("set", help="set a parameter from a YAML value")
    set_.add_argument("name")
    set_.add_argument("value")
    delete = verbs.add_parser("delete", help="delete a parameter or namespace")
    delete.add_argument("name")
    dump = verbs.add_parser("dump", help="write parameters to a YAML file")
    dump.add_argument("file")
    dump.add_argument("namespace", nargs="?", default="/")
    load = verbs.add_parser("load", help="set parameters from a YAML file")
    load.add_argument("file")
    load.add_argument("namespace", nargs="?", default="/")


def run(args: argparse.Namespace) -> int:
    if args.verb == "list":
        return list_params(args.namespace)
    if args.verb == "get":
        return get(args.name)
    if args.verb == "set":
        return set_param(args.name, args.value)
    if args.verb == "delete":
        return delete(args.name)
    if args.verb == "dump":
        return dump(args.file, args.namespace)
    return load(args.file, args.namespace)


@contextlib.contextmanager
def _server() -> Iterator[Any]:
    """The parameter server of the bus, through the tool's own node."""
    from workbench.introspect.session import cli_node, settle

    node = cli_node("rosparam")
    try:
        settle(node.bus)
        yield node.bus.params
    finally:
        node.shutdown()


def list_params(namespace: str = "/") -> int:
    """rosparam list: the parameter names under ``namespace``."""
    from workbench.introspect import params

    with _server() as server:
        print("\n".join(params.list_names(server, namespace)))
    return 0


def get(name: str) -> int:
    """rosparam get: a parameter (or a namespace) as YAML.

    Raises:
        BusError: No such parameter.
    """
    from workbench.introspect import params

    with _server() as server:
        print(params.get_text(server, name))
    return 0


def set_param(name: str, value: str) -> int:
    """rosparam set: set ``name`` from a YAML value (``1`` is an int, ``'1'`` a string).

    Raises:
        BusError: The value is not YAML.
    """
    from workbench.introspect import params

    with _server() as server:
        params.set_text(server, name, value)
    return 0


def delete(name: str) -> int:
    """rosparam delete: delete a parameter or a namespace.

    Raises:
        BusError: No such parameter.
    """
    from workbench.introspect import params

    with _server() as server:
        params.delete(server, name)
    return 0


def dump(file: str, namespace: str = "/") -> int:
    """rosparam dump: write the parameters under ``namespace`` to a YAML file."""
    from workbench.introspect import params

    with _server() as server:
        params.dump(server, file, namespace)
    return 0


def load(file: str, namespace: str = "/") -> int:
    """rosparam load: set parameters from a YAML file, under ``namespace``.

    Raises:
        BusError: The file cannot be read or is not a YAML mapping.
    """
    from workbench.introspect import params

    with _server() as server:
        params.load(server, file, namespace)
    return 0
