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
"""
import argparse
import bisect
import glob
import os
import re
import subprocess
import sys
import tempfile

PREFIXES = ("apps", "bench", "cmake", "docs", "include", "lcm_types", "scenarios", "scripts",
            "src", "test")
TOP_FILES = ("README.md", "CMakeLists.txt")
COMMENT_DIRS = ("src", "include", "apps", "test", "scripts", "bench")
SKIP_DIRS = {"corpus", "regressions", "data", "__pycache__"}
C_EXT = {".c", ".cc", ".cpp", ".cxx", ".h", ".hh", ".hpp", ".hxx"}
HASH_EXT = {".py", ".cmake", ".sh", ".bash"}

# A path token: a repository prefix or top-level file not preceded by another path
# component (build/test/x, out/hil/y, https://.../src/z are not repository paths).
PATH_RE = re.compile(
    r"(?<![\w./~$%@-])((?:{})/[\w./*?<>{{}}+@:#-]*|(?:{})(?![\w.-]))".format(
        "|".join(PREFIXES), "|".join(re.escape(f) for f in TOP_FILES)))
MD_RE = re.compile(r"(?<![\w./-])([\w./-]*[\w-]\.md)(?![\w-])")
UP_RE = re.compile(r"(?<![\w/.$}>-])((?:\.\./)+[\w.*-][\w./*-]*)")
ABS_RE = re.compile(r"(?<![\w.$}/-])(/(?:home|Users|work|root|mnt|srv)/[^\s'\"`)\]]*|~/[\w.][^\s'\"`)\]]*)")
FENCE_RE = re.compile(r"^\s*(```|~~~)")
# The evade CLI or the node as a command word (build/apps/evade, ./evade_guidance_node ...);
# never evade::module, apps/evade/ (a folder) or a word such as evade_sim.
CMD_RE = re.compile(r"(?<![\w.:-])((?:[\w.$/-]*/)?(evade_guidance_node|evade))(?![\w:/.-]|'s)")
SCRIPT_RE = re.compile(r"(?<![\w./-])((?:\./)?scripts/[\w.-]+)")
# Where a shell command ends: a pipe, ;, &&, ||, a background &, a comment, a redirection.
CMD_END_RE = re.compile(r"\s\|\s|;|&&|\|\||\s&(?:\s|$)|\s#|\s[12]?>|\s<|\)|\n\s*\n")
FLAG_NAME_RE = re.compile(r"^--[A-Za-z0-9][A-Za-z0-9-]*$")
CAPS_COMPONENT_RE = re.compile(r"^(?:[A-Z][A-Z0-9_]*|[a-z0-9_-]*[a-z0-9][A-Z]+)$")


class Problems:
    def __init__(self, root):
        self.root = root
        self.items = []

    def add(self, path, line, msg):
        rel = os.path.relpath(path, self.root) if os.path.isabs(path) else path
        self.items.append((rel, line, msg))

    def print_all(self, out=sys.stdout):
        for rel, line, msg in self.items:
            print(f"{rel}:{line}: {msg}", file=out)


class Text:
    """A file's text with offset -> line number."""

    def __init__(self, text):
        self.text = text
        self.starts = [0] + [m.end() for m in re.finditer(r"\n", text)]

    def line_of(self, off):
        return bisect.bisect_right(self.starts, off)


# ---------------------------------------------------------------------------------- paths

def strip_path_token(tok):
    tok = tok.split("#", 1)[0]
    tok = re.sub(r":\d.*$", "", tok)  # src/x.cpp:120, :120-130
    tok = tok.rstrip(".,:;!?'\")]")
    return tok


def is_placeholder(tok):
    if any(c in tok for c in "<>{}") or "..." in tok:
        return True
    for comp in tok.strip("/").split("/"):
        stem, ext = os.path.splitext(comp)
        if ext in (".md", ".txt"):  # README.md, CMakeLists.txt, docs/SECURITY.md: real names
            continue
        if CAPS_COMPONENT_RE.match(stem or comp):
            return True
    return False


