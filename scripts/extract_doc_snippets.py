#!/usr/bin/env python3
"""Extracts every ```cpp block of the given Markdown files into OUT_DIR, one complete program per
block, named <file>_<k>.cpp (k counts the file's cpp blocks from 1; '/' and '.' become '_').
Prints the names (without .cpp), one per line. A file is rewritten only when its text changed,
so that unchanged snippets are not recompiled; stale snippet files are removed.
Used by tests/CMakeLists.txt (ctest docs.snippet.*): every snippet in the docs compiles as shown.

Usage: extract_doc_snippets.py ROOT OUT_DIR FILE.md...   (FILE paths relative to ROOT)
"""
import os
import re
import sys


def main():
    root, out_dir, files = sys.argv[1], sys.argv[2], sys.argv[3:]
    os.makedirs(out_dir, exist_ok=True)
    names = []
    for rel in files:
        with open(os.path.join(root, rel), encoding="utf-8") as f:
            text = f.read()
        blocks = re.findall(r"^```cpp\n(.*?)^```\s*$", text, flags=re.S | re.M)
        base = re.sub(r"[^A-Za-z0-9]", "_", rel[:-3] if rel.endswith(".md") else rel)
        for k, code in enumerate(blocks, 1):
            name = "%s_%d" % (base, k)
            path = os.path.join(out_dir, name + ".cpp")
            body = "// Extracted from %s (C++ block %d) by scripts/extract_doc_snippets.py.\n" \
                   "#line 1 \"%s:block%d\"\n%s" % (rel, k, rel, k, code)
            old = None
            if os.path.exists(path):
                with open(path, encoding="utf-8") as f:
                    old = f.read()
            if old != body:
                with open(path, "w", encoding="utf-8") as f:
                    f.write(body)
            names.append(name)
    for f in os.listdir(out_dir):
        if f.endswith(".cpp") and f[:-4] not in names:
            os.remove(os.path.join(out_dir, f))
    print("\n".join(names))


if __name__ == "__main__":
    main()
