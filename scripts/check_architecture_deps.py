#!/usr/bin/env python3
"""Check docs/ARCHITECTURE.md's dependency tables against the CMake link graph.

Run by ctest (test/docs/CMakeLists.txt):
  docs.ArchitectureDependsOnMatchesCMake       the check
  docs.ArchitectureCheckReportsEveryDifference  --self-test: altered tables must be reported

Inputs:
  --graph  the build tree's evade_link_graph.txt, written at configure time by
           cmake/EvadeLinkGraph.cmake: "module <m>: <deps>" and "executable <e>: <deps>"
           lines giving each target's direct evade:: links (public and private), and
           "thirdparty <m>: <libs>" lines giving each module's other direct links.
  --doc    docs/ARCHITECTURE.md. Its module table (columns "module" and "depends on") and
           its executable table (columns "executable" and "links") are compared with the
           graph. In those columns only evade module names count (`evade::` prefix
           optional); third-party names (Eigen, LCM, NLopt, ...) and anything in
           parentheses are ignored; "every module" stands for all modules.

Also asserted: evade_guidance_node links no evade_sim, directly or through other modules;
and no physics module (PHYSICS) depends on evade::config, yaml-cpp or nlohmann-json, directly
or through the modules it links: a physics module takes typed structs and returns typed
structs, and the faces that read scenarios and write JSON or text live in evade::commands
(docs/ARCHITECTURE.md "Physics and faces").
Exit status 0 when everything matches, 1 with every difference listed otherwise.
"""
import argparse
import re
import sys

NODE = "evade_guidance_node"
FORBIDDEN_FOR_NODE = "sim"

# The modules that hold physics: none may reach the scenario reader (config) or a YAML or
# JSON library, directly or through what it links.
PHYSICS = ("dynamics", "sgp4", "conjunction", "threat", "formation", "observability", "sim",
           "assessment", "cam", "guidance")
FORBIDDEN_FOR_PHYSICS = "config"
# Third-party libraries a physics module must not link: a link item naming one of these.
FORBIDDEN_THIRDPARTY = ("yaml-cpp", "nlohmann_json")


def read_graph(path, thirdparty=None):
    """Returns (apps_on, {module: set(deps)}, {executable: set(deps)}); fills thirdparty
    ({module: set(libs)}) when given."""
    modules, executables, apps_on = {}, {}, False
    if thirdparty is None:
        thirdparty = {}
    with open(path, encoding="utf-8") as f:
        for raw in f:
            line = raw.strip()
            if not line or line.startswith("#"):
                continue
            if line.startswith("apps "):
                apps_on = line.split()[1] == "ON"
                continue
            head, _, deps = line.partition(":")
            kind, _, name = head.partition(" ")
            target = {"module": modules, "executable": executables,
                      "thirdparty": thirdparty}.get(kind)
            if target is None or not name:
                raise ValueError(f"{path}: cannot read line {raw!r}")
            target[name.strip()] = set(deps.split())
    return apps_on, modules, executables


def split_row(line):
    """Cells of a Markdown table row; '|' inside `code` or escaped as '\\|' does not split."""
    cells, cur, in_code, i = [], [], False, 0
    body = line.strip()
    if body.startswith("|"):
        body = body[1:]
    if body.endswith("|") and not body.endswith("\\|"):
        body = body[:-1]
    while i < len(body):
        c = body[i]
        if c == "\\" and i + 1 < len(body) and body[i + 1] == "|":
            cur.append("|")
            i += 2
            continue
        if c == "`":
            in_code = not in_code
        if c == "|" and not in_code:
            cells.append("".join(cur).strip())
            cur = []
        else:
            cur.append(c)
        i += 1
    cells.append("".join(cur).strip())
    return cells


