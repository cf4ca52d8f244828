#!/usr/bin/env python3
"""The include rules of src/ (docs/design.md, "Includes"), checked from the sources alone:

1. Every `#include "..."` names a file of src/.
2. Includes point one way, down the floors: core, grid, fd -> gbssn -> initial_data, horizon,
   diagnostics, mesh -> io -> evolution -> config -> study -> cli (main.cpp above all). A file
   may include its own floor or a lower one.
3. The parameter headers, which configurations include, reach neither the table of variables
   (core/registry.hpp, gbssn/state.hpp) nor the equations (gbssn/equations.hpp, gauge.hpp,
   horizon_shift.hpp, rhs_loop.hpp), directly or through other headers: a change to those
   recompiles only the files that evaluate them.
4. Every project header a file includes is used by it: some name the header declares at
   namespace scope (a type, enum, alias, function, constant or macro) appears in the file. An
   include copied along when a file was split, and no longer used, fails here. An include that
   is there for its definitions alone (a .cpp instantiating templates a header defines) says so
   with `// IWYU pragma: keep`, include-what-you-use's mark.

Usage: tests/includes.py [SRC_DIR]   (default: src/ beside this script's folder). Prints each
violation as `file: rule: detail` and exits 1 if there is any.
"""
import os
import re
import sys

FLOORS = {
    "core": 0, "grid": 0, "fd": 0,
    "gbssn": 1,
    "initial_data": 2, "horizon": 2, "diagnostics": 2, "mesh": 2,
    "io": 3,
    "evolution": 4,
    "config": 5,
    "study": 6,
    "cli": 7,
}
PARAMETER_HEADERS = [
    "core/wave.hpp",
    "gbssn/rhs_params.hpp",
    "gbssn/horizon_shift_params.hpp",
    "initial_data/initial_data_params.hpp",
    "horizon/horizon_finder_params.hpp",
    "mesh/stepper_options.hpp",
    "mesh/time_interpolation_kind.hpp",
    "evolution/evolution_config.hpp",
    "config/choices.hpp",
    "config/params.hpp",
]
HEAVY = ["core/registry.hpp", "gbssn/state.hpp", "gbssn/equations.hpp", "gbssn/gauge.hpp",
         "gbssn/horizon_shift.hpp", "gbssn/rhs_loop.hpp"]

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)
KEPT = re.compile(r'^\s*#\s*include\s+"([^"]+)"\s*// IWYU pragma: keep', re.M)
# names a header declares at namespace scope (indentation 0 or inside a namespace block, which
# this code base does not indent): types, enums, aliases, functions, constants, macros
DECL = [
    re.compile(r'^(?:template[ \t]*<[^>\n]*>[ \t\n]*)?(?:struct|class|union)[ \t]+'
               r'(?:\[\[[^\]]*\]\][ \t]*)?(\w+)', re.M),
    re.compile(r'^enum[ \t]+(?:class[ \t]+|struct[ \t]+)?(\w+)', re.M),
    re.compile(r'^using[ \t]+(\w+)[ \t]*=', re.M),
    re.compile(r'^#[ \t]*define[ \t]+(\w+)', re.M),
    # a function whose return type is on the line before (clang-format's wrap)
    re.compile(r'^([A-Za-z_]\w*)\(', re.M),
    # a function returning decltype(auto)
    re.compile(r'^decltype\(auto\)[ \t]+(\w+)\(', re.M),
    # a function or constant at namespace scope: a declaration starting in column 0
    re.compile(r'^(?:template[ \t]*<[^\n]*>\n)?(?:(?:inline|constexpr|static|extern|const)[ \t]+'
               r'|\[\[[^\]]*\]\][ \t]*)*[A-Za-z_][\w:<>,\*& \t]*?[ \t\*&](\w+)[ \t]*(?:\(|=|\{|;)',
               re.M),
]
# enumerators of enums declared in the header count as its names too
ENUM_BODY = re.compile(r'^enum\s+(?:class\s+)?\w+[^{;]*\{([^}]*)\}', re.M)
KEYWORDS = {"if", "for", "while", "switch", "return", "operator", "namespace", "const", "void",
            "int", "double", "bool", "auto", "else", "case", "default", "template", "public",
            "private", "protected", "static_assert", "delete", "new", "sizeof", "noexcept"}


def strip_comments(text):
    text = re.sub(r'/\*.*?\*/', ' ', text, flags=re.S)
    return re.sub(r'//[^\n]*', '', text)


def strip_strings(text):
    return re.sub(r'"(?:\\.|[^"\\])*"', '""', text)


def main():
    src = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "..", "src")
    src = os.path.normpath(src)
    files = {}
    for root, _, names in os.walk(src):
        for n in names:
            if n.endswith((".hpp", ".cpp")):
                path = os.path.join(root, n)
                files[os.path.relpath(path, src)] = open(path, encoding="utf-8").read()
    problems = []
    includes = {f: INCLUDE.findall(t) for f, t in files.items()}

    def floor(f):
        top = f.split("/")[0]
        return FLOORS.get(top, 99 if f == "main.cpp" else None)

    for f, incs in sorted(includes.items()):
        for inc in incs:
            if inc not in files:
                problems.append(f"{f}: rule 1: includes {inc}, which is not a file of src/")
                continue
            a, b = floor(f), floor(inc)
            if a is None or b is None:
                problems.append(f"{f}: rule 2: {f if a is None else inc} is on no floor "
                                "(add its folder to FLOORS and docs/design.md)")
            elif b > a:
                problems.append(f"{f}: rule 2: includes {inc}, a floor up ({b} > {a})")

    def reach(f, seen=None):
        seen = set() if seen is None else seen
        for inc in includes.get(f, []):
            if inc in files and inc not in seen:
                seen.add(inc)
                reach(inc, seen)
        return seen

    for h in PARAMETER_HEADERS:
        if h not in files:
            problems.append(f"{h}: rule 3: listed as a parameter header but missing")
            continue
        for heavy in HEAVY:
            if heavy in reach(h):
                problems.append(f"{h}: rule 3: reaches {heavy}")

    declared = {}
    for f, text in files.items():
        if not f.endswith(".hpp"):
            continue
        code = strip_strings(strip_comments(text))
        names = set()
        for d in DECL:
            names.update(d.findall(code))
        for body in ENUM_BODY.findall(code):
            names.update(re.findall(r'\b([A-Za-z_]\w*)\b\s*(?:=[^,]*)?(?:,|$)', body))
        namespaces = set(re.findall(r'\bnamespace[ \t]+([\w:]+)', code))
        names -= {part for ns in namespaces for part in ns.split("::")}
        declared[f] = {n for n in names if n not in KEYWORDS}
    for f, incs in sorted(includes.items()):
        own = os.path.splitext(f)[0]
        code = strip_strings(strip_comments(files[f]))
        code = INCLUDE.sub("", code)
        words = set(re.findall(r'\b\w+\b', code))
        kept = set(KEPT.findall(files[f]))
        for inc in incs:
            if inc not in declared or os.path.splitext(inc)[0] == own or inc in kept:
                continue  # a .cpp's own header is always included first
            if not declared[inc] & words:
                problems.append(f"{f}: rule 4: includes {inc} but uses none of its names")
    for p in problems:
        print(p)
    print(f"includes: {len(files)} files, {sum(map(len, includes.values()))} includes, "
          f"{len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
