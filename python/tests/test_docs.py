"""Every ```python snippet of docs/python.md, README.md, docs/friction_contact.md and
docs/file_formats.md runs as shown, and each `print(...)  # text` line prints what its comment
says (the part before "...", ": explanation" or " (explanation)"). The snippets run in a scratch
directory that sees the repository's tests/ (their data paths are written from the repository's
root). docs/maps.md's snippets read the output of `cpkit map` runs and are not run here."""
import contextlib
import io
import os
import re

import pytest

from conftest import SOURCE_DIR

DOCS = [os.path.join(SOURCE_DIR, *rel.split("/"))
        for rel in ("docs/python.md", "README.md", "docs/friction_contact.md",
                    "docs/file_formats.md")]


def snippets():
    found = []
    for doc in DOCS:
        with open(doc) as f:
            found += re.findall(r"```python\n(.*?)```", f.read(), flags=re.S)
    return found


def test_every_listed_doc_has_python_snippets():
    for doc in DOCS:  # none silently dropped (a renamed fence would run nothing)
        with open(doc) as f:
            assert re.search(r"```python\n", f.read()), doc


def expected_outputs(code):
    out = []
    for line in code.splitlines():
        m = re.match(r"\s*print\(.*\)\s+# (.*)$", line)
        if m:
            want = m.group(1)
            if "..." in want:
                want = want.split("...")[0]
            else:
                want = re.sub(r"^(\S+): .*$", r"\1", want)
                want = re.sub(r" \(.*\)$", "", want)  # "value (explanation)"
            out.append(want.rstrip())
    return out


@pytest.mark.parametrize("k", range(len(snippets())))
def test_snippet_runs_and_prints_what_it_says(k, tmp_path, monkeypatch):
    code = snippets()[k]
    monkeypatch.chdir(tmp_path)  # figures land in a scratch directory
    os.symlink(os.path.join(SOURCE_DIR, "tests"), tmp_path / "tests")
    buf = io.StringIO()
    with contextlib.redirect_stdout(buf):
        exec(compile(code, f"python snippet {k + 1}", "exec"), {})
    lines = buf.getvalue().splitlines()
    wants = expected_outputs(code)
    assert len(lines) == len(wants)
    for got, want in zip(lines, wants):
        assert got.startswith(want), (got, want)
