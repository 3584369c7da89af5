"""What the checks share: the repository path pattern, the problem list, a text's line numbers."""
import bisect
import os
import re
import sys


PREFIXES = ("apps", "bench", "cmake", "docs", "include", "lcm_types", "scenarios", "scripts",
            "src", "test")
TOP_FILES = ("README.md", "CMakeLists.txt")

# A path token: a repository prefix or top-level file not preceded by another path
# component (build/test/x, out/hil/y, https://.../src/z are not repository paths).
PATH_RE = re.compile(
    r"(?<![\w./~$%@-])((?:{})/[\w./*?<>{{}}+@:#-]*|(?:{})(?![\w.-]))".format(
        "|".join(PREFIXES), "|".join(re.escape(f) for f in TOP_FILES)))


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
