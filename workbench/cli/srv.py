"""``workbench srv``: rossrv -- show service definitions, md5sums and the list of types."""

from __future__ import annotations

import argparse


def configure(parser: argparse.ArgumentParser) -> None:
    verbs = parser.add_subparsers(dest="verb", metavar="VERB", required=True)
    show = verbs.add_parser("show", help="show a service's request and response fields")
    show.add_argument("type", help="service type, e.g. turtlesim/Spawn")
    md5 = verbs.add_parser("md5", help="print a service's md5sum")
    md5.add_argument("type")
    listing = verbs.add_parser("list", help="list service types")
    listing.add_argument("package", nargs="?", help="only this package")


def run(args: argparse.Namespace) -> int:
    from workbench.introspect.definitions import show_service
    from workbench.msgs import get_service, list_services

    if args.verb == "show":
        print(show_service(args.type))
    elif args.verb == "md5":
        print(get_service(args.type)._md5sum)
    else:
        names = list_services(args.package)
        if not names and args.package:
            from workbench.errors import MessageError

            raise MessageError(f"no service types in package '{args.package}'")
        print("\n".join(names))
    return 0
