"""Flags: every --flag of a command a doc shows is one the command (or script) accepts."""
import os
import re


FENCE_RE = re.compile(r"^\s*(```|~~~)")
# The evade CLI or the node as a command word (build/apps/evade, ./evade_guidance_node ...);
# never evade::module, apps/evade/ (a folder) or a word such as evade_sim.
CMD_RE = re.compile(r"(?<![\w.:-])((?:[\w.$/-]*/)?(evade_guidance_node|evade))(?![\w:/.-]|'s)")
SCRIPT_RE = re.compile(r"(?<![\w./-])((?:\./)?scripts/[\w.-]+)")
# Where a shell command ends: a pipe, ;, &&, ||, a background &, a comment, a redirection.
CMD_END_RE = re.compile(r"\s\|\s|;|&&|\|\||\s&(?:\s|$)|\s#|\s[12]?>|\s<|\)|\n\s*\n")
FLAG_NAME_RE = re.compile(r"^--[A-Za-z0-9][A-Za-z0-9-]*$")


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