INSTALL_DIRS = {"CMAKE_INSTALL_INCLUDEDIR": "include", "CMAKE_INSTALL_DATADIR": "share",
                "CMAKE_INSTALL_BINDIR": "bin", "CMAKE_INSTALL_LIBDIR": "lib"}


def install_map(root):
    """[(installed dir, source dir)] of the top-level CMakeLists.txt's install(DIRECTORY)
    rules: the docs may name a file where the install puts it (include/evade/lcm_types/ from
    lcm_types/)."""
    try:
        with open(os.path.join(root, "CMakeLists.txt"), encoding="utf-8") as f:
            cm = f.read()
    except OSError:
        return []
    out = []
    for m in re.finditer(r"install\(\s*DIRECTORY\s+(\S+)\s+DESTINATION\s+(\S+)", cm):
        src, dest = m.group(1), m.group(2)
        if "${" in src:
            continue
        dest = re.sub(r"\$\{(\w+)\}", lambda v: INSTALL_DIRS.get(v.group(1), "\0"), dest)
        if "\0" in dest or dest.startswith("/"):
            continue
        if not src.endswith("/"):
            dest = dest.rstrip("/") + "/" + os.path.basename(src)
        out.append((dest.rstrip("/"), src.rstrip("/")))
    return out


def path_exists(root, tok, installs=()):
    for dest, src in installs:  # a file where the install puts it: look at its source
        if tok.startswith(dest + "/") and dest != src:
            tok = src + tok[len(dest):]
            break
    full = os.path.join(root, tok)
    if any(c in tok for c in "*?["):
        return bool(glob.glob(full, recursive=True))
    if os.path.exists(full):
        return True
    # bench/threat_bench, test/.../x_test: the executable built from x.cpp
    if not os.path.splitext(tok)[1]:
        return any(os.path.exists(full + ext) for ext in (".cpp", ".cc", ".c", ".py"))
    return False


def check_paths(root, doc, text, problems, installs):
    for m in PATH_RE.finditer(text.text):
        tok = strip_path_token(m.group(1))
        if not tok or tok in PREFIXES or is_placeholder(tok):
            continue
        if not path_exists(root, tok, installs):
            problems.add(doc, text.line_of(m.start(1)),
                         f"names '{tok}', which does not exist in the repository")


# ---------------------------------------------------------------------------------- flags

def parse_help(out):
    """(flag names, subcommand names) from a CLI11 --help text."""
    flags, subs, section = set(), [], None
    for line in out.splitlines():
        if re.match(r"^\S.*:\s*$", line):
            section = line.strip().rstrip(":").lower()
            continue
        m = re.match(r"^\s+(-\S+)", line)
        if m and section != "subcommands":
            for name in m.group(1).split(","):
                name = re.sub(r"\{.*?\}", "", name)
                if name.startswith("--"):
                    flags.add(name)
            continue
        m = re.match(r"^\s+([a-z][\w-]*)(?:\s{2,}|$)", line)
        if m and section == "subcommands":
            subs.append(m.group(1))
    return flags, subs


class Cli:
    """The accepted flags of each command of one executable, from its --help texts."""

    def __init__(self, exe, name):
        self.exe, self.name, self.cache = exe, name, {}

    def help(self, path):
        key = tuple(path)
        if key not in self.cache:
            try:
                r = subprocess.run([self.exe, *path, "--help"], capture_output=True, text=True,
                                   timeout=60)
                out = r.stdout + r.stderr
                self.cache[key] = parse_help(out) if r.returncode == 0 else None
            except (OSError, subprocess.TimeoutExpired):
                self.cache[key] = None
        return self.cache[key]

    def subcommands(self, path):
        h = self.help(path)
        return h[1] if h else []


NUMERIC_TYPES = ("INT", "UINT", "FLOAT", "NUMBER")


