#!/usr/bin/env python3
"""Issue 40's measurement: rayspec reduce over the planted faults.

For each fault that breaks a rule (harness/fault/rule_faults.cpp), the first
case claiming that rule which the fault makes fail on this machine's device
(up to --tries, default 3) is reduced with the fault standing in for a wrong
device; the reduced case must still fail with the fault and pass without
it. Prints one row per fault and the totals: how many reduced, the median
and largest size ratio (rays, instances, primitives, statements; before
over after) and the time taken.

  python3 tools/reduce-matrix.py OUT [--jobs 2] [--only FAULT ...]
"""
import argparse
import concurrent.futures as cf
import os
import re
import statistics
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BIN = os.path.join(ROOT, "build", "rayspec")
SIZE = re.compile(r"Reduced \S+: rays (\d+) -> (\d+), instances (\d+) -> (\d+), "
                  r"geometries (\d+) -> (\d+), primitives (\d+) -> (\d+), statements (\d+) -> (\d+)")
TIME = re.compile(r"(\d+) variants .* in ([\d.]+) s")


def rule_faults():
    text = open(os.path.join(ROOT, "harness/fault/rule_faults.cpp")).read()
    out = []
    for rule, breaks in re.findall(r'\{"(R-[A-Z0-9-]+)",\s*\{([^}]*)\}', text):
        for fault in re.findall(r'"([a-z0-9-]+)"', breaks):
            out.append((rule, fault))
    return out


def rule_cases():
    listing = subprocess.run([BIN, "list", "--rules"], capture_output=True, text=True).stdout
    cases, rule = {}, None
    for line in listing.splitlines():
        if line.startswith("R-"):
            rule = line.split()[0]
            cases[rule] = []
        elif line.startswith("  ") and rule and not line.strip().endswith(" cases") \
                and not line.strip().endswith(" case"):
            cases[rule].append(line.strip())
    return cases


def first_variant(entry):
    """A listed case, or a sweep's first variant ("name (sweep: N variants)")."""
    if " (sweep:" not in entry:
        return entry
    sweep = entry.split(" (sweep:")[0]
    listing = subprocess.run([BIN, "list", "--filter", sweep + "/*"], capture_output=True,
                             text=True).stdout.splitlines()
    return listing[0].split()[0] if listing and not listing[0].endswith(" cases") else sweep


def run(args, log):
    with open(log, "w") as f:
        return subprocess.run(args, stdout=f, stderr=subprocess.STDOUT).returncode


def reduce_one(out, rule, fault, cases, tries):
    for case in [first_variant(c) for c in sorted(cases)[:tries]]:
        d = os.path.join(out, fault)
        start = time.time()
        # --keep RULE: a finding of the fault's rule, Fail or QualityWarning (a "should" rule).
        rc = run([BIN, "reduce", case, "--plant-fault", fault, "--keep", rule, "--out", d,
                  "--max-attempts", "400"], d + ".log")
        seconds = time.time() - start
        if rc == 1:
            continue
        row = {"rule": rule, "fault": fault, "case": case, "rc": rc, "seconds": seconds}
        text = open(d + ".log").read()
        m = SIZE.search(text)
        if rc != 0 or not m:
            row["error"] = text.strip().splitlines()[-1] if text.strip() else "no output"
            return row
        n = [int(x) for x in m.groups()]
        row["sizes"] = {k: (n[2 * i], n[2 * i + 1]) for i, k in
                        enumerate(["rays", "instances", "geometries", "primitives", "statements"])}
        t = TIME.search(text)
        row["variants"] = int(t.group(1)) if t else 0
        reduced = os.path.join(d, "reduced.yaml")
        row["fails_with"] = fails_by_rule(reduced, fault, rule, d + "-with")
        row["passes_without"] = run([BIN, "run", "--case", reduced, "--out", d + "-without"],
                                    d + "-without.log") == 0
        return row
    return {"rule": rule, "fault": fault, "case": "", "rc": 1, "error": "no case of the rule fails"}


def fails_by_rule(case, fault, rule, out):
    """The case with the fault gives a finding of the rule (a Fail, or a "should" rule's
    QualityWarning): its summary line names the rule."""
    run([BIN, "run", "--case", case, "--plant-fault", fault, "--out", out], out + ".log")
    summary = open(os.path.join(out, "summary.txt")).read() if os.path.exists(
        os.path.join(out, "summary.txt")) else ""
    return any(("Fail:" in line or "QualityWarning:" in line) and rule in line
               for line in summary.splitlines()[1:2])


def ratio(a, b):
    return a / b if b else float(a)


def main():
    p = argparse.ArgumentParser()
    p.add_argument("out")
    p.add_argument("--jobs", type=int, default=2)
    p.add_argument("--only", nargs="*")
    p.add_argument("--tries", type=int, default=3, help="cases of the rule tried per fault")
    a = p.parse_args()
    os.makedirs(a.out, exist_ok=True)
    cases = rule_cases()
    pairs, seen = [], set()
    for rule, fault in rule_faults():
        if fault in seen or (a.only and fault not in a.only):
            continue
        seen.add(fault)
        pairs.append((rule, fault))
    start = time.time()
    rows = []
    with cf.ThreadPoolExecutor(a.jobs) as pool:
        futures = [pool.submit(reduce_one, a.out, r, f, cases.get(r, []), a.tries) for r, f in pairs]
        for fut in cf.as_completed(futures):
            row = fut.result()
            rows.append(row)
            s = row.get("sizes")
            shown = " ".join(f"{k} {v[0]}->{v[1]}" for k, v in s.items()) if s else row.get("error", "")
            ok = "" if not s else (" ok" if row["fails_with"] and row["passes_without"] else
                                   f" CHECK fails_with={row['fails_with']} passes_without={row['passes_without']}")
            print(f"{row['fault']:34} {row['case']:54} {row.get('seconds', 0):6.1f} s  {shown}{ok}",
                  flush=True)
    reduced = [r for r in rows if r.get("sizes")]
    good = [r for r in reduced if r["fails_with"] and r["passes_without"]]
    print(f"\n{len(pairs)} faults: {len(reduced)} reduced ({len(good)} still fail with the fault and "
          f"pass without), {sum(1 for r in rows if r['rc'] == 1)} with no failing case of their "
          f"rule, {sum(1 for r in rows if r['rc'] not in (0, 1))} errors; {time.time() - start:.0f} s")
    for k in ["rays", "instances", "primitives", "statements"]:
        rs = [ratio(*r["sizes"][k]) for r in reduced]
        if rs:
            print(f"  {k:11} before/after: median {statistics.median(rs):.2f}, largest {max(rs):.2f}")
    secs = [r["seconds"] for r in reduced]
    if secs:
        print(f"  seconds per reduction: median {statistics.median(secs):.1f}, largest {max(secs):.1f}")
    return 0 if len(good) == len(reduced) else 1


if __name__ == "__main__":
    sys.exit(main())
