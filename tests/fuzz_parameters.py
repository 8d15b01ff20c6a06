#!/usr/bin/env python3
# DESCRIPTION: mutated parameter files either run to "converged" or are
# refused with one line `ddcontact: error: ...` and exit 1 or 4 -- never a
# crash, a stack trace, a hang, runaway memory or a NaN in the results.
"""Fuzz test of ddcontact's input handling.

Each variant is a shipped scene, made small (coarse meshes, few cycles, no
VTU), then changed by one to three mutations drawn with a fixed seed:
dropping a line, swapping the values of two entries, an extreme or odd
value for an entry (0, -1, 1e308, 1e-300, nan, inf, 2e9, 20, empty, text,
quotes and shell syntax, unicode, 300 characters), or an include (of the
file itself, of /dev/zero, of a missing file). Every variant runs under an
address-space limit and a time limit and is judged:

  converged  exit 0, summary.json says converged/completed, no NaN in it
             or in the CSV files;
  refused    exit 1 (bad input), 4 (diverged), 5 (target not reached),
             7 (write failure) or 8 (out of memory), exactly one line on
             stderr and it starts `ddcontact: error:`;
  FAILURE    anything else: a signal, another exit code, a time-out,
             several lines or a stack trace, a NaN written as a result.

usage: fuzz_parameters.py --exe DDCONTACT --source SRC_DIR
                          [--variants N] [--seed S] [--jobs J]
Exits 1 and prints every failing variant (its mutations and the head of
its stderr) if any variant fails.
"""
import argparse
import concurrent.futures
import json
import os
import random
import re
import resource
import shutil
import subprocess
import sys
import tempfile
import time

# The scenes, each with the entries that keep its runs small: the fuzzer
# exercises input handling, not the solvers' speed.
SCENES = {
    "two_bodies.prm": {},
    "paper_two_bodies.prm": {
        "Initial refinement": "0", "Max cycles": "2", "Delta": "0.3",
        "Gamma": "0.2", "Relaxation": "anderson", "Max iterations": "400"},
    "flat_punch.prm": {
        "Box refinement": "3", "Subdivisions": "12, 6",
        "Penalty": "1e-7"},
    "hertz.prm": {"Box refinement": "3", "Max iterations": "400",
                  "Max updates": "3"},
    "three_bodies.prm": {"Max iterations": "400"},
}

EXTREMES = ["0", "-1", "1", "2", "0.3", "1e-3", "100", "1e308", "-1e308", "1e-300", "nan", "inf",
            "-inf", "", "2e9", "20", "2147483648", "abc", "0.5",
            "x'; touch FUZZED; echo '", "$(touch FUZZED)", "`touch FUZZED`", "a|b;c:d", "\u00e9\u00df\u2603",
            "y" * 300, "1, 2, 3", "3: xy: 0; 0", "omega1", "-0"]

ENTRY = re.compile(r"^(\s*set\s+)([^=]+?)(\s*=\s*)(.*?)\s*(#.*)?$")


def small_scene(text, caps):
    """Apply the scene's caps to every entry of that name."""
    out = []
    for line in text.splitlines():
        m = ENTRY.match(line)
        if m and m.group(2).strip() in caps:
            line = m.group(1) + m.group(2) + m.group(3) + caps[m.group(2).strip()]
        out.append(line)
    text = "\n".join(out) + "\n"
    # Entries a scene leaves at their defaults that would make it slow.
    if "subsection Adaptation" in text and "Max cycles" not in caps:
        text = text.replace("subsection Adaptation\n",
                            "subsection Adaptation\n  set Max cycles = 2\n", 1)
    return text


def mutate(lines, rng, path):
    """One mutation of the lines (in place); returns its description."""
    entries = [i for i, l in enumerate(lines) if ENTRY.match(l)]
    kind = rng.choice(["drop", "swap", "extreme", "extreme", "extreme",
                       "include"])
    if kind == "drop" and lines:
        i = rng.randrange(len(lines))
        return "drop line %d: %s" % (i + 1, lines.pop(i).strip())
    if kind == "swap" and len(entries) >= 2:
        i, j = rng.sample(entries, 2)
        mi, mj = ENTRY.match(lines[i]), ENTRY.match(lines[j])
        lines[i] = mi.group(1) + mi.group(2) + mi.group(3) + mj.group(4)
        lines[j] = mj.group(1) + mj.group(2) + mj.group(3) + mi.group(4)
        return "swap values of '%s' and '%s'" % (mi.group(2), mj.group(2))
    if kind == "include":
        target = rng.choice([path, "/dev/zero", path + ".missing"])
        lines.insert(rng.randrange(len(lines) + 1), "include " + target)
        return "include " + target
    i = rng.choice(entries)
    m = ENTRY.match(lines[i])
    value = rng.choice(EXTREMES)
    lines[i] = m.group(1) + m.group(2) + m.group(3) + value
    return "set %s = %r" % (m.group(2).strip(), value[:40])


def limit_memory(limit_bytes):
    def apply():
        resource.setrlimit(resource.RLIMIT_AS, (limit_bytes, limit_bytes))
    return apply


