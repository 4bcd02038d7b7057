#!/usr/bin/env python3
"""Turns the block descriptions (tb/blocks/<block>/<block>.json) into what is generated from them.

Usage: gen_block_descriptions.py OUT JSON...

For every description it writes, below OUT:
  blocks/<dir>/<stem>_ports.hpp  the X-macro TMU_PORTS_<block>(C, F) of tb/harness/ports.hpp
                                 (one C row per channel, one F row per field) and
                                 TMU_BLOCK_INFO_<block>, the registry's name, summary and aliases;
                                 for a file of shared groups, TMU_PORTS_<group>(C, F) per group
  rtl/<top>_binds.sv             for every top in "rtl_tops": tmu_stream_check bound to every
                                 channel of the top that has a ready (Sample, Write, Stream,
                                 Result, MemRequest), which Verilator reads after the top's row
A file is rewritten only when its text changes, so that a reconfigure rebuilds nothing that is
the same. Any error names the file and the key, exits 1 and writes nothing.

The format (docs/harness.md, "The block description"):
  {"block": "noise", "summary": "...", "aliases": ["perlin"], "about": "...",
   "rtl_tops": ["tmu_noise"],
   "channels": [
     {"channel": "in", "kind": "Sample", "fields": {"u": "SolidCoord", ...}},
     {"channel": "cfg", "kind": "Cfg", "use": "texram_cfg", "fields": {...}, "env": {...}},
     {"use": "texram_memory"}, ...]}
A field's value is its format (formats.def), or [format, count] for count elements in one port.
"env" fields belong to the Cfg channel but are not ports (what the environment holds). "use"
splices a group of a shared file ({"groups": {"name": {"about": ..., "channel": ..., "fields":
..., "env": ...} or {"about": ..., "channels": [...]}}}): a channel's group gives fields, before
the channel's own; a list's group gives channels.
"""

import json
import os
import sys

# A channel kind: the kind of its fields, and whether the channel has a ready (and which way it
# goes) for the stream checker.
CHANNEL_KINDS = {
    "Sample": ("In", "in"),
    "Write": ("In", "in"),
    "Stream": ("In", "in"),
    "CombIn": ("In", None),
    "Result": ("Out", "out"),
    "CombOut": ("Out", None),
    "MemRequest": ("Req", "out"),
    "MemRequestNoReady": ("Req", None),
    "MemResponse": ("Resp", None),
    "Cfg": ("Cfg", None),
    "Stat": ("Stat", None),
}
BLOCK_KEYS = {"block", "summary", "aliases", "about", "rtl_tops", "channels"}
CHANNEL_KEYS = {"channel", "kind", "use", "fields", "env"}
GROUP_KEYS = {"about", "channel", "fields", "env", "channels"}


class DescriptionError(Exception):
    pass


def fail(path, key, reason):
    raise DescriptionError(f"{path}: {key}: {reason}")


def fields_of(path, key, obj, kind):
    """[(kind, name, format, count)] of a "fields" or "env" object."""
    if not isinstance(obj, dict):
        fail(path, key, "must be an object of name: format")
    rows = []
    for name, value in obj.items():
        fmt, count = (value, 1) if isinstance(value, str) else (value, None)
        if isinstance(value, list) and len(value) == 2:
            fmt, count = value
        if not isinstance(fmt, str) or not isinstance(count, int) or count < 1:
            fail(path, f"{key}.{name}", "must be a format or [format, count >= 1]")
        rows.append((kind, name, fmt, count))
    return rows