def help_options(out):
    """(option names, type text, description) of each option line of a CLI11 --help text.
    The option column ends at the first run of two spaces; a description too long for the
    line follows on the next one, indented."""
    rows, lines, section = [], out.splitlines(), None
    for i, line in enumerate(lines):
        if re.match(r"^\S.*:\s*$", line):
            section = line.strip().rstrip(":").lower()
            continue
        m = re.match(r"^\s+(-\S+)(?: (.*?))?(?:\s{2,}(\S.*))?$", line)
        if not m or section == "subcommands":
            continue
        desc = m.group(3)
        if desc is None and i + 1 < len(lines) and re.match(r"^\s{8,}[^\s-]", lines[i + 1]):
            desc = lines[i + 1].strip()
        rows.append((m.group(1), (m.group(2) or "").strip(), desc or ""))
    return rows


def unit_findings(cmd, help_text):
    """(problems, notes) of one command's --help text: a numeric option without a [unit]; a
    TEXT option whose help gives a physical unit (a number kept in a string)."""
    problems, notes = [], []
    for names, typ, desc in help_options(help_text):
        flag = [n for n in names.split(",") if n.startswith("--")][-1:]
        flag = flag[0] if flag else names
        base = re.split(r"[:=\s]", typ, 1)[0] if typ else ""
        has_unit = re.search(r"\[[^\]]+\]", desc) is not None
        if base in NUMERIC_TYPES and not has_unit:
            problems.append(f"{cmd} {flag} ({typ}): help lacks the unit in brackets "
                            f"(e.g. [s], [m], [-]): '{desc}'")
        elif base == "TEXT" and has_unit and re.search(r"\[(?!-\])[^\]]*[a-z]", desc):
            notes.append(f"{cmd} {flag}: a number with a unit, but its type shows TEXT "
                         f"(kept in a string)")
    return problems, notes


def check_help_units(evade_exe, node_exe):
    """Every numeric flag of every command shows its type (CLI11 prints INT, FLOAT, ...) and
    its unit in brackets in its help ("[s]", "[m/s^2]", "[-]"). Flags whose help gives a unit
    but whose type is TEXT (numbers kept in a string) are listed as notes. Returns
    (problems, notes) as lines."""
    problems, notes = [], []

    def walk(exe, name, path):
        try:
            r = subprocess.run([exe, *path, "--help"], capture_output=True, text=True, timeout=60)
        except (OSError, subprocess.TimeoutExpired) as e:
            problems.append(f"{name} {' '.join(path)} --help: {e}")
            return
        if r.returncode != 0:
            problems.append(f"{' '.join([name, *path, '--help'])}: exit {r.returncode}")
            return
        p, n = unit_findings(" ".join([name, *path]), r.stdout)
        problems.extend(p)
        notes.extend(n)
        for sub in parse_help(r.stdout)[1]:
            walk(exe, name, [*path, sub])

    walk(evade_exe, "evade", [])
    walk(node_exe, "evade_guidance_node", [])
    return problems, notes


def command_units(text):
    """(start, end) of every fenced code line (backslash continuations joined) and every
    inline code span outside fences, as offsets into text.text; and a copy of the text in
    which `\\` line continuations and table-escaped `\\|` keep their length but read as
    spaces and pipes."""
    t = text.text
    work = list(t)
    units = []
    lines = t.split("\n")
    in_fence, off, fence_spans = False, 0, []
    i = 0
    while i < len(lines):
        line = lines[i]
        start = off
        if FENCE_RE.match(line):
            in_fence = not in_fence
            fence_spans.append((start, start + len(line)))
            off += len(line) + 1
            i += 1
            continue
        if in_fence:
            line_start, end = start, start + len(line)
            while line.rstrip().endswith("\\") and i + 1 < len(lines):
                work[line_start + len(line.rstrip()) - 1] = " "  # a continuation: one command
                i += 1
                line_start = end + 1
                line = lines[i]
                end = line_start + len(line)
            units.append((start, end))
            fence_spans.append((start, end))
            off = end + 1
            i += 1
            continue
        off += len(line) + 1
        i += 1
    masked = list(work)
    for a, b in fence_spans:
        for k in range(a, b):
            if masked[k] != "\n":
                masked[k] = " "
    masked = "".join(masked)
    for m in re.finditer(r"(`+)((?:(?!\n\s*\n).)+?)\1", masked, re.S):
        units.append((m.start(2), m.end(2)))
    work = "".join(work).replace("\\|", " |")
    return units, work


