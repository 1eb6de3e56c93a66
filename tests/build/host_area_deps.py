#!/usr/bin/env python3
"""host_area_deps.py SIM_DIR [--core DIR ...] AREA:DEP,DEP ... — the sim/ areas include only what
they declare, and their names are not the core's.

Each AREA argument names an area (a folder of sim/) and the areas it declares in
sim/*/CMakeLists.txt (tread_host_area(... DEPS ...)). Fails, naming file and line, when a file of
an area includes a header of another area that its area does not declare; when the declared graph
has a cycle; or when a folder of sim/ with sources is not a declared area.

Each --core DIR is an include root of the core or the HAL (src/, hal/). An area whose folder has
the name of a folder there would share its include prefix ("mf/..." for both), and a host file
that opens a namespace tread::X which core files open would share its names: both fail.
"""
import pathlib
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s+"([a-z_0-9]+)/[^"]+"')
NAMESPACE = re.compile(r'^\s*namespace\s+tread::([a-z_0-9]+)')


def main() -> int:
    sim = pathlib.Path(sys.argv[1])
    declared = {}
    cores = []
    args = iter(sys.argv[2:])
    for arg in args:
        if arg == "--core":
            cores.append(pathlib.Path(next(args)))
            continue
        name, _, deps = arg.partition(":")
        declared[name] = {d for d in deps.split(",") if d}
    problems = []

    for folder in sorted(p for p in sim.iterdir() if p.is_dir()):
        if any(folder.glob("*.cpp")) and folder.name not in declared:
            problems.append(f"sim/{folder.name}: sources, but not a declared area")

    for area, deps in sorted(declared.items()):
        for dep in sorted(deps):
            if dep not in declared:
                problems.append(f"sim/{area}: declares '{dep}', which is not an area")
        for path in sorted((sim / area).glob("*.[ch]pp")):
            for number, line in enumerate(path.read_text().splitlines(), 1):
                m = INCLUDE.match(line)
                if not m:
                    continue
                other = m.group(1)
                header = line.split('"')[1]
                if other == area or other not in declared or not (sim / header).is_file():
                    continue  # its own area, or a core/HAL header (src/, hal/)
                if other not in deps:
                    problems.append(
                        f"sim/{area}/{path.name}:{number}: includes {header}, but {area} does not "
                        f"depend on {other} (declared: {', '.join(sorted(deps)) or 'none'})")

    # Host and core names apart: include prefixes (folder names) and namespaces.
    core_namespaces = {}
    for core in cores:
        for path in sorted(core.rglob("*.[ch]pp")):
            for line in path.read_text(errors="replace").splitlines():
                m = NAMESPACE.match(line)
                if m:
                    core_namespaces.setdefault(m.group(1), path.relative_to(core.parent))
    for area in sorted(declared):
        for core in cores:
            if (core / area).is_dir():
                problems.append(f"sim/{area}: has the name of {core.name}/{area}, so \"{area}/...\" "
                                f"includes of host and core look alike")
        for path in sorted((sim / area).glob("*.[ch]pp")):
            for number, line in enumerate(path.read_text().splitlines(), 1):
                m = NAMESPACE.match(line)
                if m and m.group(1) in core_namespaces:
                    problems.append(f"sim/{area}/{path.name}:{number}: opens namespace "
                                    f"tread::{m.group(1)}, the core's (as {core_namespaces[m.group(1)]})")

    # Cycles in the declared graph (depth-first search, grey/black colouring).
    state = {}

    def visit(node, trail):
        state[node] = "grey"
        for nxt in sorted(declared.get(node, ())):
            if state.get(nxt) == "grey":
                cycle = trail[trail.index(nxt):] + [nxt] if nxt in trail else [node, nxt]
                problems.append("cycle between areas: " + " -> ".join(cycle))
            elif nxt not in state:
                visit(nxt, trail + [nxt])
        state[node] = "black"

    for node in sorted(declared):
        if node not in state:
            visit(node, [node])

    for p in problems:
        print(p)
    print(f"{len(declared)} areas, {sum(len(d) for d in declared.values())} declared dependencies: "
          f"{'ok' if not problems else f'{len(problems)} problem(s)'}")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
