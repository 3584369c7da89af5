"""--self-test: a small tree with one problem of each kind; each reported, nothing else."""
import os
import tempfile

from .help_texts import parse_help
from .help_units import unit_findings
from .runner import run_checks


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