def find_table(text, key_col, value_col):
    """Rows {key: value cell} of the first table whose header has both columns."""
    lines = text.splitlines()
    for i in range(len(lines) - 1):
        if not lines[i].lstrip().startswith("|"):
            continue
        header = [c.strip().lower() for c in split_row(lines[i])]
        if key_col not in header or value_col not in header:
            continue
        if not re.fullmatch(r"\s*\|?[\s:|-]+\|?\s*", lines[i + 1]):
            continue
        k, v = header.index(key_col), header.index(value_col)
        rows, order = {}, []
        for line in lines[i + 2:]:
            if not line.lstrip().startswith("|"):
                break
            cells = split_row(line)
            if len(cells) <= max(k, v):
                continue
            key = cells[k].replace("`", "").strip()
            if key.startswith("evade::"):
                key = key[len("evade::"):]
            if key in rows:
                raise ValueError(f"table '{key_col}' lists '{key}' twice")
            rows[key] = cells[v]
            order.append(key)
        return rows
    return None


def strip_parentheses(cell):
    prev = None
    while prev != cell:
        prev = cell
        cell = re.sub(r"\([^()]*\)", " ", cell)
    return cell


def named_modules(cell, universe):
    """Evade modules named in a table cell (outside parentheses)."""
    cell = strip_parentheses(cell)
    if re.search(r"\bevery module\b", cell, re.IGNORECASE):
        return set(universe)
    found = set()
    for tok in re.findall(r"[A-Za-z0-9_:]+", cell.replace("`", " ")):
        if tok.startswith("evade::"):
            tok = tok[len("evade::"):]
        if tok in universe:
            found.add(tok)
    return found


def node_path_to(graph_modules, start_deps, forbidden):
    """A link path from the node's direct deps to `forbidden`, or None."""
    stack = [(d, [d]) for d in sorted(start_deps)]
    seen = set()
    while stack:
        m, path = stack.pop()
        if m == forbidden:
            return path
        if m in seen:
            continue
        seen.add(m)
        for d in sorted(graph_modules.get(m, ())):
            stack.append((d, path + [d]))
    return None


def forbidden_lib(lib):
    """The forbidden third-party library a link item names, or None."""
    for name in FORBIDDEN_THIRDPARTY:
        if name in lib:
            return name
    return None


def physics_errors(modules, thirdparty):
    """Every physics module that reaches evade::config, yaml-cpp or nlohmann-json, with the
    link path; every PHYSICS name that is not a module."""
    errors = []
    for m in PHYSICS:
        if m not in modules:
            errors.append(f"physics module '{m}' is not a CMake target (scripts/"
                          "check_architecture_deps.py PHYSICS names it)")
            continue
        path = node_path_to(modules, {m}, FORBIDDEN_FOR_PHYSICS)
        if path:
            errors.append(f"physics module '{m}' links evade_{FORBIDDEN_FOR_PHYSICS} (path: "
                          + " -> ".join(path) + "); its scenario reader and JSON belong in "
                          "evade::commands")
        for dep_path in reachable_paths(modules, m):
            for lib in sorted(thirdparty.get(dep_path[-1], ())):
                bad = forbidden_lib(lib)
                if bad:
                    errors.append(f"physics module '{m}' links {bad} (path: "
                                  + " -> ".join(dep_path + [lib]) + "); a file format that "
                                  "needs it belongs in the module of its concept, not in physics")
    return errors


def reachable_paths(modules, start):
    """[start, ..., m] for start and every module it reaches (the first path found)."""
    paths, stack = {}, [[start]]
    while stack:
        path = stack.pop()
        if path[-1] in paths:
            continue
        paths[path[-1]] = path
        for d in sorted(modules.get(path[-1], ()), reverse=True):
            stack.append(path + [d])
    return [paths[k] for k in sorted(paths)]


def compare(kind, doc_rows, truth, universe, doc_name, col):
    errors = []
    for name in sorted(set(truth) - set(doc_rows)):
        errors.append(f"{kind} '{name}' is a CMake target but has no row in {doc_name}'s "
                      f"{kind} table (CMake links: {', '.join(sorted(truth[name])) or 'none'})")
    for name in sorted(set(doc_rows) - set(truth)):
        errors.append(f"{kind} '{name}' has a row in {doc_name} but is not a CMake target")
    for name in sorted(set(doc_rows) & set(truth)):
        said = named_modules(doc_rows[name], universe)
        real = truth[name]
        if said != real:
            missing, extra = sorted(real - said), sorted(said - real)
            parts = []
            if missing:
                parts.append(f"missing from the table: {', '.join(missing)}")
            if extra:
                parts.append(f"in the table but not linked: {', '.join(extra)}")
            errors.append(f"{kind} '{name}': \"{col}\" says {{{', '.join(sorted(said))}}}, "
                          f"CMake links {{{', '.join(sorted(real))}}} ({'; '.join(parts)})")
    return errors


