#!/usr/bin/env python3
"""Generate bindings/fortran/cvmesh_c_interfaces.inc from include/cvmesh.h.

The .inc holds, for the Fortran module `cvmesh` (cvmesh.f90 includes it):
  - every integer #define and every enum constant as a Fortran parameter;
  - every public value struct as a bind(C) derived type;
  - one bind(C, name="cvm_...") interface per CVM_API function.

Type mapping (STYLE.md section 12):
  int32_t, cvm_index -> integer(c_int32_t)   int64_t -> integer(c_int64_t)
  size_t -> integer(c_size_t)   int, enums -> integer(c_int)   double -> real(c_double)
  handle pointers (cvm_mesh *) -> type(c_ptr), value      handle ** -> type(c_ptr)
  const T * -> T, intent(in) :: x(*)     T * -> an array x(*), or a scalar
  intent(out) when the name is `out` or ends in `_out` (outputs come first)
  const char * -> character(kind=c_char) :: x(*)   (as a result: type(c_ptr))
  void * -> type(c_ptr), value   function-pointer typedefs -> type(c_funptr), value
A declaration outside these rules stops the script with a message: extend the
rules (or OVERRIDES) rather than editing the output.

Usage: gen_interfaces.py [--header H] [--output O] [--check]
  --check  compare with the existing output instead of writing it; exit 1 on
           a difference (run by bindings/fortran/check.sh, so drift fails `make check`).
"""

import argparse
import difflib
import re
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent.parent

SCALARS = {
    "int32_t": "integer(c_int32_t)",
    "int64_t": "integer(c_int64_t)",
    "size_t": "integer(c_size_t)",
    "int": "integer(c_int)",
    "double": "real(c_double)",
    "char": "character(kind=c_char)",
}

# (function, parameter) -> mapping kind, for parameters the naming rules get wrong.
OVERRIDES = {
    ("cvm_mesh_insert_points", "ids_out"): "array_out",  # one id per input point
}

LINE_MAX = 100


class HeaderError(Exception):
    pass


def strip_comments(text):
    text = re.sub(r"/\*.*?\*/", lambda m: "\n" * m.group(0).count("\n"), text, flags=re.S)
    return re.sub(r"//[^\n]*", "", text)


