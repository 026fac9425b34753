"""``workbench service``: rosservice (list, call, type, find, info)."""

from __future__ import annotations

import argparse
import contextlib
from collections.abc import Iterator
from typing import Any


def configure(parser: argparse.ArgumentParser) -> None:
    verbs = parser.add_subparsers(dest="verb", metavar="VERB", required=True)
    listing = verbs.add_parser("list", help="list offered services")
    listing.add_argument("-n", "--nodes", action="store_true", help="with the nodes offering them")
    call = verbs.add_parser("call", help="call a service with YAML arguments")
    call.add_argument("service")
    call.add_argument(
        "args", nargs=argparse.REMAINDER, help="request fields in order, or a YAML dict"
    )
    kind = verbs.add_parser("type", help="print a service's type")
    kind.add_argument("service")
    find = verbs.add_parser("find", help="services of a type")
    find.add_argument("type")
    info = verbs.add_parser("info", help="node, type and arguments of a service")
    info.add_argument("service")


def run(args: argparse.Namespace) -> int:
    if args.verb == "list":
        return list_services(nodes=args.nodes)
    if args.verb == "type":
        return service_type(args.service)
    if args.verb == "find":
        return find(args.type)
    if args.verb == "info":
        return info(args.service)
    return call(args.service, [w for w in args.args if w != "--"])


@contextlib.contextmanager
def _session() -> Iterator[tuple[Any, Any]]:
    """The tool's own node and the bus graph."""
    from workbench.introspect.session import cli_node, graph

    node = cli_node("rosservice")
    try:
        yield node, graph(node.bus)
    finally:
        node.shutdown()


def _print(text: str) -> int:
    if text:
        print(text)
    return 0


def list_services(*, nodes: bool = False) -> int:
    """rosservice list: the offered services (with the nodes offering them)."""
    from workbench.introspect import graphtext

    with _session() as (_, g):
        return _print(graphtext.service_list(g, nodes=nodes))


def service_type(service: str) -> int:
    """rosservice type: a service's type.

    Raises:
        BusError: No such service.
    """
    from workbench.introspect import graphtext

    with _session() as (_, g):
        return _print(graphtext.require_service(g, service).type)


def find(type_name: str) -> int:
    """rosservice find: the services of a type.

    Raises:
        MessageError: An unknown service type.
    """
    from workbench.introspect import graphtext
    from workbench.msgs import get_service

    kind = get_service(type_name)._type  # an unknown type fails before joining the bus
    with _session() as (_, g):
        return _print(graphtext.service_find(g, kind))


def info(service: str) -> int:
    """rosservice info: the node, type and arguments of a service."""
    from workbench.introspect import graphtext

    with _session() as (_, g):
        return _print(graphtext.service_info(g, service))


def call(service: str, words: list[str]) -> int:
    """rosservice call: call ``service`` with request fields in order, or a YAML dict.

    Raises:
        BusError: No such service, or no answer within 10 s.
        MessageError: The arguments do not fit the request (naming its fields).
    """
    with _session() as (node, g):
        return _print(_call(node, g, service, words))


def _call(node: Any, g: Any, service_name: str, words: list[str]) -> str:
    from workbench.errors import MessageError
    from workbench.introspect.args import message_from_args
    from workbench.introspect.echo import format_value
    from workbench.introspect.graphtext import require_service
    from workbench.msgs import get_service

    record = require_service(g, service_name)
    service = get_service(record.type)
    fields = " ".join(service.Request.__slots__) or "no arguments"
    try:
        request = message_from_args(service.Request, words, what=f"service {record.name}")
    except MessageError as error:
        raise MessageError(error.message, hint=f"{record.name} takes: {fields}") from None
    response = node.create_client(record.name, service).call(request, timeout=10.0)
    return format_value(response) if response.__slots__ else ""
