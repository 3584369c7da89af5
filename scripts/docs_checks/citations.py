"""Citations: no doc or comment cites a file outside the repository."""
import glob
import os
import re

from .common import PATH_RE


MD_RE = re.compile(r"(?<![\w./-])([\w./-]*[\w-]\.md)(?![\w-])")
UP_RE = re.compile(r"(?<![\w/.$}>-])((?:\.\./)+[\w.*-][\w./*-]*)")
ABS_RE = re.compile(r"(?<![\w.$}/-])(/(?:home|Users|work|root|mnt|srv)/[^\s'\"`)\]]*|~/[\w.][^\s'\"`)\]]*)")


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
