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
    if args.verb == "show":
        return show(args.type)
    if args.verb == "md5":
        return md5(args.type)
    return list_services(args.package)


def show(type_name: str) -> int:
    """rossrv show: a service's request and response fields.

    Raises:
        MessageError: An unknown service type.
    """
    from workbench.introspect.definitions import show_service

    print(show_service(type_name))
    return 0


def md5(type_name: str) -> int:
    """rossrv md5: a service's md5sum."""
    from workbench.msgs import get_service

    print(get_service(type_name)._md5sum)
    return 0


def list_services(package: str | None = None) -> int:
    """rossrv list: the service types (of one package).

    Raises:
        MessageError: The package has no service types.
    """
    from workbench.msgs import list_services as service_types

    names = service_types(package)
    if not names and package:
        from workbench.errors import MessageError

        raise MessageError(f"no service types in package '{package}'")
    print("\n".join(names))
    return 0
