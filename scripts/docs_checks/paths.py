"""Paths: every repository path that README.md or a docs/*.md names exists."""
import glob
import os
import re

from .common import PATH_RE, PREFIXES


CAPS_COMPONENT_RE = re.compile(r"^(?:[A-Z][A-Z0-9_]*|[a-z0-9_-]*[a-z0-9][A-Z]+)$")


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