class Descriptions:
    def __init__(self, paths):
        self.docs = {}
        for path in paths:
            try:
                with open(path, encoding="utf-8") as f:
                    self.docs[path] = json.load(f)
            except (OSError, json.JSONDecodeError) as e:
                raise DescriptionError(f"{path}: {e}") from e
            if not isinstance(self.docs[path], dict):
                fail(path, "(top level)", "must be an object")
        # Every group by name: (the file that defines it, its definition).
        self.groups = {}
        for path, doc in self.docs.items():
            for name, group in doc.get("groups", {}).items():
                if name in self.groups:
                    fail(path, f"groups.{name}", f"also defined in {self.groups[name][0]}")
                unknown = set(group) - GROUP_KEYS
                if unknown:
                    fail(path, f"groups.{name}", f"unknown keys {sorted(unknown)}")
                self.groups[name] = (path, group)

    def group(self, path, key, name, want):
        if name not in self.groups:
            fail(path, key, f"no group {name!r} (known: {sorted(self.groups)})")
        gpath, group = self.groups[name]
        if ("channels" in group) != (want == "channels"):
            fail(path, key, f"group {name!r} gives {'channels' if 'channels' in group else 'fields'}")
        return gpath, group

    def channel_rows(self, path, key, channel, uses):
        """The rows of one channel: ("C", kind, channel), then its fields' ("F", kind, channel,
        name, format, count) and ("use", group) where a group's fields stand."""
        unknown = set(channel) - CHANNEL_KEYS
        if unknown:
            fail(path, key, f"unknown keys {sorted(unknown)}")
        if set(channel) == {"use"}:  # a group of channels
            self.group(path, f"{key}.use", channel["use"], "channels")
            uses.add(channel["use"])
            return [("use", channel["use"])]
        ch, kind = channel.get("channel"), channel.get("kind")
        if not isinstance(ch, str) or not ch.isidentifier():
            fail(path, f"{key}.channel", "must be a name")
        if kind not in CHANNEL_KINDS:
            fail(path, f"{key}.kind", f"{kind!r} is not one of {', '.join(CHANNEL_KINDS)}")
        rows = [("C", kind, ch)]
        if "use" in channel:
            self.group(path, f"{key}.use", channel["use"], "fields")
            uses.add(channel["use"])
            rows.append(("use", channel["use"]))
        return rows + self.field_rows(path, key, channel, ch, CHANNEL_KINDS[kind][0])

    @staticmethod
    def field_rows(path, key, obj, ch, field_kind):
        rows = fields_of(path, f"{key}.fields", obj.get("fields", {}), field_kind)
        rows += fields_of(path, f"{key}.env", obj.get("env", {}), "Env")
        return [("F", kind, ch, name, fmt, count) for kind, name, fmt, count in rows]

    def rows(self, path, key, channels, uses):
        if not isinstance(channels, list) or not channels:
            fail(path, key, "must be a non-empty list of channels")
        out = []
        for i, channel in enumerate(channels):
            if not isinstance(channel, dict):
                fail(path, f"{key}[{i}]", "must be an object")
            out += self.channel_rows(path, f"{key}[{i}]", channel, uses)
        return out

    def group_rows(self, path, name, group, uses):
        if "channels" in group:
            return self.rows(path, f"groups.{name}.channels", group["channels"], uses)
        ch = group.get("channel")
        if not isinstance(ch, str):
            fail(path, f"groups.{name}.channel", "a group of fields names its channel")
        # Only the Cfg channel's fields are shared today: a group of fields is Cfg (and env).
        return self.field_rows(path, f"groups.{name}", group, ch, "Cfg")


def macro(name, rows):
    """#define name(C, F) with one row a line, the backslashes aligned."""
    lines = [f"#define {name}(C, F)"]
    for row in rows:
        if row[0] == "C":
            lines.append(f"  C({row[1]}, {row[2]})")
        elif row[0] == "F":
            lines.append(f"  F({row[1]}, {row[2]}, {row[3]}, {row[4]}, {row[5]})")
        else:
            lines.append(f"  TMU_PORTS_{row[1]}(C, F)")
    width = max(len(line) for line in lines) + 1
    return "\n".join(line.ljust(width) + "\\" for line in lines[:-1]) + "\n" + lines[-1] + "\n"


def comment(text):
    """text as // lines of at most 100 columns. No line starts with the word Verilator:
    Verilator reads `// verilator ...` as a directive (and stops on one it does not know), so
    such a word takes the word before it onto its line."""
    out, line = [], "//"
    for word in text.split():
        if len(line) + 1 + len(word) > 100:
            head, _, last = line.rpartition(" ")
            if word.lower().startswith("verilator") and head != "//":
                out.append(head)
                line = "// " + last
            else:
                out.append(line)
                line = "//"
        line += " " + word
    out.append(line)
    return "\n".join(out) + "\n"


def c_string(text):
    return json.dumps(text, ensure_ascii=False)


