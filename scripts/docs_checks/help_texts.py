"""The reading of a CLI11 --help text: each command's flags and subcommands."""
import re
import subprocess


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
