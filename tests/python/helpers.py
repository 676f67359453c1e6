"""Shared by the binding tests: where the built `tribo` and the examples are, and a CLI runner."""

import json
import os
import subprocess
import tempfile

SOURCE_DIR = os.environ.get("TRIBO_SOURCE_DIR", os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..")))
EXAMPLES = os.path.join(SOURCE_DIR, "examples")
TRIBO_EXE = os.environ.get("TRIBO_EXE", "")


def example(name):
    return os.path.join(EXAMPLES, name)


def example_text(name, replacements=()):
    """The text of examples/NAME with (old, new) replacements, each of which must apply once — so a
    changed example fails loudly instead of testing something else."""
    with open(example(name)) as f:
        text = f.read()
    for old, new in replacements:
        if text.count(old) != 1:
            raise AssertionError(f"{name}: expected '{old}' once, found {text.count(old)} times")
        text = text.replace(old, new)
    return text


def write_config(directory, name, text):
    path = os.path.join(directory, name)
    with open(path, "w") as f:
        f.write(text)
    return path


def run_cli(*args):
    """Runs the built `tribo` with args; returns the CompletedProcess (stdout, stderr as text)."""
    if not TRIBO_EXE or not os.path.exists(TRIBO_EXE):
        raise AssertionError("TRIBO_EXE does not name the built tribo (run through ctest)")
    return subprocess.run([TRIBO_EXE, *args], capture_output=True, text=True, timeout=600)


def run_cli_json(args, out_dir, json_name):
    p = run_cli(*args, "--out", out_dir)
    if p.returncode != 0:
        raise AssertionError(f"tribo {' '.join(args)} failed ({p.returncode}): {p.stderr}")
    with open(os.path.join(out_dir, json_name)) as f:
        return json.load(f)


def temp_dir(test_case):
    d = tempfile.TemporaryDirectory(prefix="tribo-pytest-")
    test_case.addCleanup(d.cleanup)
    return d.name
