#!/usr/bin/env python3
"""Check that every source file's tests can be found (issue 41 item 5).

Run by ctest (test/docs/CMakeLists.txt):
  docs.EverySourceFileHasItsTests         the check
  docs.TestMapCheckReportsEveryProblem    --self-test: altered tables must be reported

A file src/M/x.cpp is tested in a test file of the same stem, test/**/x_test.cpp or
test/**/x_test.py; every other src/**/*.cpp must have exactly one row in the table of
docs/ARCHITECTURE.md's section "## Where each file's tests are" (columns `file`,
`tested in`, `how`). Checked:
  - every src/**/*.cpp has a same-stem test file or exactly one row;
  - every row's file exists under src/ and has no same-stem test (else the row is redundant);
  - every path in a row's `tested in` column exists in the repository.
Exit status 0 with "test map: N files, M with a same-name test, K in docs/ARCHITECTURE.md",
1 with every problem listed otherwise.
"""
import argparse
import os
import re
import sys

SECTION = "## Where each file's tests are"
DOC = os.path.join("docs", "ARCHITECTURE.md")
PATH_RE = re.compile(r"`([^`]+)`")


def source_files(root):
    """Repository-relative paths of every src/**/*.cpp, sorted."""
    out = []
    for d, _, names in os.walk(os.path.join(root, "src")):
        for n in names:
            if n.endswith(".cpp"):
                out.append(os.path.relpath(os.path.join(d, n), root).replace(os.sep, "/"))
    return sorted(out)


def test_stems(root):
    """Stems x of every test/**/x_test.cpp and test/**/x_test.py."""
    stems = set()
    for _, _, names in os.walk(os.path.join(root, "test")):
        for n in names:
            for suffix in ("_test.cpp", "_test.py"):
                if n.endswith(suffix):
                    stems.add(n[: -len(suffix)])
    return stems


def stem_of(path):
    return os.path.splitext(os.path.basename(path))[0]


def split_row(line):
    """Cells of a Markdown table row ('|' inside `code` does not split)."""
    body = line.strip()
    if body.startswith("|"):
        body = body[1:]
    if body.endswith("|"):
        body = body[:-1]
    cells, cur, in_code = [], [], False
    for c in body:
        if c == "`":
            in_code = not in_code
        if c == "|" and not in_code:
            cells.append("".join(cur).strip())
            cur = []
            continue
        cur.append(c)
    cells.append("".join(cur).strip())
    return cells


def read_table(doc_text):
    """Rows of the section's table as (line number, file, [tested-in paths], how).
    Raises ValueError when the section or its table header is missing."""
    lines = doc_text.splitlines()
    try:
        start = next(i for i, l in enumerate(lines) if l.strip() == SECTION)
    except StopIteration:
        raise ValueError(f"{DOC}: no section '{SECTION}'") from None
    rows, header = [], None
    for i in range(start + 1, len(lines)):
        line = lines[i]
        if line.startswith("## "):
            break
        if not line.strip().startswith("|"):
            if header is not None and rows:
                break
            continue
        cells = split_row(line)
        if header is None:
            header = [c.lower() for c in cells]
            if header[:3] != ["file", "tested in", "how"]:
                raise ValueError(f"{DOC}:{i + 1}: table columns must be file | tested in | how")
            continue
        if all(set(c) <= set("-: ") for c in cells):
            continue
        cells += [""] * (3 - len(cells))
        files = PATH_RE.findall(cells[0])
        tested_in = ["none"] if cells[1].strip("` ") == "none" else PATH_RE.findall(cells[1])
        rows.append((i + 1, files[0] if len(files) == 1 else cells[0], tested_in, cells[2]))
    if header is None:
        raise ValueError(f"{DOC}: section '{SECTION}' has no table")
    return rows


def check(root, doc_text, sources=None, stems=None, exists=None):
    """Returns (problems, counts): problems a list of strings, counts (N, M, K)."""
    sources = source_files(root) if sources is None else sources
    stems = test_stems(root) if stems is None else stems
    if exists is None:
        def exists(p):
            return os.path.exists(os.path.join(root, p))
    problems = []
    try:
        rows = read_table(doc_text)
    except ValueError as e:
        return [str(e)], (len(sources), 0, 0)
    by_file = {}
    for line, f, tested_in, how in rows:
        by_file.setdefault(f, []).append(line)
        where = f"{DOC}:{line}"
        if f not in sources:
            problems.append(f"{where}: row for '{f}', which is not a src/**/*.cpp file")
        elif stem_of(f) in stems:
            problems.append(f"{where}: row for '{f}' is redundant: it has a same-name test "
                            f"({stem_of(f)}_test.cpp or .py)")
        if not tested_in:
            problems.append(f"{where}: row for '{f}' names no test file (write `none` if none)")
        for p in tested_in:
            if p != "none" and not exists(p):
                problems.append(f"{where}: row for '{f}': '{p}' does not exist")
        if not how.strip():
            problems.append(f"{where}: row for '{f}' says nothing under 'how'")
    with_test = [s for s in sources if stem_of(s) in stems]
    for s in sources:
        n = len(by_file.get(s, []))
        if stem_of(s) in stems:
            continue
        if n == 0:
            problems.append(f"{s}: no {stem_of(s)}_test.cpp or .py under test/ and no row in "
                            f"{DOC} '{SECTION}'")
        elif n > 1:
            lines = ", ".join(str(l) for l in by_file[s])
            problems.append(f"{s}: {n} rows in {DOC} (lines {lines}); one expected")
    in_doc = sum(1 for s in sources if stem_of(s) not in stems and s in by_file)
    return problems, (len(sources), len(with_test), in_doc)


