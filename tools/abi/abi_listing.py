#!/usr/bin/env python3
"""The public ABI of libmodesplit as one JSON listing.

What it lists, from the public headers (include/modesplit/*.h) and the
compiler that builds the library:
  functions  every function a header declares: its C signature, return and
             parameter types, and whether libmodesplit.so exports it
             (`nm -D`); a symbol the library exports that no header
             declares is an error;
  structs    every public struct: sizeof, alignment, each field's type,
             offset and size (a C program printing sizeof/offsetof);
  enums      every enum constant's value (named and anonymous enums);
  typedefs   the function-pointer and other non-struct typedefs;
  opaque     the handle types whose layout is private;
  macros     the integer MS_* macros (limits, versions, ABI numbers).

The declarations come from pycparser (a C99 parser in Python, Debian's
python3-pycparser) run on the preprocessed headers; every number comes from
the compiler, so the listing is the ABI a C caller gets, not a guess.

    abi_listing.py --lib build/lib/libmodesplit.so --out tools/abi/abi.json
    abi_listing.py --lib build/lib/libmodesplit.so --check tools/abi/abi.json

--check regenerates the listing and fails with a unified diff when it
differs from the committed one (`make check-abi`); after a deliberate ABI
change, `make abi` rewrites it (and the Python package's copy).
"""
import argparse
import difflib
import json
import os
import re
import subprocess
import sys
import tempfile

try:
    from pycparser import c_ast, c_parser
except ImportError:  # pragma: no cover - said plainly, not a traceback
    sys.exit("abi: pycparser is missing (Debian: python3-pycparser; tools/deps.sh installs it)")

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
HEADERS = ["modesplit/modesplit.h", "modesplit/plugin.h"]
# GNU spellings the system headers may use and a C99 parser does not know.
STRIP_GNU = [
    "-D__attribute__(x)=", "-D__extension__=", "-D__restrict=", "-D__restrict__=",
    "-D__inline=", "-D__inline__=", "-D__asm__(x)=", "-D__asm(x)=", "-D__volatile__=",
    "-D__builtin_va_list=int", "-D_Noreturn=", "-D__signed__=signed",
]


def run(cmd, **kw):
    r = subprocess.run(cmd, capture_output=True, text=True, **kw)
    if r.returncode != 0:
        sys.exit("abi: %s failed:\n%s%s" % (" ".join(cmd), r.stdout, r.stderr))
    return r.stdout


def include_dir(args):
    return os.path.abspath(args.include)


def public_file(coord, inc):
    return coord is not None and os.path.abspath(str(coord.file)).startswith(
        os.path.join(inc, "modesplit") + os.sep)


def base_name(t):
    if isinstance(t, c_ast.IdentifierType):
        return " ".join(t.names)
    if isinstance(t, c_ast.Struct):
        return "struct " + (t.name or "{...}")
    if isinstance(t, c_ast.Union):
        return "union " + (t.name or "{...}")
    if isinstance(t, c_ast.Enum):
        return "enum " + (t.name or "{...}")
    raise ValueError("abi: unexpected type node %s" % type(t).__name__)


def dim_str(d):
    if d is None:
        return ""
    if isinstance(d, c_ast.Constant):
        return d.value
    from pycparser import c_generator
    return c_generator.CGenerator().visit(d)


def declarator(t, inner=""):
    """C text of type t declaring `inner` (a name, or "" for the type alone)."""
    if isinstance(t, c_ast.TypeDecl):
        base = " ".join(list(t.quals) + [base_name(t.type)])
        return (base + " " + inner).rstrip() if inner else base
    if isinstance(t, c_ast.PtrDecl):
        q = " ".join(t.quals)
        s = "*" + (q + (" " if inner else "") if q else "") + inner
        if isinstance(t.type, (c_ast.ArrayDecl, c_ast.FuncDecl)):
            s = "(" + s + ")"
        return declarator(t.type, s)
    if isinstance(t, c_ast.ArrayDecl):
        return declarator(t.type, inner + "[" + dim_str(t.dim) + "]")
    if isinstance(t, c_ast.FuncDecl):
        return declarator(t.type, inner + "(" + ", ".join(params(t)) + ")")
    if isinstance(t, c_ast.Typename):
        return declarator(t.type, inner)
    raise ValueError("abi: unexpected declarator node %s" % type(t).__name__)


