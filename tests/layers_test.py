#!/usr/bin/env python3
"""Every include stays within the layers CMake declares: a source of one library folder
("scene/scene.cpp") may include its own folder's headers and those of the libraries it links
(target_link_libraries, PUBLIC or PRIVATE), and through those the libraries they link PUBLIC, and
nothing else of the project. An include that runs up a layer ("geometry/" including "scene/") or
across to a library not linked fails here, naming the file, the line and what would have to be
linked. The public headers (include/phongvk, "phongvk/...") and the headers shaders and C++
share (shaders/) are open to every layer. Run by CTest as layers:

    python3 tests/layers_test.py [SOURCE_DIR]
"""

import os
import re
import sys

# Each library folder and its CMake target; the command (cli/) and the Python module (python/)
# link the shared library, whose public headers are include/phongvk.
FOLDERS = {
    "base": "phongvk_base", "geometry": "phongvk_geometry", "meshio": "phongvk_meshio", "scene": "phongvk_scene",
    "prepare": "phongvk_prepare", "image": "phongvk_image", "reference": "phongvk_reference",
    "vulkan": "phongvk_vulkan", "compute": "phongvk_compute", "graphics": "phongvk_graphics", "api": "phongvk_api",
    "tools": "phongvk_tools", "cli": "phongvk", "python": "_phongvk", "bench": "phongvk_bench",
}
OPEN = {"phongvk", "shaders"}
# Folders that build on include/phongvk alone, whatever they link: of the project's libraries they
# may include only the tools.
PUBLIC_ONLY = {"cli", "python"}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([A-Za-z0-9_]+)/[^"]+"', re.M)
LINK = re.compile(r"target_link_libraries\(\s*(\S+)\s+([^)]*)\)", re.S)


def links(root):
    """Each target's linked targets: {target: [(library, public)]}, from every CMakeLists.txt."""
    found = {}
    for folder in FOLDERS:
        path = os.path.join(root, folder, "CMakeLists.txt")
        if not os.path.exists(path):
            continue
        text = re.sub(r"#.*", "", open(path, encoding="utf-8").read())
        for target, args in LINK.findall(text):
            public = True
            for word in args.split():
                if word in ("PUBLIC", "INTERFACE"):
                    public = True
                elif word == "PRIVATE":
                    public = False
                else:
                    found.setdefault(target, []).append((word, public))
    return found


def reachable(target, graph):
    """The libraries `target` may include: what it links, then what those link PUBLIC."""
    seen, todo = set(), [name for name, _ in graph.get(target, [])]
    while todo:
        name = todo.pop()
        if name in seen:
            continue
        seen.add(name)
        todo += [inner for inner, public in graph.get(name, []) if public]
    return seen


def violations(root):
    graph = links(root)
    problems = []
    for folder, target in FOLDERS.items():
        reach = {f for f, t in FOLDERS.items() if t in reachable(target, graph)}
        if folder in PUBLIC_ONLY:
            reach &= {"tools"}
        allowed = {folder} | OPEN | reach
        directory = os.path.join(root, folder)
        for name in sorted(os.listdir(directory)) if os.path.isdir(directory) else []:
            if not name.endswith((".h", ".cpp")):
                continue
            text = open(os.path.join(directory, name), encoding="utf-8").read()
            for match in INCLUDE.finditer(text):
                used = match.group(1)
                if used in FOLDERS and used not in allowed:
                    line = text.count("\n", 0, match.start()) + 1
                    problems.append("%s/%s:%d includes %s/, but %s does not link %s" %
                                    (folder, name, line, used, target, FOLDERS[used]))
    return problems


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..")
    problems = violations(root)
    for problem in problems:
        print(problem)
    print("%d includes outside their layer" % len(problems))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
