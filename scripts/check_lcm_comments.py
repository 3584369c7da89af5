#!/usr/bin/env python3
"""The .lcm comments a sensor is written from say what the node checks (issue 46).

1. Every constant an .lcm comment names (REASON_..., MODE_..., AUTH_...: a word whose first part
   is the prefix of a declared constant) is declared in some lcm_types/*.lcm file.
2. The upper limits of evade_angles_t's fields that the node enforces (guidance::MeasurementLimits in
   include/evade/guidance/angles_measurement.hpp, read from the header, not copied here) appear in
   the fields' comments as "<= VALUE" and in docs/GUIDANCE_NODE.md NODE-IN-2 as "≤ VALUE".

  scripts/check_lcm_comments.py --source-dir .              exit 1 and one line per finding
  scripts/check_lcm_comments.py --source-dir . --self-test  altered copies must each be reported
"""
import argparse
import pathlib
import re
import sys

# evade_angles_t field -> the MeasurementLimits constant that bounds it from above.
ANGLE_LIMITS = {
    "sigma_angle_rad": "kMaxSigmaAngleRad",
    "sigma_rate_radps": "kMaxAngleRateRadps",
    "range_m": "kMaxRangeM",
    "range_rate_mps": "kMaxRangeRateMps",
}
CONST_RE = re.compile(r"^\s*const\s+\w+\s+([A-Z][A-Z0-9_]*)\s*=", re.M)
WORD_RE = re.compile(r"\b([A-Z][A-Z0-9]*)_[A-Z0-9_]*[A-Z0-9]\b")


def comments(text):
    return [line.split("//", 1)[1] for line in text.splitlines() if "//" in line]


def constant_findings(lcm_texts):
    declared = set()
    for text in lcm_texts.values():
        declared.update(CONST_RE.findall(text))
    prefixes = {name.split("_", 1)[0] for name in declared}
    out = []
    for name, text in sorted(lcm_texts.items()):
        for comment in comments(text):
            for m in WORD_RE.finditer(comment):
                if m.group(1) in prefixes and m.group(0) not in declared:
                    out.append(f"lcm_types/{name}: the comment names {m.group(0)}, which no .lcm "
                               "file declares")
    return out


def limit_values(header_text):
    return {k: v for k, v in re.findall(r"(kMax\w+)\s*=\s*([0-9.eE+-]+);", header_text)}


def same_number(text_value, value):
    try:
        return float(text_value) == float(value)
    except ValueError:
        return False


def limit_findings(angles_lcm, header_text, node_doc):
    values = limit_values(header_text)
    node_in_2 = node_doc.split("**NODE-IN-2", 1)[-1].split("- **NODE-IN-3", 1)[0]
    out = []
    for field, const in ANGLE_LIMITS.items():
        if const not in values:
            out.append(f"angles_measurement.hpp: MeasurementLimits::{const} not found")
            continue
        line = next((l for l in angles_lcm.splitlines() if re.search(rf"\b{field};", l)), "")
        said = re.findall(r"<=\s*([0-9.eE+-]+)", line.split("//", 1)[-1])
        if not any(same_number(s, values[const]) for s in said):
            out.append(f"lcm_types/evade_angles_t.lcm: {field}'s comment does not say "
                       f"<= {values[const]} ({const})")
        doc_said = re.findall(r"≤\s*([0-9.eE+-]+)", node_in_2)
        if not any(same_number(s, values[const]) for s in doc_said):
            out.append(f"docs/GUIDANCE_NODE.md NODE-IN-2 does not give {field}'s limit "
                       f"≤ {values[const]} ({const})")
    return out


def check(lcm_texts, header_text, node_doc):
    return constant_findings(lcm_texts) + limit_findings(
        lcm_texts.get("evade_angles_t.lcm", ""), header_text, node_doc)


def self_test(lcm_texts, header_text, node_doc):
    arm = lcm_texts["evade_arm_t.lcm"]
    angles = lcm_texts["evade_angles_t.lcm"]
    cases = {
        "a constant that is not declared": (
            dict(lcm_texts, **{"evade_arm_t.lcm": arm.replace("reason REASON_DISARMED", "reason REASON_NOPE")}),
            header_text, node_doc, ["REASON_NOPE"]),
        "a limit missing from a comment": (
            dict(lcm_texts, **{"evade_angles_t.lcm": angles.replace("<= 0.5", "")}),
            header_text, node_doc, ["sigma_angle_rad's comment"]),
        "a limit changed in the header": (
            lcm_texts, header_text.replace("kMaxRangeM = 1.0e8", "kMaxRangeM = 2.0e8"), node_doc,
            ["range_m's comment", "NODE-IN-2 does not give range_m"]),
        "a limit missing from NODE-IN-2": (
            lcm_texts, header_text, node_doc.replace("σ_angle ≤ 0.5", "σ_angle"),
            ["NODE-IN-2 does not give sigma_angle_rad"]),
    }
    ok = not check(lcm_texts, header_text, node_doc)
    if not ok:
        print("self-test: the tree itself has findings")
    for what, (texts, header, doc, expect) in cases.items():
        found = check(texts, header, doc)
        if len(found) != len(expect) or any(e not in f for e, f in zip(expect, found)):
            print(f"self-test: {what}: expected the findings {expect}, got {found}")
            ok = False
    return ok


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--source-dir", required=True, type=pathlib.Path)
    ap.add_argument("--self-test", action="store_true")
    args = ap.parse_args(argv)
    root = args.source_dir
    lcm_texts = {p.name: p.read_text(encoding="utf-8") for p in sorted(root.glob("lcm_types/*.lcm"))}
    header = (root / "include/evade/guidance/angles_measurement.hpp").read_text(encoding="utf-8")
    node_doc = (root / "docs/GUIDANCE_NODE.md").read_text(encoding="utf-8")
    if args.self_test:
        ok = self_test(lcm_texts, header, node_doc)
        print("check_lcm_comments self-test:", "ok" if ok else "FAILED")
        return 0 if ok else 1
    findings = check(lcm_texts, header, node_doc)
    for f in findings:
        print(f)
    print(f"check_lcm_comments: {len(findings)} findings in {len(lcm_texts)} .lcm files")
    return 1 if findings else 0


if __name__ == "__main__":
    sys.exit(main())
