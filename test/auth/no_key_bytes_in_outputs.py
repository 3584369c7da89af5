#!/usr/bin/env python3
"""security.NoKeyBytesInAnyOutputForAnyMalformedKeyFile (docs/SECURITY.md KEY-1).

Writes one genuinely random key (its 64 hex digits known here) into every malformed key-file
shape we could think of -- the four fields in every wrong order, a missing field, an extra
field, the hex a digit short or long, a non-hex digit, upper case, CRLF, a NUL byte, the same id
twice, the hex in place of the id, a 1 MiB line, an all-zero, arithmetic or low-entropy key,
mode 0644, a symbolic link to a valid key file, a FIFO, a directory, (as root) a file owned by
nobody -- and runs each through the node and the three signing ground commands. Every run must
exit 2 (bad input), name the key file, and print neither the key's hex in either case nor any
16-hex-digit window of it, on stdout or stderr. A valid key file is the control: the ground
commands accept it (no acknowledgement over memq://: exit 4), so an exit 2 is the key file's
refusal and not a flag the command no longer knows.

usage: no_key_bytes_in_outputs.py EVADE EVADE_GUIDANCE_NODE
"""
import itertools
import os
import secrets
import subprocess
import sys
import tempfile

TIMEOUT_S = 60


def weak(key):
    """The weak-key rule of auth::key_weakness (a test key must not be refused for it)."""
    steps = {(key[i] - key[i - 1]) % 256 for i in range(1, len(key))}
    return all(b == 0 for b in key) or len(steps) == 1 or len(set(key)) < 16


def random_key():
    for _ in range(8):
        k = secrets.token_bytes(32)
        if not weak(k):
            return k
    raise RuntimeError("the random generator gives weak keys")


def windows(hex_text):
    """The key's text and every 16-digit window of it, lower case (outputs are lowered)."""
    h = hex_text.lower()
    return {h} | {h[i:i + 16] for i in range(len(h) - 15)}


def shapes(hex_key, hex_other):
    """(name, kind, content, extra secret hex texts). kind: text, mode0644, symlink, chown,
    fifo, dir."""
    fields = ["key", "1", "command", hex_key]
    out = []
    for order in itertools.permutations(range(4)):
        if order != (0, 1, 2, 3):
            line = " ".join(fields[i] for i in order)
            out.append(("fields in order %s" % "".join(map(str, order)), "text", line + "\n", []))
    for missing in range(4):
        line = " ".join(f for i, f in enumerate(fields) if i != missing)
        out.append(("field %d missing" % missing, "text", line + "\n", []))
    good = "key 1 command " + hex_key
    non_hex = hex_key[:30] + "g" + hex_key[31:]
    zero = "0" * 64
    arith = "".join("%02x" % ((0x37 + 5 * i) % 256) for i in range(32))
    low = "".join("%02x" % b for b in (bytes.fromhex(hex_key)[i % 11] for i in range(32)))
    out += [
        ("extra field at the end", "text", good + " extra\n", []),
        ("extra field in the middle", "text", "key 1 command extra " + hex_key + "\n", []),
        ("the hex twice", "text", good + " " + hex_key + "\n", []),
        ("hex one digit short", "text", good[:-1] + "\n", []),
        ("hex one digit long", "text", good + "a\n", []),
        ("non-hex digit", "text", "key 1 command " + non_hex + "\n", []),
        ("upper case", "text", "key 1 command " + hex_key.upper() + "\n", []),
        ("CRLF line ending", "text", good + "\r\n", []),
        ("NUL byte in the hex", "text", "key 1 command " + hex_key[:20] + "\0" + hex_key[21:] + "\n", []),
        ("NUL byte after the line", "text", good + "\0\n", []),
        ("same id twice", "text", good + "\n" + good + "\n", []),
        ("same id twice, other role", "text", good + "\nkey 1 sensor " + hex_other + "\n", [hex_other]),
        ("the hex in place of the id", "text", "key " + hex_key + " command " + hex_key + "\n", []),
        ("the hex in place of the id and role", "text", "key " + hex_key + " " + hex_key + " " + hex_key + "\n", []),
        ("a 1 MiB line", "text", "key 1 command " + hex_key * (1 << 14) + "\n", []),
        ("a 1 MiB comment before the key", "text", "# " + hex_key * (1 << 14) + "\n" + good + "\n", []),
        ("an all-zero key", "text", "key 1 command " + zero + "\n", [zero]),
        ("an arithmetic key", "text", "key 1 command " + arith + "\n", [arith]),
        ("a low-entropy key", "text", "key 1 command " + low + "\n", [low]),
        ("0x prefix", "text", "key 1 command 0x" + hex_key[2:] + "\n", []),
        ("a valid line, then a bad one", "text", "key 2 command " + hex_other + "\nkey 1 comand " + hex_key + "\n", [hex_other]),
        ("only the hex", "text", hex_key + "\n", []),
        ("tab inside the hex", "text", "key 1 command " + hex_key[:32] + "\t" + hex_key[32:] + "\n", []),
        ("empty file", "text", "", []),
        ("mode 0644", "mode0644", good + "\n", []),
        ("a symlink to a valid key file", "symlink", good + "\n", []),
        ("a file owned by nobody", "chown", good + "\n", []),
        ("a FIFO", "fifo", "", []),
        ("a directory", "dir", "", []),
    ]
    return out


