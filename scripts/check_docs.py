#!/usr/bin/env python3
"""Check that README.md and docs/*.md name only what exists, and that comments cite nothing
outside the repository.

Run by ctest (test/docs/CMakeLists.txt, test/cli/CMakeLists.txt):
  docs.PathsAndFlagsExist                 the check, on the source tree
  docs.PathsAndFlagsCheckReportsProblems  --self-test: a small tree with one problem of each
                                          kind; every one must be reported, nothing else
  cli.NumericFlagsShowTypeAndUnit         --help-units: every numeric flag of every command
                                          shows its type (INT, FLOAT, ...) and its unit in
                                          brackets ([s], [m/s^2], [-]) in its --help

Usage:
  scripts/check_docs.py --evade EXE --node EXE --source-dir DIR [--self-test]
  scripts/check_docs.py --evade EXE --node EXE --help-units

  --evade       the built `evade` executable (its `--help` texts are the flag lists)
  --node        the built `evade_guidance_node` executable
  --source-dir  the repository root

What is checked:
1. Paths. Every repository path that README.md or a docs/*.md names, in backticks or in plain
   text, exists: tokens starting with apps/ bench/ cmake/ docs/ include/ lcm_types/
   scenarios/ scripts/ src/ test/, and README.md, CMakeLists.txt. Trailing punctuation,
   `:LINE` suffixes and `#anchors` are stripped; globs (`lcm_types/*.lcm`) must match a file.
   Skipped: generated paths (anything under out/ or build/: a token preceded by another path
   component is not a repository path), and paths with a placeholder (`<name>`, `{a,b}`,
   `...`, or a capital component such as NAME, FILE, seedN). A path without an extension
   that names an executable built from `PATH.cpp` (bench/threat_bench) is accepted.
2. Flags. Every `--flag` of a command shown in a fenced code block or an inline code span
   that starts with `evade <subcommand>` (or build/apps/evade ...) or `evade_guidance_node`
   is one that command accepts, as listed by `<exe> <subcommand...> --help` (run once per
   command; CLI11's option column, aliases included). Subcommands may be two words
   (`plan cam`); `plan a|b` must hold for each, `plan ...` for at least one. A word after
   `evade` that is no command, followed by a flag, is reported too. Flags of `scripts/NAME`
   commands must appear in that script's text (its usage comment).
3. Citations. No doc and no comment in src/ include/ apps/ test/ scripts/ bench/ cites a file
   outside the repository: a `NAME.md` that is not in the repository (e.g. "STYLE.md §2"),
   a `../` path leading out of it or to nothing, an absolute path under a home or
   workspace directory (home, Users, work, root, mnt or srv at the root) or under ~/.

Every problem is printed as FILE:LINE: message. Exit status 0 when there is none, 1 otherwise.

This file parses the arguments and runs the checks; they live in scripts/docs_checks/, one
module per kind (paths, flags, citations, help_units, self_test ...).
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # docs_checks/, from any cwd
from docs_checks.help_units import check_help_units  # noqa: E402
from docs_checks.runner import run_checks  # noqa: E402
from docs_checks.self_test import self_test  # noqa: E402
from docs_checks.sources import COMMENT_DIRS  # noqa: E402


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n", 1)[0])
    ap.add_argument("--evade", required=True, help="the built evade executable")
    ap.add_argument("--node", required=True, help="the built evade_guidance_node executable")
    ap.add_argument("--source-dir", help="the repository root (required but for --help-units)")
    ap.add_argument("--self-test", action="store_true",
                    help="check the check on a small tree with known problems")
    ap.add_argument("--help-units", action="store_true",
                    help="instead: every numeric flag's help shows its type and [unit]")
    a = ap.parse_args(argv)
    if a.self_test:
        return self_test(a.evade, a.node)
    if a.help_units:
        problems, notes = check_help_units(a.evade, a.node)
        for n in notes:
            print(f"note: {n}")
        for p in problems:
            print(p)
        if problems:
            print(f"check_docs --help-units: {len(problems)} problem(s)", file=sys.stderr)
            return 1
        print("check_docs --help-units: ok: every numeric flag shows its type and unit")
        return 0
    if not a.source_dir:
        ap.error("--source-dir is required")
    problems = run_checks(a.source_dir, a.evade, a.node)
    problems.print_all()
    if problems.items:
        print(f"check_docs: {len(problems.items)} problem(s)", file=sys.stderr)
        return 1
    print("check_docs: ok: paths, flags and citations of README.md, docs/*.md and the "
          "comments of " + ", ".join(d + "/" for d in COMMENT_DIRS))
    return 0


if __name__ == "__main__":
    sys.exit(main())
