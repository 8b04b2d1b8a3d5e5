#!/usr/bin/env python3
"""Every file the docs and the code's comments cite exists: a path in the README or docs/
("scenes/basic.json", `compute/gpu_renderer.h`), a path or a file name in a comment
("(compute/gpu_buffers.cpp writeControl)", "edges.h setupEdges"). A file renamed or removed without its
citations fails here, naming each citation. Run by CTest as doc_paths:

    python3 tests/doc_paths_test.py [SOURCE_DIR]

Placeholders in examples ("scenes/x.json", "NAME_fuzzer.cpp") and headers of other projects
("gtest.h", "tiny_gltf.h") are not files of this repository and are passed over.
"""

import os
import re
import subprocess
import sys

EXTENSIONS = r"(?:h|cpp|comp|glsl|json|py|sh|md|cmake|txt|ipynb|vert|frag|in|supp)"
# "folder/file.ext" anywhere, or `file.ext` in backticks.
PATH = re.compile(r"`([A-Za-z0-9_./-]+\." + EXTENSIONS + r")`|(?<![\w/.-])((?:[A-Za-z0-9_.-]+/)+[A-Za-z0-9_.-]+\."
                  + EXTENSIONS + r")(?![\w/])")
# A bare source file name in a comment: "edges.h", "gpu_buffers.cpp".
NAME = re.compile(r"(?<![\w/.-])([A-Za-z0-9_]+\.(?:h|cpp|comp|glsl))(?![\w.])")
EXTERNAL = {"gtest.h", "stb_image.h", "stb_image_write.h", "stb_easy_font.h", "tiny_gltf.h", "tiny_obj_loader.h",
            "volk.h", "volk.c", "vulkan.h", "libdeflate.h", "mpi.h", "embed.h", "pybind11.h", "numpy.h", "stl.h"}
PLACEHOLDERS = {"x", "a", "NAME", "N", "NAME_fuzzer"}
HASH_COMMENTS = (".py", ".sh", ".cmake")


def tracked_files(root):
    """The repository's files: in a checkout, git's list of tracked files and of new ones it does not
    ignore (a document not yet committed is checked and citable), those present on disk; else every
    file outside build folders."""
    git = subprocess.run(["git", "-C", root, "ls-files", "--cached", "--others", "--exclude-standard"],
                         capture_output=True, text=True)
    if git.returncode == 0 and git.stdout:
        listed = dict.fromkeys(git.stdout.splitlines())
        return [f for f in listed if os.path.isfile(os.path.join(root, f))]
    files = []
    for folder, subfolders, names in os.walk(root):
        subfolders[:] = [d for d in subfolders if not d.startswith(("build", ".", "out"))]
        files += [os.path.relpath(os.path.join(folder, n), root) for n in names]
    return files


def cited_text(root, path):
    """A document's text, or a source file's comments (# or //, not #include)."""
    with open(os.path.join(root, path), encoding="utf-8", errors="replace") as f:
        text = f.read()
    if path.endswith(".md"):
        return text
    hash_comments = path.endswith(HASH_COMMENTS) or os.path.basename(path) == "CMakeLists.txt"
    return "\n".join(re.findall(r"#(.*)" if hash_comments else r"//(.*)", text))


def is_placeholder(name):
    stem = os.path.basename(name).split(".")[0]
    return stem in PLACEHOLDERS or stem.startswith("_") or "/." in name


def missing_citations(root):
    files = tracked_files(root)
    tracked = set(files)
    names = {os.path.basename(f) for f in files}
    folders = {os.path.dirname(f) for f in files}
    sources = [f for f in files if f.endswith((".md", ".h", ".cpp", ".comp", ".glsl") + HASH_COMMENTS)
               or os.path.basename(f) == "CMakeLists.txt"]
    missing = []
    for source in sources:
        text = cited_text(root, source)
        for m in PATH.finditer(text):
            cited = m.group(1) or m.group(2)
            if cited.startswith(("build", "out/", "/", "http")) or is_placeholder(cited):
                continue
            candidates = [cited, "include/" + cited, "scenes/" + cited, os.path.normpath(os.path.join(os.path.dirname(source), cited))]
            if any(c in tracked or c in folders for c in candidates) or ("/" not in cited and cited in names):
                continue
            if cited.endswith(".spv.h"):  # made by the build from shaders/*.comp
                continue
            missing.append((source, cited))
        if source.endswith(".md"):
            continue
        for m in NAME.finditer(text):
            name = m.group(1)
            if name in names or name in EXTERNAL or is_placeholder(name) or name.endswith(".spv.h"):
                continue
            missing.append((source, name))
    return missing


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    missing = missing_citations(root)
    for source, cited in missing:
        print(f"{source}: cites '{cited}', which is not a file of the repository")
    print(f"{len(missing)} citations of files that do not exist")
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main())
