"""--help-units: every numeric flag of every command shows its type and [unit] in its help."""
import re
import subprocess

from .help_texts import parse_help


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
