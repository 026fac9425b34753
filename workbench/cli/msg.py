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
    if args.verb == "show":
        return show(args.type)
    if args.verb == "md5":
        return md5(args.type)
    return list_messages(args.package)


def show(type_name: str) -> int:
    """rosmsg show: a message's fields, nested types expanded.

    Raises:
        MessageError: An unknown type (naming close matches).
    """
    from workbench.introspect.definitions import show_message

    print(show_message(type_name))
    return 0


def md5(type_name: str) -> int:
    """rosmsg md5: a message's md5sum."""
    from workbench.msgs import get_type, md5sum

    print(md5sum(get_type(type_name)._type))
    return 0


def list_messages(package: str | None = None) -> int:
    """rosmsg list / package: the message types (of one package), without service parts.

    Raises:
        MessageError: The package has no message types.
    """
    from workbench.msgs import list_services, list_types

    parts = {f"{s}{end}" for s in list_services(package) for end in ("Request", "Response")}
    names = [n for n in list_types(package) if n not in parts]
    if not names and package:
        from workbench.errors import MessageError

        raise MessageError(f"no message types in package '{package}'")
    print("\n".join(names))
    return 0
