"""The source files whose comments are checked, and the comments of C/C++ and # files."""
import os
import re


COMMENT_DIRS = ("src", "include", "apps", "test", "scripts", "bench")
SKIP_DIRS = {"corpus", "regressions", "data", "__pycache__"}
C_EXT = {".c", ".cc", ".cpp", ".cxx", ".h", ".hh", ".hpp", ".hxx"}
HASH_EXT = {".py", ".cmake", ".sh", ".bash"}


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