def flags_in(seg, base):
    """(flag alternatives, offset) of each --flag token of a command's argument text."""
    for m in re.finditer(r"\S+", seg):
        tok = m.group(0).strip("[](){}\"',.;:")
        if not tok.startswith("--") or tok == "--":
            continue
        names = [n.split("=", 1)[0].strip("[](){}\"',.;:") for n in tok.split("|")]
        names = [n for n in names if FLAG_NAME_RE.match(n)]
        if names:
            yield names, base + m.start()


def command_args(work, start, end):
    """The argument text of a command starting at start, up to where the command ends."""
    seg = work[start:end]
    m = CMD_END_RE.search(seg)
    return seg[: m.start()] if m else seg


def check_evade_command(cli, doc, text, work, args_start, end, problems):
    seg = command_args(work, args_start, end)
    words = [(w.group(0), args_start + w.start()) for w in re.finditer(r"\S+", seg)]
    if not words:
        return
    top = cli.subcommands([])
    first = words[0][0]
    paths, rest_from, need_all = None, 0, True
    if first.startswith("--"):
        paths, rest_from = [[]], 0
    elif first in top:
        subs = cli.subcommands([first])
        if subs and (len(words) == 1 or words[1][0].startswith("--")):
            # `evade plan --publish`: prose for "any plan command" (plan itself takes none)
            paths, rest_from, need_all = [[first, s] for s in subs], 1, False
        elif subs:
            second = words[1][0]
            if second in ("...", "…"):
                paths, need_all = [[first, s] for s in subs], False
            else:
                alts = second.split("|")
                bad = [a for a in alts if a not in subs]
                if bad:
                    if re.match(r"^[a-z][\w|-]*$", second):
                        problems.add(doc, text.line_of(words[1][1]),
                                     f"`{cli.name} {first} {second}`: unknown command "
                                     f"'{first} {bad[0]}' (commands: {', '.join(subs)})")
                    return
                paths = [[first, a] for a in alts]
            rest_from = 2
        else:
            paths, rest_from = [[first]], 1
    else:
        if (re.match(r"^[a-z][a-z0-9-]*$", first) and len(words) > 1
                and words[1][0].startswith("--")):
            problems.add(doc, text.line_of(words[0][1]),
                         f"`{cli.name} {first}`: unknown command '{first}' "
                         f"(commands: {', '.join(top)})")
        return
    rest = seg[words[rest_from][1] - args_start:] if rest_from < len(words) else ""
    base = words[rest_from][1] if rest_from < len(words) else args_start
    for names, off in flags_in(rest, base):
        for name in names:
            if name == "--help":
                continue
            ok = [name in (cli.help(p) or (set(), []))[0] for p in paths]
            if (all(ok) if need_all else any(ok)):
                continue
            if not need_all:
                problems.add(doc, text.line_of(off),
                             f"no `{cli.name} {paths[0][0]} ...` command accepts {name}")
                continue
            cmd = " ".join([cli.name] + (paths[0] if len(paths) == 1 else
                                         [paths[0][0], "|".join(p[1] for p in paths)]))
            problems.add(doc, text.line_of(off),
                         f"`{cmd}` does not accept {name} (see `{cmd} --help`)")


def check_script_command(root, doc, text, work, token, args_start, end, problems, cache):
    rel = token[2:] if token.startswith("./") else token
    path = os.path.join(root, rel)
    if not os.path.isfile(path):
        return  # the path check reports it
    if path not in cache:
        with open(path, encoding="utf-8", errors="replace") as f:
            cache[path] = f.read()
    seg = command_args(work, args_start, end)
    for names, off in flags_in(seg, args_start):
        for name in names:
            if not re.search(r"(?<![\w-])" + re.escape(name) + r"(?![\w-])", cache[path]):
                problems.add(doc, text.line_of(off),
                             f"`{rel}` does not mention {name} (not in the script's usage)")