def check(apps_on, modules, executables, doc_text, doc_name="docs/ARCHITECTURE.md",
          thirdparty=None):
    errors = physics_errors(modules, thirdparty or {})
    mod_rows = find_table(doc_text, "module", "depends on")
    if mod_rows is None:
        return [f"{doc_name}: no table with columns 'module' and 'depends on'"]
    universe = set(modules) | set(mod_rows)
    errors += compare("module", mod_rows, modules, universe, doc_name, "depends on")
    if apps_on:
        exe_rows = find_table(doc_text, "executable", "links")
        if exe_rows is None:
            errors.append(f"{doc_name}: no table with columns 'executable' and 'links'")
        else:
            errors += compare("executable", exe_rows, executables, universe, doc_name, "links")
        if NODE not in executables:
            errors.append(f"{NODE} is not among the configured executables")
        else:
            path = node_path_to(modules, executables[NODE], FORBIDDEN_FOR_NODE)
            if path:
                errors.append(f"{NODE} links evade_{FORBIDDEN_FOR_NODE} (path: {NODE} -> "
                              + " -> ".join(path) + "); the node must not link the simulator")
    return errors


def self_test(doc_text):
    """Builds a graph equal to the doc's own tables, then alters it: each change must be
    reported, and the unaltered graph must pass."""
    mod_rows = find_table(doc_text, "module", "depends on")
    exe_rows = find_table(doc_text, "executable", "links")
    if mod_rows is None or exe_rows is None:
        print("self-test: the doc lacks the module or the executable table")
        return 1
    universe = set(mod_rows)
    base_mods = {m: named_modules(c, universe) for m, c in mod_rows.items()}
    base_exes = {e: named_modules(c, universe) for e, c in exe_rows.items()}

    def copy():
        return ({k: set(v) for k, v in base_mods.items()},
                {k: set(v) for k, v in base_exes.items()})

    cases = []
    mods, exes = copy()
    cases.append(("unaltered", mods, exes, doc_text, None))
    physics = physics_cases(base_mods, base_exes, doc_text, copy)
    with_dep = sorted(m for m in base_mods if base_mods[m])
    if not with_dep:
        print("self-test: no module in the table has a dependency")
        return 1
    m0 = with_dep[0]
    d0 = sorted(base_mods[m0])[0]
    mods, exes = copy()
    mods[m0].discard(d0)
    cases.append((f"'{m0}' no longer links '{d0}'", mods, exes, doc_text, f"module '{m0}'"))
    mods, exes = copy()
    other = sorted(universe - base_mods[m0] - {m0})[0]
    mods[m0].add(other)
    cases.append((f"'{m0}' also links '{other}'", mods, exes, doc_text, f"module '{m0}'"))
    mods, exes = copy()
    mods["zz_new_module"] = {"core"}
    cases.append(("a new module without a row", mods, exes, doc_text, "'zz_new_module'"))
    mods, exes = copy()
    del mods[m0]
    for deps in mods.values():
        deps.discard(m0)
    for deps in exes.values():
        deps.discard(m0)
    cases.append((f"module '{m0}' removed from CMake", mods, exes, doc_text, f"'{m0}'"))
    row = next(line for line in doc_text.splitlines()
               if line.lstrip().startswith("|") and split_row(line)[0].strip("` ") == m0)
    cases.append((f"row '{m0}' deleted from the doc", *copy(),
                  doc_text.replace(row + "\n", ""), f"'{m0}' is a CMake target"))
    mods, exes = copy()
    if NODE in exes:
        exes[NODE].add(FORBIDDEN_FOR_NODE)
        cases.append(("the node links sim directly", mods, exes, doc_text, f"{NODE} links evade_sim"))
        mods, exes = copy()
        direct = sorted(exes[NODE] - {FORBIDDEN_FOR_NODE})
        if direct:
            mods[direct[0]].add(FORBIDDEN_FOR_NODE)
            cases.append((f"the node reaches sim through '{direct[0]}'", mods, exes, doc_text,
                          f"{NODE} links evade_sim"))
    mods, exes = copy()
    exes["zz_new_tool"] = set()
    cases.append(("a new executable without a row", mods, exes, doc_text, "'zz_new_tool'"))

    cases = [(n, m, e, t, {}, x) for n, m, e, t, x in cases] + physics
    failed = 0
    for name, mods, exes, text, thirdparty, expect in cases:
        errors = check(True, mods, exes, text, thirdparty=thirdparty)
        if expect is None:
            ok = not errors
        else:
            ok = any(expect in e for e in errors)
        print(f"self-test {'ok  ' if ok else 'FAIL'} {name}")
        for e in errors:
            print(f"    reported: {e}")
        failed += 0 if ok else 1
    print(f"self-test: {len(cases) - failed} of {len(cases)} cases as expected")
    return 1 if failed else 0


