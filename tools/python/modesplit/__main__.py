"""python -m modesplit: small commands over the package.

    python -m modesplit version        the library's version and path
    python -m modesplit export ...     USD export (modesplit.usd_export, when
                                       that module is installed)
"""
import importlib
import sys


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    if not argv or argv[0] in ("-h", "--help"):
        print(__doc__.strip())
        return 0 if argv else 2
    cmd, rest = argv[0], argv[1:]
    if cmd == "version":
        from . import lib, version
        print("libmodesplit %s (%s)" % (version(), lib().path))
        return 0
    if cmd == "export":
        try:
            mod = importlib.import_module("modesplit.usd_export")
        except ModuleNotFoundError as e:
            if e.name != "modesplit.usd_export":
                raise
            print("modesplit: export needs modesplit.usd_export, which this install lacks",
                  file=sys.stderr)
            return 2
        # usd_export.main(argv) or main() reading sys.argv: either works
        import inspect
        if inspect.signature(mod.main).parameters:
            return mod.main(rest)
        sys.argv = ["python -m modesplit export"] + rest
        return mod.main()
    print("modesplit: unknown command %r (version, export)" % cmd, file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main())