class Header:
    """What the generator needs from cvmesh.h."""

    def __init__(self, text):
        self.text = strip_comments(text)
        self.typedefs = {}   # alias -> base scalar type
        self.enums = []      # (enum name, [(constant, value)])
        self.opaque = set()  # handle structs
        self.structs = []    # (name, [(ctype, field)])
        self.funptrs = set()
        self.defines = []    # (name, value, fortran type)
        self.functions = []  # (ret, name, [(ctype, pname)])
        self._parse()

    def _parse(self):
        t = self.text
        for m in re.finditer(r"typedef\s+(\w+)\s+(\w+)\s*;", t):
            if m.group(1) in SCALARS:
                self.typedefs[m.group(2)] = m.group(1)
        for m in re.finditer(r"typedef\s+struct\s+(\w+)\s+(\w+)\s*;", t):
            self.opaque.add(m.group(2))
        for m in re.finditer(r"typedef\s+[\w\s\*]+?\(\s*\*\s*(\w+)\s*\)\s*\(", t):
            self.funptrs.add(m.group(1))
        for m in re.finditer(r"typedef\s+enum\s+\w*\s*\{(.*?)\}\s*(\w+)\s*;", t, re.S):
            consts, value = [], -1
            for item in m.group(1).split(","):
                item = item.strip()
                if not item:
                    continue
                name, _, expr = item.partition("=")
                value = self._eval(expr, {}) if expr.strip() else value + 1
                consts.append((name.strip(), value))
            self.enums.append((m.group(2), consts))
        for m in re.finditer(r"typedef\s+struct\s+(\w+)\s*\{(.*?)\}\s*(\w+)\s*;", t, re.S):
            fields = []
            for decl in m.group(2).split(";"):
                decl = decl.strip()
                if decl:
                    ctype, name = decl.rsplit(None, 1)
                    fields.append((ctype, name))
            self.structs.append((m.group(3), fields))
        known = {}
        folded = re.sub(r"\\\n", " ", t)  # join backslash-continued #defines
        for m in re.finditer(r"^[ \t]*#[ \t]*define[ \t]+(CVM_\w+)[ \t]+(.+?)[ \t]*$", folded, re.M):
            name, expr = m.group(1), m.group(2)
            try:
                value = self._eval(expr, known)
            except HeaderError:
                continue  # not a number (e.g. CVM_API)
            known[name] = value
            ftype = "integer(c_int32_t)" if "(cvm_index)" in expr else "integer(c_int)"
            self.defines.append((name, value, ftype))
        code = re.sub(r"^[ \t]*#.*$", "", folded, flags=re.M)  # declarations only
        for m in re.finditer(r"\bCVM_API\s+([^;{]*?)\b(\w+)\s*\(([^)]*)\)\s*;", code, re.S):
            ret = " ".join(m.group(1).split())
            params = []
            plist = " ".join(m.group(3).split())
            if plist not in ("", "void"):
                for p in plist.split(","):
                    p = p.strip().replace("*", " * ")
                    p = " ".join(p.split()).replace("* *", "**")
                    ctype, pname = p.rsplit(" ", 1)
                    params.append((ctype.replace(" *", "*"), pname))
            self.functions.append((ret.replace(" *", "*"), m.group(2), params))
        if not self.functions:
            raise HeaderError("no CVM_API function found")

    @staticmethod
    def _eval(expr, known):
        e = re.sub(r"\(\s*(?:cvm_index|int32_t|int64_t|int|size_t)\s*\)", "", expr)
        for name, value in known.items():
            e = re.sub(r"\b%s\b" % name, str(value), e)
        if not re.search(r"\d", e) or not re.fullmatch(r"[\d\s\+\-\*\(\)]+", e):
            raise HeaderError("cannot evaluate %r" % expr)
        return int(eval(e, {"__builtins__": {}}))  # digits and + - * ( ) only

    def enum_names(self):
        return {name for name, _ in self.enums}

    def struct_names(self):
        return {name for name, _ in self.structs}


def base_type(h, ctype):
    """Normalised (const?, base, pointer depth) of a C type string."""
    const = ctype.startswith("const ")
    t = ctype[6:] if const else ctype
    depth = t.count("*")
    base = t.replace("*", "").strip()
    base = h.typedefs.get(base, base)
    return const, base, depth


def fortran_param(h, func, ctype, name):
    """Declaration line(s) of one dummy argument."""
    const, base, depth = base_type(h, ctype)
    kind = OVERRIDES.get((func, name))
    enums, structs = h.enum_names(), h.struct_names()
    if depth == 0:
        if base in SCALARS and base != "char":
            return "%s, value :: %s" % (SCALARS[base], name)
        if base in enums:
            return "integer(c_int), value :: %s" % name
        if base in h.funptrs:
            return "type(c_funptr), value :: %s" % name
    elif depth == 1:
        if base in h.opaque or base == "void":
            return "type(c_ptr), value :: %s" % name
        if base == "char" and const:
            return "character(kind=c_char), intent(in) :: %s(*)" % name
        ftype = (SCALARS.get(base) if base != "char" else None) or \
            ("integer(c_int)" if base in enums else None) or \
            ("type(%s)" % base if base in structs else None)
        if ftype:
            if const:
                return "%s, intent(in) :: %s(*)" % (ftype, name)
            if kind == "array_out":
                return "%s, intent(out) :: %s(*)" % (ftype, name)
            if name == "out" or name.endswith("_out"):
                return "%s, intent(out) :: %s" % (ftype, name)
            return "%s, intent(inout) :: %s(*)" % (ftype, name)
    elif depth == 2:
        if base in h.opaque or base in SCALARS:
            return "type(c_ptr), intent(out) :: %s" % name
    raise HeaderError("%s: no Fortran mapping for parameter '%s %s'; extend "
                      "gen_interfaces.py" % (func, ctype, name))


def fortran_result(h, func, ret):
    """(is_function, declaration of the result) for a C return type."""
    const, base, depth = base_type(h, ret)
    if ret == "void":
        return False, None
    if depth == 0 and base in SCALARS and base != "char":
        return True, SCALARS[base]
    if depth == 0 and base in h.enum_names():
        return True, "integer(c_int)"
    if depth == 1 and (base == "char" or base in h.opaque or base == "void"):
        return True, "type(c_ptr)"
    raise HeaderError("%s: no Fortran mapping for return type '%s'" % (func, ret))