def check_flags(root, doc, text, evade, node, problems, script_cache):
    units, work = command_units(text)
    for start, end in units:
        unit = work[start:end]
        for m in CMD_RE.finditer(unit):
            prefix = m.group(1)[: -len(m.group(2))]
            if prefix and not (prefix == "./" or
                               prefix.endswith(("apps/", "bin/", "evade_guidance_node/"))):
                continue  # some/other/evade: not the built CLI
            args_start = start + m.end()
            if m.group(2) == "evade":
                check_evade_command(evade, doc, text, work, args_start, end, problems)
                continue
            flags = (node.help([]) or (set(), []))[0]
            for names, off in flags_in(command_args(work, args_start, end), args_start):
                for name in names:
                    if name != "--help" and name not in flags:
                        problems.add(doc, text.line_of(off),
                                     f"`evade_guidance_node` does not accept {name} "
                                     f"(see `evade_guidance_node --help`)")
        for m in SCRIPT_RE.finditer(unit):
            check_script_command(root, doc, text, work, m.group(1), start + m.end(), end,
                                 problems, script_cache)


# ------------------------------------------------------------------------------ citations

def md_names(root):
    names = set()
    for dp, dn, fn in os.walk(root):
        dn[:] = [d for d in dn if not d.startswith(".") and d not in ("build", "out")
                 and not d.startswith("build-")]
        names.update(f for f in fn if f.endswith(".md"))
    return names


def check_citations(root, path, comments, problems, md_set, is_doc=False):
    """comments: (line, text) pairs of the file's comments (a doc: every line)."""
    here = os.path.dirname(path)
    for line, c in comments:
        for m in MD_RE.finditer(c):
            tok = m.group(1).rstrip(".")
            if re.search(r"--[\w-]+[ =]$", c[: m.start(1)]):
                continue  # `--report OUT.md`: a flag's argument in a usage line, not a citation
            if is_doc and PATH_RE.fullmatch(tok):
                continue  # a repository path: check_paths says whether it exists
            if re.match(r"(build|build-[\w-]+|out)/", tok):
                continue  # an output the scripts write (build/, build-fuzz/, out/), not a citation
            cands = [os.path.join(root, tok), os.path.join(here, tok),
                     os.path.join(root, "docs", tok)]
            if any(os.path.exists(p) for p in cands):
                continue
            if "/" not in tok and tok in md_set:
                continue
            if "<" in tok or "*" in tok:
                continue
            problems.add(path, line, f"cites '{tok}', which is not in the repository")
        for m in UP_RE.finditer(c):
            tok = m.group(1).rstrip(".,;:")
            target = os.path.normpath(os.path.join(here, tok))
            inside = (target + os.sep).startswith(os.path.normpath(root) + os.sep)
            if not inside or not (glob.glob(target) if "*" in tok else os.path.exists(target)):
                problems.add(path, line,
                             f"cites '{tok}', which is outside the repository" if not inside
                             else f"cites '{tok}', which does not exist")
        for m in ABS_RE.finditer(c):
            problems.add(path, line,
                         f"cites '{m.group(1)}', an absolute path outside the repository")


def c_comments(src):
    """(line, text) of each comment of C/C++ source (strings and chars skipped)."""
    out, i, n, line = [], 0, len(src), 1
    while i < n:
        ch = src[i]
        if ch == "\n":
            line += 1
            i += 1
        elif src.startswith("//", i):
            j = src.find("\n", i)
            j = n if j < 0 else j
            out.append((line, src[i + 2:j]))
            i = j
        elif src.startswith("/*", i):
            j = src.find("*/", i + 2)
            j = n if j < 0 else j
            for k, part in enumerate(src[i + 2:j].split("\n")):
                out.append((line + k, part))
            line += src.count("\n", i, j)
            i = j + 2
        elif src.startswith('R"', i) and (i == 0 or not (src[i - 1].isalnum() or src[i - 1] == "_")):
            m = re.match(r'R"([^()\\\s]{0,16})\(', src[i:])
            if not m:
                i += 1
                continue
            close = ")" + m.group(1) + '"'
            j = src.find(close, i + m.end())
            j = n if j < 0 else j + len(close)
            line += src.count("\n", i, j)
            i = j
        elif ch in "\"'":
            if ch == "'" and i > 0 and src[i - 1].isalnum():  # 1'000'000 digit separators
                i += 1
                continue
            j = i + 1
            while j < n and src[j] != ch and src[j] != "\n":
                j += 2 if src[j] == "\\" else 1
            i = j + 1
        else:
            i += 1
    return out


