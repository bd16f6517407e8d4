"""Every `/usr/bin/python3 -c "..."` example of docs/python.md runs, and
prints what the page says it prints (the indented block after "prints")."""

import os
import re
import subprocess
import sys
import textwrap

import pytest

from conftest import RHEOMETRY, SOURCE

PAGE = (SOURCE / "docs" / "python.md").read_text()
EXAMPLE = re.compile(r'/usr/bin/python3 -c "(.*?)"\n(?:\nprints\n\n((?:    [^\n]*\n|\n)+?)\n(?=\S))?',
                     re.S)
EXAMPLES = EXAMPLE.findall(PAGE)


def test_the_page_has_examples():
    assert len(EXAMPLES) >= 4


@pytest.mark.parametrize("code, printed", EXAMPLES, ids=[f"example{k}" for k in range(len(EXAMPLES))])
def test_example(code, printed):
    if "../shared/data/rheometry" in code and not RHEOMETRY.exists():
        pytest.skip(f"{RHEOMETRY} absent: the shared rheometry data are not on this machine")
    done = subprocess.run([sys.executable, "-c", textwrap.dedent(code)], cwd=SOURCE,
                          capture_output=True, text=True, env=os.environ)
    assert done.returncode == 0, done.stderr
    if printed:
        expected = textwrap.dedent(printed).strip("\n")
        assert [line.rstrip() for line in done.stdout.strip("\n").splitlines()] == \
            [line.rstrip() for line in expected.splitlines()]