def params(fd):
    out = []
    for p in (fd.args.params if fd.args else []):
        if isinstance(p, c_ast.EllipsisParam):
            out.append("...")
        else:
            out.append(declarator(p.type, p.name or ""))
    return out or ["void"]


def tidy(s):
    # "float *" not "float*": one space before a star that follows a word
    return re.sub(r"\s+", " ", s).strip()


def parse(args, inc):
    src = "".join("#include <%s>\n" % h for h in HEADERS)
    text = run([args.cc, "-E", "-std=c11", "-I" + inc] + STRIP_GNU + ["-x", "c", "-"],
               input=src)
    return c_parser.CParser().parse(text, "<abi>")


def collect(ast, inc):
    functions, structs, enums, typedefs, opaque = {}, {}, [], {}, []
    anon = {}

    def add_enum(en, name, coord):
        if en.values is None:
            return
        hdr = os.path.basename(str(coord.file))
        if name is None:
            anon[hdr] = anon.get(hdr, 0) + 1
            name = "(anonymous %d in %s)" % (anon[hdr], hdr)
        enums.append((name, [e.name for e in en.values.enumerators]))

    for node in ast.ext:
        if not public_file(node.coord, inc):
            continue
        if isinstance(node, c_ast.Typedef):
            t = node.type
            if isinstance(t, c_ast.TypeDecl) and isinstance(t.type, c_ast.Struct):
                if t.type.decls is None:
                    opaque.append(node.name)
                else:
                    structs[node.name] = [(d.name, tidy(declarator(d.type)))
                                          for d in t.type.decls]
            elif isinstance(t, c_ast.TypeDecl) and isinstance(t.type, c_ast.Enum):
                add_enum(t.type, node.name, node.coord)
            else:
                typedefs[node.name] = "typedef " + tidy(declarator(t, node.name)) + ";"
        elif isinstance(node, c_ast.Decl):
            t = node.type
            if isinstance(t, c_ast.FuncDecl):
                functions[node.name] = {
                    "signature": tidy(declarator(t, node.name)) + ";",
                    "returns": tidy(declarator(t.type)),
                    "params": [
                        {"name": p.name, "type": tidy(declarator(p.type))}
                        for p in (t.args.params if t.args else [])
                        if not isinstance(p, c_ast.EllipsisParam)
                        and not (p.name is None and declarator(p.type) == "void")
                    ],
                }
            elif isinstance(t, c_ast.Enum):
                add_enum(t, t.name, node.coord)
            elif isinstance(t, c_ast.Struct) and t.decls is not None:
                structs["struct " + t.name] = [(d.name, tidy(declarator(d.type)))
                                               for d in t.decls]
    return functions, structs, enums, typedefs, sorted(opaque)


def int_macros(inc):
    """Names of the object-like MS_* macros with a numeric body."""
    names = []
    for h in sorted(os.listdir(os.path.join(inc, "modesplit"))):
        if not h.endswith(".h"):
            continue
        with open(os.path.join(inc, "modesplit", h)) as f:
            for line in f:
                m = re.match(r"\s*#\s*define\s+(MS_\w+)\s+(.+?)\s*(/\*.*)?$", line)
                if m and not re.search(r'["{}]|__attribute__', m.group(2)):
                    names.append(m.group(1))
    return sorted(set(names))