def hash_comments(src):
    """(line, text) of each # comment of a shell, Python or CMake file."""
    out = []
    for k, raw in enumerate(src.split("\n"), 1):
        s = re.sub(r'"(?:[^"\\]|\\.)*"|\'[^\']*\'', lambda m: " " * len(m.group(0)), raw)
        m = re.search(r"(?:^|(?<=\s))#", s)
        if m:
            out.append((k, raw[m.end():]))
    return out


def source_files(root):
    for d in COMMENT_DIRS:
        for dp, dn, fn in os.walk(os.path.join(root, d)):
            dn[:] = sorted(x for x in dn if x not in SKIP_DIRS and not x.startswith("."))
            for f in sorted(fn):
                p = os.path.join(dp, f)
                ext = os.path.splitext(f[:-3] if f.endswith(".in") else f)[1]  # x.hpp.in
                if ext in C_EXT:
                    yield p, "c"
                elif ext in HASH_EXT or f == "CMakeLists.txt":
                    yield p, "hash"
                elif not ext:
                    try:
                        with open(p, "rb") as fh:
                            if fh.read(2) == b"#!":
                                yield p, "hash"
                    except OSError:
                        pass


# ---------------------------------------------------------------------------------- main

def docs_of(root):
    docs = [os.path.join(root, "README.md")]
    docs += sorted(glob.glob(os.path.join(root, "docs", "*.md")))
    return [d for d in docs if os.path.isfile(d)]


def run_checks(root, evade_exe, node_exe):
    root = os.path.abspath(root)
    problems = Problems(root)
    evade, node = Cli(evade_exe, "evade"), Cli(node_exe, "evade_guidance_node")
    for cli in (evade, node):
        if cli.help([]) is None:
            problems.add(cli.exe, 0, f"`{cli.name} --help` failed: cannot list its flags")
            return problems
    md_set = md_names(root)
    installs = install_map(root)
    script_cache = {}
    for doc in docs_of(root):
        with open(doc, encoding="utf-8") as f:
            text = Text(f.read())
        check_paths(root, doc, text, problems, installs)
        check_flags(root, doc, text, evade, node, problems, script_cache)
        check_citations(root, doc, list(enumerate(text.text.split("\n"), 1)), problems,
                        md_set, is_doc=True)
    for path, kind in source_files(root):
        try:
            with open(path, encoding="utf-8") as f:
                src = f.read()
        except (UnicodeDecodeError, OSError):
            continue
        comments = c_comments(src) if kind == "c" else hash_comments(src)
        check_citations(root, path, comments, problems, md_set)
    return problems


SELF_TEST_README = """# t
Shipped: `scenarios/seed0.yaml`, src/core/, `lcm_types/*.lcm`, docs/A.md#anchor, apps/x.cpp:12.
Skipped: `scenarios/NAME.yaml`, scenarios/seedN.yaml, `include/evade/<module>/`, out/a/b.png,
build/bench/y, bench/b (an executable of bench/b.cpp).
Missing: `src/gone.cpp`, test/also_gone/x_test.cpp, `lcm_types/*.nothing`.

```sh
build/apps/evade sim --accel 1 --json     # fine
evade plan cam --lead-s 10 --pc-max 1e-4 --no-such-cam
evade plan observability|cam --plan-out F --lead-s 3
evade_guidance_node --rate-hz 50 --no-such-node \\
  --quiet --bogus-continued
scripts/tool --known --unknown-script-flag | grep x --not-checked
```
`evade scren --json`, `evade --version`, `evade plan ... --publish`, `evade sim --set k=v`.
See STYLE.md §2, docs/A.md, A.md and ../shared/notes.
"""
SELF_TEST_EXPECT = [
    ("README.md", 5, "names 'src/gone.cpp'"),
    ("README.md", 5, "names 'test/also_gone/x_test.cpp'"),
    ("README.md", 5, "names 'lcm_types/*.nothing'"),
    ("README.md", 9, "`evade plan cam` does not accept --no-such-cam"),
    ("README.md", 10, "`evade plan observability|cam` does not accept --lead-s"),
    ("README.md", 11, "`evade_guidance_node` does not accept --no-such-node"),
    ("README.md", 12, "`evade_guidance_node` does not accept --bogus-continued"),
    ("README.md", 13, "`scripts/tool` does not mention --unknown-script-flag"),
    ("README.md", 15, "unknown command 'scren'"),
    ("README.md", 16, "cites 'STYLE.md'"),
    ("README.md", 16, "cites '../shared/notes', which is outside the repository"),
    ("docs/A.md", 2, "names 'docs/ARCH.md'"),
    ("src/core/a.cpp", 1, "cites 'STYLE.md'"),
    ("src/core/a.cpp", 3, "cites '~/notes.txt'"),
    ("src/core/a.cpp", 4, "cites '../../../elsewhere/x.hpp', which is outside"),
    ("scripts/tool", 2, "cites 'NOTES.md'"),
]


