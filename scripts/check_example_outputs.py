#!/usr/bin/env python3
"""The example outputs quoted in docs/PYTHON.md are what the examples print (issue 46).

docs/PYTHON.md quotes each example's output in the first fenced block after its heading
(**`NAME.py`**). Every quoted line must be a line the example printed in this run
(OUTPUTS/NAME.out, written by scripts/test's Python stage), in the same order; two kinds of
quoted line are not compared: "..." (lines left out of the quote) and a line with a wall time
("N s for ..." or "(N ms per run)"), which varies from machine to machine.

  scripts/check_example_outputs.py --doc docs/PYTHON.md --outputs build/examples [--self-test]
"""
import argparse
import pathlib
import re
import sys

HEADING_RE = re.compile(r"^\*\*`(?:examples/python/)?([A-Za-z0-9_]+)\.py`\*\*")
TIMING_RE = re.compile(r"\d+(\.\d+)? s for |\d+(\.\d+)? ms per run")


def quoted_blocks(doc_text):
    """{example name: [quoted lines]} from the doc."""
    blocks, name, inside, lines = {}, None, False, []
    for line in doc_text.splitlines():
        m = HEADING_RE.match(line)
        if m and not inside:
            name = m.group(1)
            continue
        if line.startswith("```"):
            if inside:
                if name is not None and name not in blocks:
                    blocks[name] = lines
                inside, lines, name = False, [], None
            elif name is not None:
                inside = True
            continue
        if inside:
            lines.append(line)
    return blocks


def compared(line):
    return line.strip() != "..." and not TIMING_RE.search(line)


def findings(blocks, outputs):
    out = []
    for name, quoted in sorted(blocks.items()):
        if name not in outputs:
            out.append(f"{name}.py: no output ({name}.out) to compare the quote with")
            continue
        printed = outputs[name].splitlines()
        at = 0
        for line in filter(compared, quoted):
            try:
                at = printed.index(line, at) + 1
            except ValueError:
                out.append(f"docs/PYTHON.md quotes {name}.py printing {line!r}; it did not print "
                           "that line (in that order)")
    return out


def self_test(blocks, outputs):
    ok = not findings(blocks, outputs)
    if not ok:
        print("self-test: the docs and outputs themselves have findings")
    name = sorted(blocks)[0]
    first = next(l for l in blocks[name] if compared(l))
    altered = dict(blocks, **{name: [first.replace(first[:1], "#", 1)] + blocks[name]})
    got = findings(altered, outputs)
    if len(got) != 1 or name not in got[0]:
        print(f"self-test: an altered quoted line: expected one finding for {name}.py, got {got}")
        ok = False
    got = findings(blocks, {k: v for k, v in outputs.items() if k != name})
    if len(got) != 1 or "no output" not in got[0]:
        print(f"self-test: a missing output: expected one finding, got {got}")
        ok = False
    return ok


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--doc", required=True, type=pathlib.Path)
    ap.add_argument("--outputs", required=True, type=pathlib.Path)
    ap.add_argument("--self-test", action="store_true")
    args = ap.parse_args(argv)
    blocks = quoted_blocks(args.doc.read_text(encoding="utf-8"))
    if not blocks:
        print(f"check_example_outputs: no quoted example output in {args.doc}")
        return 1
    outputs = {p.stem: p.read_text(encoding="utf-8") for p in args.outputs.glob("*.out")}
    if args.self_test:
        ok = self_test(blocks, outputs)
        print("check_example_outputs self-test:", "ok" if ok else "FAILED")
        return 0 if ok else 1
    found = findings(blocks, outputs)
    for f in found:
        print(f)
    print(f"check_example_outputs: {len(found)} findings in {len(blocks)} quoted outputs")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
