"""The whole check of a source tree: each doc's paths, flags and citations, each comment's."""
import glob
import os

from .citations import check_citations, md_names
from .common import Problems, Text
from .flags import check_flags
from .help_texts import Cli
from .paths import check_paths, install_map
from .sources import c_comments, hash_comments, source_files


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