def self_test(evade_exe, node_exe):
    with tempfile.TemporaryDirectory() as root:
        def write(rel, body):
            p = os.path.join(root, rel)
            os.makedirs(os.path.dirname(p), exist_ok=True)
            with open(p, "w", encoding="utf-8") as f:
                f.write(body)
        write("README.md", SELF_TEST_README)
        write("docs/A.md", "# A\nSee `docs/ARCH.md`? No: README.md.\n")
        write("scenarios/seed0.yaml", "x: 1\n")
        write("lcm_types/a.lcm", "\n")
        write("apps/x.cpp", "int main() { return 0; }\n")
        write("bench/b.cpp", "\n")
        write("src/core/a.cpp",
              "// Validate, then trust (STYLE.md §3).\n"
              "const char* s = \"STYLE.md in a string is not a comment\";\n"
              "/* notes: ~/notes.txt */\n"
              "int x;  // from ../../../elsewhere/x.hpp; ../../README.md is fine\n")
        write("scripts/tool", "#!/bin/sh\n# tool [--known]  (NOTES.md)\necho \"#--x\"\n")
        problems = run_checks(root, evade_exe, node_exe)
        got = [f"{f}:{l}: {m}" for f, l, m in problems.items]
        missing = [e for e in SELF_TEST_EXPECT
                   if not any(g.startswith(f"{e[0]}:{e[1]}: ") and e[2] in g for g in got)]
        extra = [g for g in got if not any(g.startswith(f"{e[0]}:{e[1]}: ") and e[2] in g
                                           for e in SELF_TEST_EXPECT)]
        # The --help-units reading of a CLI11 help text (a description on the next line too).
        canned = ("x\nUsage: x [OPTIONS]\n\nOptions:\n"
                  "  -h,--help                   Print this help message and exit\n"
                  "  --span-s FLOAT=5            time span [s]\n"
                  "  --count INT                 how many\n"
                  "  --key-id INT:INT in [1 - 2147483647]\n"
                  "                              which key [-] (default: the only one)\n"
                  "  --accel TEXT                acceleration [m/s^2]\n"
                  "  --name TEXT                 a name\n")
        up, un = unit_findings("x", canned)
        if (len(up) != 1 or "--count" not in up[0] or len(un) != 1 or "--accel" not in un[0]
                or parse_help(canned)[0] != {"--help", "--span-s", "--count", "--key-id",
                                             "--accel", "--name"}):
            print(f"self-test: --help-units reading wrong: problems {up}, notes {un}, "
                  f"flags {sorted(parse_help(canned)[0])}")
            missing.append(("--help-units", 0, "canned help"))
        for e in missing:
            print(f"self-test: NOT reported: {e[0]}:{e[1]}: ...{e[2]}...")
        for g in extra:
            print(f"self-test: reported but not expected: {g}")
        if missing or extra:
            print("self-test: all reports were:\n  " + "\n  ".join(got))
            return 1
        print(f"self-test: ok ({len(got)} problems reported, as expected)")
        return 0


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
