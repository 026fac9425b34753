"""``workbench service``: rosservice (list, call, type, find, info)."""

from __future__ import annotations

import argparse
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
    from workbench.introspect import graphtext
    from workbench.introspect.session import cli_node, graph

    node = cli_node("rosservice")
    try:
        g = graph(node.bus)
        if args.verb == "list":
            text = graphtext.service_list(g, nodes=args.nodes)
        elif args.verb == "type":
            text = graphtext.require_service(g, args.service).type
        elif args.verb == "find":
            from workbench.msgs import get_service

            text = graphtext.service_find(g, get_service(args.type)._type)
        elif args.verb == "info":
            text = graphtext.service_info(g, args.service)
        else:
            text = _call(node, g, args)
        if text:
            print(text)
        return 0
    finally:
        node.shutdown()


def _call(node: Any, g: Any, args: argparse.Namespace) -> str:
    from workbench.errors import MessageError
    from workbench.introspect.args import message_from_args
    from workbench.introspect.echo import format_value
    from workbench.introspect.graphtext import require_service
    from workbench.msgs import get_service

    words = [w for w in args.args if w != "--"]
    record = require_service(g, args.service)
    service = get_service(record.type)
    fields = " ".join(service.Request.__slots__) or "no arguments"
    try:
        request = message_from_args(service.Request, words, what=f"service {record.name}")
    except MessageError as error:
        raise MessageError(error.message, hint=f"{record.name} takes: {fields}") from None
    response = node.create_client(record.name, service).call(request, timeout=10.0)
    return format_value(response) if response.__slots__ else ""
