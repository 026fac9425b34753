"""``workbench msg``: rosmsg -- show message definitions, md5sums and the list of types."""

from __future__ import annotations

import argparse


def configure(parser: argparse.ArgumentParser) -> None:
    verbs = parser.add_subparsers(dest="verb", metavar="VERB", required=True)
    show = verbs.add_parser("show", help="show a message's fields (nested types expanded)")
    show.add_argument("type", help="message type, e.g. geometry_msgs/Twist")
    md5 = verbs.add_parser("md5", help="print a message's md5sum")
    md5.add_argument("type")
    listing = verbs.add_parser("list", help="list message types")
    listing.add_argument("package", nargs="?", help="only this package")
    package = verbs.add_parser("package", help="list the message types of one package")
    package.add_argument("package")


def run(args: argparse.Namespace) -> int:
    from workbench.introspect.definitions import show_message
    from workbench.msgs import get_type, list_services, list_types, md5sum

    if args.verb == "show":
        print(show_message(args.type))
    elif args.verb == "md5":
        print(md5sum(get_type(args.type)._type))
    else:
        parts = {
            f"{s}{end}" for s in list_services(args.package) for end in ("Request", "Response")
        }
        names = [n for n in list_types(args.package) if n not in parts]
        if not names and args.package:
            from workbench.errors import MessageError

            raise MessageError(f"no message types in package '{args.package}'")
        print("\n".join(names))
    return 0
