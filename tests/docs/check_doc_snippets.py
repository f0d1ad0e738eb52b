#!/usr/bin/env python3
"""Every XML snippet in the given Markdown files is judged by `mhd validate`.

    check_doc_snippets.py MHD REPO FILE.md...

A snippet is a fenced ```xml block. A whole scene (`<?xml` or `<scene`) is validated as it
stands, from a folder where its relative paths mean what they mean in scenes/ (scenes/'s
XML is copied there, assets/ linked). A fragment (<plugin>, <plugins>, <object>,
<material>, <rig>, ...) is first put into a scene that includes common/materials.xml, in
metres when its positions and sizes are all under 10, else in millimetres. Each failure
is printed as FILE:LINE (the snippet's first line) with validate's own words; the exit
status is the number of failing snippets (0: every snippet validates)."""

import os
import re
import shutil
import subprocess
import sys
import tempfile

FENCE = re.compile(r"^```xml\s*$")


def snippets(path):
    """(first line number, text) of each ```xml block."""
    found, block, start = [], None, 0
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            if block is None:
                if FENCE.match(line):
                    block, start = [], number + 1
            elif line.startswith("```"):
                found.append((start, "".join(block)))
                block = None
            else:
                block.append(line)
    return found


def unit_of(fragment):
    numbers = []
    for attr in re.findall(r'\b(?:position|size|radius|half_size|value)="([^"]*)"', fragment):
        for token in attr.split():
            try:
                numbers.append(abs(float(token)))
            except ValueError:
                pass
    return "m" if all(n < 10 for n in numbers) else "mm"


def as_scene(text):
    body = text.strip()
    if body.startswith("<?xml") or body.startswith("<scene"):
        return body
    if body.startswith("<plugin ") or body.startswith("<plugin>"):
        body = f"<plugins>\n{body}\n</plugins>"
    return (f'<?xml version="1.0" encoding="UTF-8"?>\n<scene version="1" name="doc_snippet" unit="{unit_of(body)}">\n'
            f'<include file="common/materials.xml"/>\n{body}\n</scene>\n')


def main(argv):
    if len(argv) < 4:
        print(__doc__, file=sys.stderr)
        return 2
    mhd, repo, files = argv[1], argv[2], argv[3:]
    failures = checked = 0
    with tempfile.TemporaryDirectory(prefix="mhd_doc_snippets_") as tmp:
        scenes = os.path.join(tmp, "scenes")
        shutil.copytree(os.path.join(repo, "scenes"), scenes)  # XML only, a few hundred kB
        os.symlink(os.path.join(os.path.abspath(repo), "assets"), os.path.join(tmp, "assets"))
        for doc in files:
            for line, text in snippets(doc):
                checked += 1
                scene = os.path.join(scenes, f"doc_snippet_{checked}.xml")
                with open(scene, "w", encoding="utf-8") as f:
                    f.write(as_scene(text))
                run = subprocess.run([mhd, "validate", "--no-meshes", scene], capture_output=True, text=True,
                                     timeout=60)
                if run.returncode != 0:
                    failures += 1
                    print(f"{os.path.relpath(doc, repo)}:{line}: error: this snippet does not validate:")
                    for said in run.stderr.strip().splitlines():
                        print(f"  {said.replace(scene, 'snippet')}")
    print(f"{checked} snippets, {failures} do not validate")
    return min(failures, 100)


if __name__ == "__main__":
    sys.exit(main(sys.argv))
