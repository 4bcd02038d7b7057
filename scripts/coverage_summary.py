#!/usr/bin/env python3
"""Per-module summary of Verilator coverage files (scripts/coverage.sh, docs/coverage.md).

usage: coverage_summary.py OUT.md BLOCK=MERGED.dat...

Reads each block's merged coverage data (verilator_coverage --write) and writes a markdown
table: per block and SystemVerilog module, the line, branch and toggle points covered of
the total. A point is covered when its count is not 0: a line or branch hit, a toggle point
(one bit of a signal) changed; scripts/coverage.sh has already set the toggles that changed
only once in a run to 0 (a rise and a fall make a toggle, and one change after reset may be
a flop's random initial value replaced by a constant). A point is counted once however many
instances, parameter variants or models (a block's configurations) it appears in, with their
counts summed. Next to OUT.md, OUT.uncovered.txt lists every point not covered, block by block,
module by module: file, line and Verilator's comment; toggles one line a signal, with the
bits that did not toggle.
"""
import collections
import os
import sys

KINDS = ("line", "branch", "toggle", "user")


def read_points(path):
    """Yields (keys, count) for every point of a Verilator coverage file."""
    with open(path, encoding="utf-8", errors="replace") as f:
        for text in f:
            if not text.startswith("C '"):
                continue
            end = text.rindex("'")
            fields = text[3:end].split("\x01")
            keys = {}
            for field in fields:
                if "\x02" in field:
                    k, v = field.split("\x02", 1)
                    keys[k] = v
            yield keys, int(text[end + 1:].strip())


def module_and_kind(keys):
    """('tmu_noise', 'toggle') from the point's page, e.g. v_toggle/tmu_noise."""
    page = keys.get("page", "")
    kind, _, module = page.partition("/")
    kind = kind[2:] if kind.startswith("v_") else kind
    # Parameterised copies (name__Pxx) are the same source module.
    module = module.split("__", 1)[0] if module else "?"
    return module, kind


def bit_ranges(bits):
    """'0-3,7' from [0, 1, 2, 3, 7]."""
    bits = sorted(bits)
    parts, start = [], None
    for i, b in enumerate(bits):
        if start is None:
            start = b
        if i + 1 == len(bits) or bits[i + 1] != b + 1:
            parts.append(str(start) if start == b else f"{start}-{b}")
            start = None
    return ",".join(parts)


def describe_missed(missed):
    """The lines of the uncovered listing of one module: line and branch points one a line,
    toggles one a signal with the bits never toggled."""
    text = []
    toggles = collections.defaultdict(list)  # (file, line, signal) -> bits
    for file, line, kind, comment in sorted(missed):
        if kind != "toggle":
            text.append(f"  {file}:{line}: {kind}: {comment}")
            continue
        signal, bit = comment, None
        if comment.endswith("]") and "[" in comment:
            head, _, tail = comment.rpartition("[")
            if tail[:-1].isdigit():
                signal, bit = head, int(tail[:-1])
        toggles[(file, line, signal)].append(bit)
    for (file, line, signal), bits in sorted(toggles.items()):
        numbered = [b for b in bits if b is not None]
        where = f"[{bit_ranges(numbered)}]" if numbered else ""
        text.append(f"  {file}:{line}: toggle: {signal}{where}")
    return text


def fraction(covered, total):
    if total == 0:
        return "-"
    return f"{covered}/{total} ({100.0 * covered / total:.1f} %)"


def main(argv):
    if len(argv) < 3 or argv[1] in ("-h", "--help"):
        print(__doc__.strip())
        return 0 if len(argv) > 1 else 2
    out_md = argv[1]
    rows = []
    uncovered_text = []
    totals = collections.Counter()
    for arg in argv[2:]:
        block, _, path = arg.partition("=")
        # One point per source point: the runs of different models (a block's configurations,
        # its parameter variants) name the same point with other hierarchies.
        points = collections.Counter()
        for keys, count in read_points(path):
            module, kind = module_and_kind(keys)
            points[(module, kind, os.path.relpath(keys.get("f", "?")),
                    int(keys.get("l", "0") or 0), keys.get("n", ""), keys.get("o", ""))] += count
        per_module = collections.defaultdict(collections.Counter)
        missed = collections.defaultdict(list)
        for (module, kind, file, line, _, comment), count in points.items():
            per_module[module][kind + "_total"] += 1
            if count > 0:
                per_module[module][kind + "_covered"] += 1
            else:
                missed[module].append((file, line, kind, comment))
        for module in sorted(per_module):
            c = per_module[module]
            cov = sum(c[k + "_covered"] for k in KINDS)
            tot = sum(c[k + "_total"] for k in KINDS)
            rows.append((block, module, c, cov, tot))
            for k in KINDS:
                totals[k + "_covered"] += c[k + "_covered"]
                totals[k + "_total"] += c[k + "_total"]
            if missed[module]:
                uncovered_text.append(f"== {block} / {module}: {tot - cov} of {tot} points")
                uncovered_text.extend(describe_missed(missed[module]))
    has_user = totals["user_total"] > 0
    head = "| block | module | lines | branches | toggles |" + (" user |" if has_user else "")
    head += " all points |"
    lines = [head, "|" + "---|" * (head.count("|") - 1)]
    for block, module, c, cov, tot in rows:
        cells = [block, f"`{module}`"] + [
            fraction(c[k + "_covered"], c[k + "_total"]) for k in KINDS
            if k != "user" or has_user
        ] + [fraction(cov, tot)]
        lines.append("| " + " | ".join(cells) + " |")
    with open(out_md, "w", encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n")
    base = out_md[:-3] if out_md.endswith(".md") else out_md
    with open(base + ".uncovered.txt", "w", encoding="utf-8") as f:
        f.write("\n".join(uncovered_text) + "\n")
    print("\n".join(lines))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
