#!/usr/bin/env python3
# Runs vkd3d's effect conformance cases (vkd3d/*.shader_test: each [effect] section an effect
# the native compiler accepts, each [effect fail] one it rejects) through `fxkit check
# --profile P` and fails when fxkit disagrees on a case that argued.txt does not name.
# Usage: vkd3d_effects.py FXKIT [--list]      (--list: print every case's id and verdict)
import glob
import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))


def cases():
    """(id, profile, fxc_accepts, source) per effect section; id = file#n, n counting the
    file's effect sections from 1."""
    out = []
    for path in sorted(glob.glob(os.path.join(HERE, "vkd3d", "*.shader_test"))):
        name = os.path.basename(path)
        profile, section, body, count = "fx_2_0", None, [], 0

        def flush():
            nonlocal count
            if section is not None and section.startswith("effect"):
                count += 1
                out.append((f"{name}#{count}", profile, "fail" not in section, "\n".join(body)))

        for line in open(path, encoding="utf-8").read().splitlines():
            m = re.match(r"^\[(.*)\]\s*$", line)
            if m:
                flush()
                section, body = m.group(1), []
                continue
            if section == "require":
                m = re.match(r"shader model\s*(<|>=)\s*([\d.]+)", line)
                if m and m.group(1) == ">=":
                    version = float(m.group(2))
                    profile = "fx_5_0" if version >= 5.0 else ("fx_4_1" if version >= 4.1 else "fx_4_0")
            elif section is not None and not line.startswith("%"):
                body.append(line)
        flush()
    return out


def argued():
    """Case ids fxkit deliberately or knowingly disagrees on (argued.txt: id, then why)."""
    ids = set()
    for line in open(os.path.join(HERE, "argued.txt"), encoding="utf-8"):
        line = line.strip()
        if line and not line.startswith("#"):
            ids.add(line.split()[0])
    return ids


def main():
    fxkit = sys.argv[1]
    listing = "--list" in sys.argv[2:]
    known = argued()
    agree, wrong, crashes = 0, [], 0
    all_cases = cases()
    with tempfile.TemporaryDirectory() as d:
        for case_id, profile, accepts, source in all_cases:
            path = os.path.join(d, "case.fx")
            with open(path, "w", encoding="utf-8") as f:
                f.write(source + "\n")
            try:
                r = subprocess.run([fxkit, "check", "--profile", profile, path], capture_output=True, text=True, timeout=60)
                rc, output = r.returncode, r.stdout + r.stderr
            except subprocess.TimeoutExpired:
                rc, output = 124, "timed out"
            if rc not in (0, 1):
                crashes += 1
            same = rc in (0, 1) and (rc == 0) == accepts
            agree += same
            if listing:
                print(f"{case_id} {profile} fxc {'accepts' if accepts else 'rejects'}: {'agree' if same else 'DISAGREE'}")
            if not same and case_id not in known:
                wrong.append(f"{case_id} ({profile}): fxc {'accepts' if accepts else 'rejects'} it, fxkit rc={rc}\n"
                             f"{source}\n--- fxkit:\n{output}")
    stale = sorted(known - {c[0] for c in all_cases})
    for w in wrong:
        print(w)
    for s in stale:
        print(f"argued.txt names {s}, which is no case")
    print(f"vkd3d effect conformance: agree {agree}/{len(all_cases)}, argued {len(known)}, "
          f"unexplained disagreements {len(wrong)}, crashes/hangs {crashes}")
    return 0 if not wrong and not stale and crashes == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