def wrap_call(head, names, indent):
    """`head(a, b, c)` folded with & continuations at LINE_MAX."""
    lines, line = [], indent + head + "("
    for i, n in enumerate(names):
        piece = n + (", " if i + 1 < len(names) else ")")
        if len(line) + len(piece) > LINE_MAX - 2:
            lines.append(line.rstrip() + " &")
            line = indent + "    "
        line += piece
    if not names:
        line += ")"
    lines.append(line)
    return lines


def generate(h, header_name):
    out = []
    w = out.append
    w("! cvmesh_c_interfaces.inc - bind(C) declarations of include/cvmesh.h for module cvmesh.")
    w("! GENERATED by bindings/fortran/gen_interfaces.py from %s: do not edit." % header_name)
    w("! Regenerate with: python3 bindings/fortran/gen_interfaces.py")
    w("")
    w("! ---- constants (#define) ----")
    w("! Fortran names are case-insensitive: a macro named like a function")
    w("! (CVM_VERSION_NUMBER, cvm_version_number) gets the suffix _H.")
    funcs = {name.lower() for _, name, _ in h.functions}
    for name, value, ftype in h.defines:
        if name.lower() in funcs:
            name += "_H"
        w("%s, parameter :: %s = %d" % (ftype, name, value))
    for ename, consts in h.enums:
        w("")
        w("! ---- enum %s ----" % ename)
        for name, value in consts:
            w("integer(c_int), parameter :: %s = %d" % (name, value))
    for sname, fields in h.structs:
        w("")
        w("! ---- struct %s ----" % sname)
        w("type, bind(C) :: %s" % sname)
        for ctype, fname in fields:
            const, base, depth = base_type(h, ctype)
            if depth or base not in SCALARS or base == "char":
                raise HeaderError("struct %s: no mapping for field '%s %s'" % (sname, ctype, fname))
            w("    %s :: %s" % (SCALARS[base], fname))
        w("end type %s" % sname)
    w("")
    w("interface")
    for ret, name, params in h.functions:
        is_func, rdecl = fortran_result(h, name, ret)
        kw = "function" if is_func else "subroutine"
        pnames = [p for _, p in params]
        w("")
        call = wrap_call("%s %s" % (kw, name), pnames, "    ")
        bind = ' bind(C, name="%s")' % name
        if len(call[-1] + bind) > LINE_MAX:
            call[-1] += " &"
            call.append("        " + bind.strip())
        else:
            call[-1] += bind
        out.extend(call)
        w("        import")
        w("        implicit none")
        for ctype, pname in params:
            w("        " + fortran_param(h, name, ctype, pname))
        if is_func:
            w("        %s :: %s" % (rdecl, name))
        w("    end %s %s" % (kw, name))
    w("")
    w("end interface")
    for line in out:
        if len(line) > 132:
            raise HeaderError("generated line longer than 132 characters: " + line)
    return "\n".join(out) + "\n"


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--header", default=str(ROOT / "include" / "cvmesh.h"))
    ap.add_argument("--output", default=str(HERE / "cvmesh_c_interfaces.inc"))
    ap.add_argument("--check", action="store_true")
    args = ap.parse_args(argv)
    try:
        text = generate(Header(Path(args.header).read_text()), "include/cvmesh.h")
    except HeaderError as e:
        print("gen_interfaces: %s" % e, file=sys.stderr)
        return 2
    out = Path(args.output)
    if args.check:
        old = out.read_text() if out.exists() else ""
        if old != text:
            sys.stdout.writelines(difflib.unified_diff(
                old.splitlines(True), text.splitlines(True), str(out), "regenerated"))
            print("gen_interfaces: %s is out of date with %s; run "
                  "python3 bindings/fortran/gen_interfaces.py and commit the result"
                  % (out, args.header), file=sys.stderr)
            return 1
        print("gen_interfaces: %s matches %s (%d functions)" % (out.name, Path(args.header).name,
                                                                 text.count(" bind(C, name=")))
        return 0
    out.write_text(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
