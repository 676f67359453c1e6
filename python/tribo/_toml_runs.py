"""Configs as files, dicts or a file plus overrides, all run through the CLI's own readers.

The compiled *_from_toml functions take a path. To vary a key from a notebook (a parameter study)
the config is loaded with tomllib, the overrides are set by dotted key, relative file names that
exist beside the original are made absolute, and the result is written to a temporary TOML file —
so every key, default and error of the CLI applies unchanged.
"""

import contextlib
import copy
import json
import math
import os
import re
import tempfile
import tomllib

_BARE_KEY = re.compile(r"^[A-Za-z0-9_-]+$")


def _key(k):
    return k if _BARE_KEY.match(k) else json.dumps(k)


def _value(v):
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        if math.isnan(v):
            return "nan"
        if math.isinf(v):
            return "inf" if v > 0 else "-inf"
        return repr(v)  # shortest round-trip text: the same double back
    if isinstance(v, str):
        return json.dumps(v)  # JSON's escapes are valid in TOML basic strings
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(_value(x) for x in v) + "]"
    if hasattr(v, "tolist"):  # NumPy scalars and arrays
        return _value(v.tolist())
    raise TypeError(f"cannot write {type(v).__name__} to TOML")


def _is_table_array(v):
    return isinstance(v, (list, tuple)) and v and all(isinstance(x, dict) for x in v)


def dumps(doc, prefix=""):
    """TOML text of a dict of scalars, arrays, tables and arrays of tables."""
    lines = []
    for k, v in doc.items():
        if not isinstance(v, dict) and not _is_table_array(v):
            lines.append(f"{_key(k)} = {_value(v)}")
    for k, v in doc.items():
        name = prefix + _key(k)
        if isinstance(v, dict):
            lines.append(f"\n[{name}]")
            lines.append(dumps(v, name + "."))
        elif _is_table_array(v):
            for item in v:
                lines.append(f"\n[[{name}]]")
                lines.append(dumps(item, name + "."))
    return "\n".join(x for x in lines if x != "")


def _absolutise(doc, base_dir):
    """Strings naming a file beside the base config become absolute (the copy lives elsewhere)."""
    for k, v in doc.items():
        if isinstance(v, dict):
            _absolutise(v, base_dir)
        elif isinstance(v, list):
            for x in v:
                if isinstance(x, dict):
                    _absolutise(x, base_dir)
        elif isinstance(v, str) and v and not os.path.isabs(v):
            candidate = os.path.join(base_dir, v)
            if os.path.exists(candidate):
                doc[k] = os.path.abspath(candidate)


def _set(doc, dotted, value):
    *tables, last = dotted.split(".")
    t = doc
    for name in tables:
        t = t.setdefault(name, {})
        if not isinstance(t, dict):
            raise ValueError(f"override '{dotted}': '{name}' is not a table")
    old = t.get(last)
    # An integer key stays an integer when the new value is a whole number (grid = 64.0 → 64).
    if isinstance(old, int) and not isinstance(old, bool) and isinstance(value, float) and value.is_integer():
        value = int(value)
    t[last] = value


@contextlib.contextmanager
def config_file(config, overrides=None):
    """Yields (path, label): a TOML file holding `config` (a path or a dict) with `overrides`
    ({"rig.drive_speed_m_per_s": 0.01, ...}) applied; the path itself when there is nothing to
    apply. `label` names the config in error messages."""
    if isinstance(config, (str, os.PathLike)) and not overrides:
        yield os.fspath(config), os.fspath(config)
        return
    if isinstance(config, (str, os.PathLike)):
        path = os.fspath(config)
        try:
            with open(path, "rb") as f:
                doc = tomllib.load(f)
        except OSError as e:
            raise ValueError(f"{path}: cannot read: {e.strerror}") from None
        except tomllib.TOMLDecodeError as e:
            raise ValueError(f"{path}: {e}") from None
        _absolutise(doc, os.path.dirname(os.path.abspath(path)))
        label = f"{path} (with overrides)"
    elif isinstance(config, dict):
        doc = copy.deepcopy(config)
        _absolutise(doc, os.getcwd())
        label = "<config dict>"
    else:
        raise TypeError("config must be a path or a dict")
    for k, v in (overrides or {}).items():
        _set(doc, k, v)
    with tempfile.TemporaryDirectory(prefix="tribo-py-") as d:
        tmp = os.path.join(d, "config.toml")
        with open(tmp, "w") as f:
            f.write(dumps(doc) + "\n")
        try:
            yield tmp, label
        except ValueError as e:  # name the user's config, not the temporary copy
            raise ValueError(str(e).replace(tmp, label)) from None