def probe(args, inc, structs, enums, macros):
    """Compile and run a C program printing every size, offset and value."""
    lines = ["#include <stdio.h>", "#include <stddef.h>"]
    lines += ["#include <%s>" % h for h in HEADERS]
    lines += ["int main(void) {"]
    for s, fields in structs.items():
        lines.append('printf("S\\t%s\\t%%zu\\t%%zu\\n", sizeof(%s), _Alignof(%s));' % (s, s, s))
        for name, _ in fields:
            lines.append('printf("F\\t%s\\t%s\\t%%zu\\t%%zu\\n", offsetof(%s, %s), '
                         'sizeof(((%s *)0)->%s));' % (s, name, s, name, s, name))
    for _, names in enums:
        for n in names:
            lines.append('printf("E\\t%s\\t%%lld\\n", (long long)%s);' % (n, n))
    for n in macros:
        lines.append('printf("M\\t%s\\t%%lld\\n", (long long)(%s));' % (n, n))
    lines += ["return 0;", "}"]
    with tempfile.TemporaryDirectory() as tmp:
        c = os.path.join(tmp, "abi_probe.c")
        exe = os.path.join(tmp, "abi_probe")
        with open(c, "w") as f:
            f.write("\n".join(lines) + "\n")
        run([args.cc, "-std=c11", "-w", "-I" + inc, c, "-o", exe])
        out = run([exe])
    sizes, offsets, values = {}, {}, {}
    for row in out.splitlines():
        p = row.split("\t")
        if p[0] == "S":
            sizes[p[1]] = (int(p[2]), int(p[3]))
        elif p[0] == "F":
            offsets[(p[1], p[2])] = (int(p[3]), int(p[4]))
        else:
            values[p[1]] = int(p[2])
    return sizes, offsets, values


# The linker's section bounds, which GNU ld puts in the dynamic table of
# some builds (ThreadSanitizer's): not exports of the library.
LINKER_SYMBOLS = {"__bss_start", "_edata", "_end"}


def exported(lib):
    out = run(["nm", "-D", "--defined-only", lib])
    return {p[2] for p in (l.split() for l in out.splitlines())
            if len(p) == 3 and p[1] in "TDRBW" and p[2] not in LINKER_SYMBOLS}


def listing(args):
    inc = include_dir(args)
    functions, structs, enums, typedefs, opaque = collect(parse(args, inc), inc)
    macros = int_macros(inc)
    sizes, offsets, values = probe(args, inc, structs, enums, macros)
    syms = exported(args.lib)
    stray = sorted(s for s in syms if s not in functions)
    if stray:
        sys.exit("abi: %s exports symbols no public header declares: %s"
                 % (args.lib, ", ".join(stray)))
    for name, f in functions.items():
        f["exported"] = name in syms
    return {
        "library": "libmodesplit",
        "generated_by": "tools/abi/abi_listing.py (regenerate: make abi)",
        "functions": dict(sorted(functions.items())),
        "structs": {
            s: {
                "size": sizes[s][0],
                "align": sizes[s][1],
                "fields": [{"name": n, "type": t, "offset": offsets[(s, n)][0],
                            "size": offsets[(s, n)][1]} for n, t in fields],
            }
            for s, fields in sorted(structs.items())
        },
        "enums": {name: {n: values[n] for n in names} for name, names in enums},
        "typedefs": dict(sorted(typedefs.items())),
        "opaque": opaque,
        "macros": {n: values[n] for n in macros},
    }


def dump(obj):
    return json.dumps(obj, indent=1) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--lib", required=True, help="libmodesplit.so whose exports to list")
    ap.add_argument("--include", default=os.path.join(ROOT, "include"))
    ap.add_argument("--cc", default=os.environ.get("CC", "cc").split()[0])
    g = ap.add_mutually_exclusive_group(required=True)
    g.add_argument("--out", nargs="+", help="write the listing to these files")
    g.add_argument("--check", nargs="+", help="fail if these files differ from the listing")
    args = ap.parse_args()
    text = dump(listing(args))
    if args.out:
        for path in args.out:
            with open(path, "w") as f:
                f.write(text)
        print("abi: wrote %s" % ", ".join(args.out))
        return 0
    bad = 0
    for path in args.check:
        try:
            with open(path) as f:
                old = f.read()
        except OSError as e:
            print("abi: cannot read %s: %s" % (path, e), file=sys.stderr)
            bad = 1
            continue
        if old != text:
            sys.stderr.writelines(difflib.unified_diff(
                old.splitlines(True), text.splitlines(True), path, "headers + " + args.lib))
            print("abi: %s differs from the headers and %s (the diff above); if the change "
                  "is meant, run `make abi` and commit the listing" % (path, args.lib),
                  file=sys.stderr)
            bad = 1
    if not bad:
        data = json.loads(text)
        print("abi: %d functions, %d structs, %d enum values match %s"
              % (len(data["functions"]), len(data["structs"]),
                 sum(len(v) for v in data["enums"].values()), ", ".join(args.check)))
    return bad


if __name__ == "__main__":
    sys.exit(main())
