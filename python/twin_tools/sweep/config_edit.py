"""Setting one existing key of a YAML config file in a run's copy of the config folder
(twin_tools.sweep.cli, the `config:` part of a sweep spec).

A key is a path of mapping keys joined by '/', e.g. `pack/cells_in_parallel` in battery.yaml; a
list element is addressed by its index (`driveline/gear_ratios/0`). A key that the file does not
have is an error (never added silently); so is a value of another type than the file's (a number
for a number, true/false for a boolean, a string for a string, a list for a list).

The copy keeps the file as it is (comments, units, layout) except the one value: the line that
holds the key is rewritten; the result is parsed again and compared with the expected content.
A value that does not sit on the key's line (a block list) is written by dumping the whole file
(comments lost in that copy only).
"""
import copy
import re

import yaml


class KeyPathError(ValueError):
    pass


def split_path(key):
    parts = [p for p in key.split("/")]
    if not key or any(p == "" for p in parts):
        raise KeyPathError("'%s' is not a key path (keys joined by '/', e.g. pack/cells_in_parallel)" % key)
    return parts


def lookup(data, parts):
    """The value at `parts`; KeyPathError naming the first missing part and what exists there."""
    node = data
    for i, p in enumerate(parts):
        where = "/".join(parts[:i]) or "the top level"
        if isinstance(node, dict):
            if p not in node:
                raise KeyPathError("no key '%s' under %s (keys there: %s)" % (
                    p, where, ", ".join(str(k) for k in node)))
            node = node[p]
        elif isinstance(node, list):
            if not re.fullmatch(r"\d+", p) or int(p) >= len(node):
                raise KeyPathError("'%s' under %s: a list of %d elements (index 0..%d)" % (
                    p, where, len(node), len(node) - 1))
            node = node[int(p)]
        else:
            raise KeyPathError("%s is a value (%r), it has no key '%s'" % (where, node, p))
    return node


def _kind(v):
    if isinstance(v, bool):
        return "boolean"
    if isinstance(v, (int, float)):
        return "number"
    if isinstance(v, str):
        return "string"
    if isinstance(v, list):
        return "list"
    if isinstance(v, dict):
        return "mapping"
    return "null" if v is None else type(v).__name__


_NUMBER = re.compile(r"[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?")


def check_type(old, new):
    """Error text when `new` may not replace `old`, else None. A string that reads as a number
    (YAML 1.1 takes `42.7e6` for a string, yaml-cpp for a number) counts as a number."""
    ko, kn = _kind(old), _kind(new)
    if ko == "string" and _NUMBER.fullmatch(old.strip()):
        ko = "number"
    if ko == "mapping":
        return "it is a group of keys, not a value (set one of its keys: %s)" % ", ".join(map(str, old))
    if ko != kn:
        return "the file has a %s (%r), the sweep gives a %s (%r)" % (ko, old, kn, new)
    if ko == "number" and isinstance(old, int) and not isinstance(new, int):
        if float(new) != int(new):
            return "the file has an integer (%r), the sweep gives %r" % (old, new)
    return None


def same_number_type(old, new):
    """`new` written as the file writes `old`: 20000 -> 20000.0 for a real-valued key (a ROS
    parameter keeps the YAML type), 7.0 -> 7 for an integer key."""
    if isinstance(new, bool) or not isinstance(new, (int, float)):
        return new
    if isinstance(old, bool):
        return new
    if isinstance(old, int):
        return int(new)
    return float(new)


def format_value(v):
    """A YAML flow representation of one value (no document end marker)."""
    s = yaml.safe_dump(v, default_flow_style=True, width=1 << 30).strip()
    if s.endswith("\n..."):
        s = s[: -len("\n...")]
    if s.endswith("..."):
        s = s[: -3].strip()
    return s


_KEY_LINE = re.compile(r"^(?P<indent> *)(?P<key>[^\s#:'\"\-][^:#]*?|'[^']*'|\"[^\"]*\")\s*:(?P<rest>.*)$")


def _split_comment(rest):
    """(value text, trailing ' # comment' incl. its leading blanks) of a line's remainder."""
    quote = None
    for i, ch in enumerate(rest):
        if quote:
            if ch == quote:
                quote = None
        elif ch in "'\"":
            quote = ch
        elif ch == "#" and (i == 0 or rest[i - 1] in " \t"):
            j = i
            while j > 0 and rest[j - 1] in " \t":
                j -= 1
            return rest[:j], rest[j:]
    return rest.rstrip(), ""


def _edit_line(text, parts, expected):
    """The text with the value of `parts` rewritten on its own line (or the one-line flow list or
    mapping that holds it), or None when the value is not on one line of a block mapping (then
    the caller dumps the whole file). `expected`: the whole document with the new value."""
    lines = text.split("\n")
    stack = []  # (indent, key) of the open block mappings
    for n, line in enumerate(lines):
        stripped = line.strip()
        if not stripped or stripped.startswith("#") or stripped in ("---", "..."):
            continue
        if stripped.startswith("- "):
            continue  # block list items: never a key path of ours unless handled by the dump
        m = _KEY_LINE.match(line)
        if not m:
            continue
        indent = len(m.group("indent"))
        key = m.group("key").strip().strip("'\"")
        while stack and stack[-1][0] >= indent:
            stack.pop()
        path = [k for _, k in stack] + [key]
        value, comment = _split_comment(m.group("rest"))
        if value.strip():
            if path == parts[: len(path)]:
                old = value.strip()
                new = format_value(lookup(expected, path))
                lead = value[: len(value) - len(value.lstrip())] or " "
                pad = max(1, len(old) - len(new) + (len(comment) - len(comment.lstrip()))) if comment else 0
                tail = (" " * pad + comment.lstrip()) if comment else ""
                lines[n] = m.group("indent") + m.group("key") + ":" + lead + new + tail
                return "\n".join(lines)
        else:
            stack.append((indent, key))
    return None


def set_key(text, key, value):
    """(new text, old value, value as written) of a YAML document with `key` (a '/' path) set to `value`.
    KeyPathError (no such key, or a value of another type) before anything is written."""
    data = yaml.safe_load(text)
    parts = split_path(key)
    old = lookup(data, parts)
    why = check_type(old, value)
    if why:
        raise KeyPathError(why)
    value = same_number_type(old, value)
    expected = copy.deepcopy(data)
    parent = lookup(expected, parts[:-1]) if len(parts) > 1 else expected
    parent[int(parts[-1]) if isinstance(parent, list) else parts[-1]] = copy.deepcopy(value)
    new = _edit_line(text, parts, expected)
    if new is None or yaml.safe_load(new) != expected:
        new = yaml.safe_dump(expected, default_flow_style=False, sort_keys=False, width=1 << 30)
        if yaml.safe_load(new) != expected:  # cannot happen with safe_dump; checked all the same
            raise KeyPathError("could not be written back")
    return new, old, value