def header(descs, path, doc):
    text = comment(
        f"GENERATED by scripts/gen_block_descriptions.py from {path_in_tree(path)}: edit that file."
    )
    if "block" not in doc and "groups" not in doc:
        fail(path, "(top level)", 'neither a block ("block") nor shared groups ("groups")')
    body = ""
    uses = set()
    if "groups" in doc:
        for name, group in doc["groups"].items():
            if "about" in group:
                body += comment(group["about"])
            body += macro(f"TMU_PORTS_{name}", descs.group_rows(path, name, group, uses))
    if "block" in doc:
        unknown = set(doc) - BLOCK_KEYS
        if unknown:
            fail(path, "(top level)", f"unknown keys {sorted(unknown)}")
        block = doc["block"]
        stem = os.path.splitext(os.path.basename(path))[0]
        if block != stem:
            fail(path, "block", f"{block!r} is not the file's name {stem!r}")
        for key in ("summary", "about"):
            if not isinstance(doc.get(key), str) or not doc[key]:
                fail(path, key, "must be a non-empty string")
        aliases = doc.get("aliases", [])
        if not isinstance(aliases, list) or not all(isinstance(a, str) for a in aliases):
            fail(path, "aliases", "must be a list of names")
        body += comment(doc["about"])
        info = ", ".join([c_string(block), c_string(doc["summary"])])
        alias_list = ", ".join(c_string(a) for a in aliases)
        body += f"#define TMU_BLOCK_INFO_{block} {{{info}, {{{alias_list}}}}}\n"
        body += macro(f"TMU_PORTS_{block}", descs.rows(path, "channels", doc.get("channels"), uses))
    files = sorted({descs.groups[name][0] for name in uses} - {path})
    includes = "".join(f'#include "{include_name(f)}"\n' for f in files)
    return text + "#pragma once\n\n" + includes + ("\n" if includes else "") + body


def include_name(path):
    """blocks/<dir>/<stem>_ports.hpp of tb/blocks/<dir>/<stem>.json."""
    d = os.path.basename(os.path.dirname(path))
    stem = os.path.splitext(os.path.basename(path))[0]
    return f"blocks/{d}/{stem}_ports.hpp"


def flat_rows(descs, path, rows):
    """rows with every group spliced in: C and F rows only."""
    out = []
    for row in rows:
        if row[0] == "use":
            gpath, group = descs.groups[row[1]]
            out += flat_rows(descs, gpath, descs.group_rows(gpath, row[1], group, set()))
        else:
            out.append(row)
    return out


def binds(descs, path, doc, top):
    rows = flat_rows(descs, path, descs.rows(path, "channels", doc.get("channels"), set()))
    text = ""
    for i, row in enumerate(rows):
        if row[0] != "C" or CHANNEL_KINDS[row[1]][1] is None:
            continue
        ch, way = row[2], CHANNEL_KINDS[row[1]][1]
        suffix = "i" if way == "in" else "o"
        data = [f"{ch}_{r[3]}_{suffix}" for r in rows[i + 1 :] if r[0] == "F" and r[2] == ch]
        data = data[0] if len(data) == 1 else "{" + ", ".join(data) + "}"
        ready = f"{ch}_ready_o" if way == "in" else f"{ch}_ready_i"
        text += (
            f"bind {top} tmu_stream_check #(\n"
            f"  .W($bits({data}))\n"
            f") u_{ch}_check (\n"
            f"  .clk_i, .rst_ni, .valid_i({ch}_valid_{suffix}), .ready_i({ready}),\n"
            f"  .data_i({data})\n"
            ");\n"
        )
    if not text:
        return None  # a combinational top: no channel has a ready
    return comment(
        f"GENERATED by scripts/gen_block_descriptions.py from {path_in_tree(path)}: the "
        f"ready/valid rules (rtl/common/tmu_stream_check.sv) on every channel of {top} with a "
        "ready, in every instance. Verilator reads it after the top's row; synthesis and Icarus "
        "do not (rtl/manifest.txt's header)."
    ) + text


def path_in_tree(path):
    parts = os.path.normpath(path).split(os.sep)
    return "/".join(parts[parts.index("tb") :]) if "tb" in parts else path


def write_if_changed(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    try:
        with open(path, encoding="utf-8") as f:
            if f.read() == text:
                return
    except OSError:
        pass
    tmp = path + ".tmp"
    with open(tmp, "w", encoding="utf-8") as f:
        f.write(text)
    os.replace(tmp, path)


def main(argv):
    if len(argv) < 3 or argv[1] in ("-h", "--help"):
        print(__doc__)
        return 0 if len(argv) > 1 and argv[1] in ("-h", "--help") else 2
    out = argv[1]
    try:
        descs = Descriptions(argv[2:])
        files = {}  # every output's text, written only when all descriptions are good
        for path, doc in descs.docs.items():
            files[os.path.join(out, include_name(path))] = header(descs, path, doc)
            for top in doc.get("rtl_tops", []):
                text = binds(descs, path, doc, top)
                if text:
                    files[os.path.join(out, "rtl", f"{top}_binds.sv")] = text
    except DescriptionError as e:
        print(f"gen_block_descriptions: {e}", file=sys.stderr)
        return 1
    for path, text in files.items():
        write_if_changed(path, text)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