def physics_summary():
    return (f"{len(PHYSICS)} physics modules ({', '.join(PHYSICS)}) reach no evade_"
            f"{FORBIDDEN_FOR_PHYSICS}, {' or '.join(FORBIDDEN_THIRDPARTY)}")


def physics_cases(base_mods, base_exes, doc_text, copy):
    """Self-test cases of the physics rule: each alteration must be reported."""
    cases = []
    free = [m for m in PHYSICS if m in base_mods]
    if not free:
        return cases
    p = free[0]
    mods, exes = copy()
    mods[p].add(FORBIDDEN_FOR_PHYSICS)
    cases.append((f"physics '{p}' links config", mods, exes, doc_text, {},
                  f"physics module '{p}' links evade_{FORBIDDEN_FOR_PHYSICS}"))
    mods, exes = copy()
    mods["zz_face"] = {FORBIDDEN_FOR_PHYSICS}
    mods[p].add("zz_face")
    cases.append((f"physics '{p}' reaches config through another module", mods, exes, doc_text,
                  {}, f"physics module '{p}' links evade_{FORBIDDEN_FOR_PHYSICS} (path: {p} -> "
                  "zz_face"))
    mods, exes = copy()
    cases.append((f"physics '{p}' links nlohmann_json", mods, exes, doc_text,
                  {p: {"nlohmann_json::nlohmann_json"}}, f"physics module '{p}' links nlohmann_json"))
    below = sorted(m for m in base_mods[p])
    if below:
        mods, exes = copy()
        cases.append((f"physics '{p}' reaches yaml-cpp through '{below[0]}'", mods, exes, doc_text,
                      {below[0]: {"yaml-cpp"}},
                      f"physics module '{p}' links yaml-cpp (path: {p} -> {below[0]}"))
    return cases


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--graph", required=True)
    ap.add_argument("--doc", required=True)
    ap.add_argument("--self-test", action="store_true")
    args = ap.parse_args()
    with open(args.doc, encoding="utf-8") as f:
        doc_text = f.read()
    if args.self_test:
        return self_test(doc_text)
    thirdparty = {}
    apps_on, modules, executables = read_graph(args.graph, thirdparty)
    errors = check(apps_on, modules, executables, doc_text, thirdparty=thirdparty)
    if errors:
        print(f"{args.doc} does not match the CMake link graph ({args.graph}):")
        for e in errors:
            print(f"  - {e}")
        print("Fix the table (or the CMake links) so that both say the same.")
        return 1
    if apps_on:
        print(f"{args.doc}: {len(modules)} modules and {len(executables)} executables match "
              f"the CMake link graph; {NODE} does not link evade_{FORBIDDEN_FOR_NODE}; "
              f"{physics_summary()}")
    else:
        print(f"{args.doc}: {len(modules)} modules match the CMake link graph (apps not "
              f"configured: executables not checked); {physics_summary()}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