def table_lines(doc_text):
    """Indexes of the section's table data rows in doc_text.splitlines()."""
    lines = doc_text.splitlines()
    start = next(i for i, l in enumerate(lines) if l.strip() == SECTION)
    out = []
    for i in range(start + 1, len(lines)):
        if lines[i].startswith("## "):
            break
        if lines[i].strip().startswith("| `src/"):
            out.append(i)
    return out


def self_test(root, doc_text):
    """Alters the table in memory; each alteration must be reported, the original must pass."""
    sources, stems = source_files(root), test_stems(root)
    failures = []

    def run(text):
        return check(root, text, sources, stems)[0]

    base = run(doc_text)
    if base:
        failures.append("the unaltered table must pass; it reports:\n  " + "\n  ".join(base))
    lines = doc_text.splitlines()
    rows = table_lines(doc_text)
    if not rows:
        print("self-test: the table has no rows", file=sys.stderr)
        return 1
    tested = next((s for s in sources if stem_of(s) in stems), None)
    dropped_file = PATH_RE.findall(lines[rows[0]])[0]
    cases = []
    # 1. A row dropped: its file has neither a same-name test nor a row.
    cases.append(("a row dropped", "\n".join(lines[: rows[0]] + lines[rows[0] + 1:]),
                  f"{dropped_file}: no "))
    # 2. A row for a file that has a same-name test: redundant.
    if tested is not None:
        extra = f"| `{tested}` | `test/docs/CMakeLists.txt` | nothing |"
        cases.append(("a row for a file with a test",
                      "\n".join(lines[: rows[-1] + 1] + [extra] + lines[rows[-1] + 1:]),
                      f"row for '{tested}' is redundant"))
    # 3. A tested-in path that does not exist.
    missing = "test/no_such_dir/no_such_test.cpp"
    altered = list(lines)
    altered[rows[0]] = altered[rows[0]].replace("| `test/", f"| `{missing}`, `test/", 1)
    cases.append(("a missing tested-in path", "\n".join(altered), f"'{missing}' does not exist"))
    # 4. The same file twice.
    cases.append(("a row duplicated",
                  "\n".join(lines[: rows[0] + 1] + [lines[rows[0]]] + lines[rows[0] + 1:]),
                  f"{dropped_file}: 2 rows"))
    # 5. A row for a file that does not exist under src/.
    ghost = "| `src/core/no_such_file.cpp` | `test/docs/CMakeLists.txt` | nothing |"
    cases.append(("a row for no such file",
                  "\n".join(lines[: rows[-1] + 1] + [ghost] + lines[rows[-1] + 1:]),
                  "row for 'src/core/no_such_file.cpp', which is not"))
    for name, text, expected in cases:
        got = run(text)
        if not any(expected in p for p in got):
            failures.append(f"{name}: expected a problem containing {expected!r}; got "
                            f"{got or 'none'}")
        elif len(got) != 1:
            failures.append(f"{name}: expected exactly one problem; got {got}")
    if failures:
        print("test map self-test FAILED:\n" + "\n".join(failures), file=sys.stderr)
        return 1
    print(f"test map self-test: {len(cases)} altered tables, each problem reported")
    return 0


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--source-dir", default=os.path.join(os.path.dirname(__file__), ".."),
                    help="the repository root (default: this script's parent directory)")
    ap.add_argument("--self-test", action="store_true",
                    help="check the check on altered copies of the table")
    args = ap.parse_args()
    root = os.path.abspath(args.source_dir)
    with open(os.path.join(root, DOC), encoding="utf-8") as f:
        doc_text = f.read()
    if args.self_test:
        return self_test(root, doc_text)
    problems, (n, m, k) = check(root, doc_text)
    if problems:
        print(f"test map: {len(problems)} problem(s):", file=sys.stderr)
        for p in problems:
            print("  " + p, file=sys.stderr)
        return 1
    print(f"test map: {n} files, {m} with a same-name test, {k} in {DOC}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