def make_file(d, name, kind, content):
    """Creates the shape in directory d; returns its path, or None when it cannot be made here."""
    p = os.path.join(d, name)
    if kind == "fifo":
        os.mkfifo(p, 0o600)
        return p
    if kind == "dir":
        os.mkdir(p, 0o700)
        return p
    target = p if kind != "symlink" else os.path.join(d, name + ".target")
    fd = os.open(target, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o600)
    os.write(fd, content.encode("latin-1"))
    os.close(fd)
    os.chmod(target, 0o644 if kind == "mode0644" else 0o600)
    if kind == "symlink":
        os.symlink(target, p)
    if kind == "chown":
        if os.geteuid() != 0:
            return None
        os.chown(p, 65534, 65534)
    return p


def commands(evade, node, key_file, state_dir):
    ground = ["--key", key_file, "--lcm-url", "memq://", "--ack-timeout-s", "0.05"]
    return [
        ("node", [node, "--keys", key_file, "--auth-state", os.path.join(state_dir, "node.state"),
                  "--max-cycles", "1", "--lcm-url", "memq://"]),
        ("arm", [evade, "arm", "--arm"] + ground),
        ("arm --json", [evade, "arm", "--arm"] + ground + ["--json"]),
        ("key --activate", [evade, "key", "--activate", "2"] + ground),
        ("plan formation", [evade, "plan", "formation", "--scenario", "seed3", "--publish"] + ground + ["--json"]),
    ]


def run(argv):
    try:
        r = subprocess.run(argv, stdin=subprocess.DEVNULL, capture_output=True, timeout=TIMEOUT_S)
        return r.returncode, r.stdout.decode("latin-1"), r.stderr.decode("latin-1")
    except subprocess.TimeoutExpired as e:
        return "timeout", (e.stdout or b"").decode("latin-1"), (e.stderr or b"").decode("latin-1")


def redact(text, secrets_):
    low = text.lower()
    for s in sorted(secrets_, key=len, reverse=True):
        while s in low:
            i = low.index(s)
            text = text[:i] + "<KEY>" + text[i + len(s):]
            low = text.lower()
    return text[-600:]


def check_outputs(what, out, err, secret_windows, problems):
    both = (out + "\n" + err).lower()
    found = sorted(w for w in secret_windows if w in both)
    if found:
        problems.append("%s: key text in the output (%d windows): %s"
                        % (what, len(found), redact(out + "\n" + err, secret_windows)))


def main(argv):
    if len(argv) != 3:
        print(__doc__)
        return 2
    evade, node = argv[1], argv[2]
    key = random_key()
    hex_key = key.hex()
    hex_other = random_key().hex()
    problems = []
    runs = 0
    base = tempfile.mkdtemp(prefix="evade_no_key_bytes_")  # mode 0700
    # Control: a valid key file (the command key, and the telemetry key the ground verifies the
    # node's answers with) is accepted by the ground (no acknowledgement: exit 4).
    d = tempfile.mkdtemp(dir=base)
    hex_tm = random_key().hex()
    valid = make_file(d, "valid.key", "text",
                      "key 1 command " + hex_key + "\nkey 3 telemetry " + hex_tm + "\n")
    for what, cmd in commands(evade, node, valid, d):
        rc, out, err = run(cmd)
        runs += 1
        check_outputs("control, " + what, out, err, windows(hex_key) | windows(hex_tm), problems)
        if what != "node" and rc != 4:
            problems.append("control, %s: a valid key file gave exit %s, not 4 (no acknowledgement): %s"
                            % (what, rc, redact(err, windows(hex_key))))
    skipped = []
    for i, (name, kind, content, extra) in enumerate(shapes(hex_key, hex_other)):
        d = tempfile.mkdtemp(dir=base)
        f = make_file(d, "k%02d.key" % i, kind, content)
        if f is None:
            skipped.append(name)
            continue
        secret_windows = windows(hex_key)
        for h in extra:
            secret_windows |= windows(h) if h != "0" * 64 else {h}
        for what, cmd in commands(evade, node, f, d):
            rc, out, err = run(cmd)
            runs += 1
            label = "%s, %s" % (name, what)
            check_outputs(label, out, err, secret_windows, problems)
            if rc != 2:
                problems.append("%s: exit %s, not 2: %s" % (label, rc, redact(err, secret_windows)))
            elif f not in out + err:
                problems.append("%s: exit 2 without naming the key file: %s"
                                % (label, redact(err, secret_windows)))
    subprocess.run(["rm", "-rf", base], check=False)
    for s in skipped:
        print("skipped (needs root): " + s)
    for p in problems:
        print("FAIL " + p)
    print("%d runs, %d shapes skipped, %d problems" % (runs, len(skipped), len(problems)))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
