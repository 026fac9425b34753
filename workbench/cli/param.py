"""``workbench param``: rosparam (list, get, set, delete, dump, load)."""

from __future__ import annotations

import argparse
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
    from workbench.introspect import params
    from workbench.introspect.session import cli_node, settle

    node = cli_node("rosparam")
    try:
        settle(node.bus)
        server = node.bus.params
        if args.verb == "list":
            print("\n".join(params.list_names(server, args.namespace)))
        elif args.verb == "get":
            print(params.get_text(server, args.name))
        elif args.verb == "set":
            params.set_text(server, args.name, args.value)
        elif args.verb == "delete":
            params.delete(server, args.name)
        elif args.verb == "dump":
            params.dump(server, args.file, args.namespace)
        else:
            params.load(server, args.file, args.namespace)
        return 0
    finally:
        node.shutdown()


__all__: list[Any] = []