def judge(code, stderr, outdir):
    """'converged', 'refused' or a failure reason."""
    lines = [l for l in stderr.splitlines() if l.strip()]
    if code == 0:
        summary = os.path.join(outdir, "summary.json")
        if not os.path.exists(summary):
            return "exit 0 without summary.json"
        text = open(summary).read()
        try:
            status = json.loads(text).get("status")
        except ValueError:
            return "summary.json is not JSON"
        if status not in ("converged", "completed"):
            return "exit 0 with status %r" % status
        for name in [summary] + [os.path.join(outdir, f)
                                 for f in os.listdir(outdir)
                                 if f.endswith(".csv")]:
            if re.search(r"\bnan\b|\binf\b", open(name).read(), re.I):
                return "NaN or inf in " + os.path.basename(name)
        return "converged"
    # The documented exit codes of a clean refusal (doc/running.md): bad input,
    # failed iteration, target not reached, write failure, out of memory.
    if code in (1, 4, 5, 7, 8) and len(lines) == 1 and \
            lines[0].startswith("ddcontact: error: ") and \
            "Stacktrace" not in stderr:
        return "refused"
    if code < 0:
        return "signal %d" % -code
    return "exit %d with %d line(s) on stderr" % (code, len(lines))


def run_variant(args, number, scene, text, mutations, work):
    directory = os.path.join(work, "v%04d" % number)
    os.makedirs(directory)
    path = os.path.join(directory, scene)
    with open(path, "w") as f:
        f.write(text.replace("@SELF@", path))
    outdir = os.path.join(directory, "out")
    env = dict(os.environ, OMP_NUM_THREADS="1", DEAL_II_NUM_THREADS="1",
               DDCONTACT_GMSH_TIMEOUT="10")
    start = time.time()
    try:
        p = subprocess.run(
            [args.exe, "--output", outdir, "--set", "Output/Write vtu=false",
             "--set", "Threads=1", path],
            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
            timeout=args.timeout, env=env, cwd=directory,
            preexec_fn=limit_memory(args.memory_mb << 20))
        verdict = judge(p.returncode, p.stderr.decode(errors="replace"),
                        outdir)
        stderr = p.stderr.decode(errors="replace")
    except subprocess.TimeoutExpired as e:
        verdict = "time-out after %d s" % args.timeout
        stderr = (e.stderr or b"").decode(errors="replace")
    seconds = time.time() - start
    # The shell syntax among the values creates this file if anything ever
    # hands a value to a shell.
    if os.path.exists(os.path.join(directory, "FUZZED")):
        verdict = "a shell ran a value"
    if verdict in ("converged", "refused"):
        shutil.rmtree(directory, ignore_errors=True)
    return number, scene, mutations, verdict, stderr, seconds


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--exe", required=True)
    parser.add_argument("--source", required=True)
    parser.add_argument("--variants", type=int, default=300)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--timeout", type=int, default=30)
    parser.add_argument("--memory-mb", type=int, default=4096)
    args = parser.parse_args()
    args.exe = os.path.abspath(args.exe)
    args.source = os.path.abspath(args.source)

    rng = random.Random(args.seed)
    bases = {s: small_scene(open(os.path.join(args.source, "prm", s)).read(),
                            caps) for s, caps in SCENES.items()}
    variants = []
    for number in range(args.variants):
        scene = rng.choice(sorted(bases))
        lines = bases[scene].splitlines()
        # Mostly one mutation, so that many variants still run.
        n_mutations = rng.choice([1, 1, 1, 2, 2, 3])
        mutations = [mutate(lines, rng, "@SELF@") for _ in range(n_mutations)]
        variants.append((number, scene, "\n".join(lines) + "\n", mutations))

    work = tempfile.mkdtemp(prefix="ddcontact-fuzz-")
    start = time.time()
    results = []
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        futures = [pool.submit(run_variant, args, n, s, t, m, work)
                   for n, s, t, m in variants]
        for f in concurrent.futures.as_completed(futures):
            results.append(f.result())
    elapsed = time.time() - start
    results.sort()

    counts = {"converged": 0, "refused": 0}
    failures = []
    for number, scene, mutations, verdict, stderr, seconds in results:
        if verdict in counts:
            counts[verdict] += 1
        else:
            failures.append((number, scene, mutations, verdict, stderr))
    for number, scene, mutations, verdict, stderr in failures:
        print("FAIL variant %d of %s: %s" % (number, scene, verdict))
        for m in mutations:
            print("    mutation: " + m)
        for line in stderr.splitlines()[:4]:
            print("    stderr: " + line[:200])
    peak_mb = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024.
    slowest = max(r[5] for r in results)
    print("fuzz: %d variants (seed %d): %d converged, %d refused, %d failed; "
          "%.0f s, slowest run %.1f s, peak memory of a run %.0f MB"
          % (len(results), args.seed, counts["converged"], counts["refused"],
             len(failures), elapsed, slowest, peak_mb))
    if not failures:
        shutil.rmtree(work, ignore_errors=True)
    else:
        print("failing variants kept in " + work)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
