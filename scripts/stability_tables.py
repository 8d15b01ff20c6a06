#!/usr/bin/env python3
"""Write the result tables of doc/stability.md from doc/stability.csv.

scripts/stability_matrix.sh runs this after every run of the matrix, so
that the tables and the case counts of the document are the CSV's. Each
"### <group>" subsection of "## Results" gets the table of the CSV rows of
that group; the line "N cases — ..." gets the counts. The text around them
is left alone.

usage: scripts/stability_tables.py [--check] [REPOSITORY]   (default: this
one); --check writes nothing and fails, naming the document, if its tables
differ from what the CSV gives (ctest doc_tables).
"""
import collections
import csv
import os
import re
import sys

HEADER = ("| case | parameters | exit | converged? | iterations | answer | "
          "reference | error | tol | verdict / message |\n"
          "| --- | --- | ---: | --- | ---: | --- | --- | ---: | ---: | --- |\n")


def row(r):
    message = r["message"].replace("ddcontact: error: ", "", 1)
    verdict = r["verdict"] + (": " + message if message else "")
    converged = "yes" if r["code"] == "0" else "no"
    cells = [r["name"], r["desc"], r["code"], converged, r["iterations"],
             r["answer"], r["reference"], r["error"], r["tol"], verdict]
    return "| " + " | ".join(c.replace("|", "/") for c in cells) + " |\n"


def render(root):
    """doc/stability.md's path, and its text with the tables and counts of
    doc/stability.csv; exits naming what is missing."""
    rows = list(csv.DictReader(open(os.path.join(root, "doc",
                                                 "stability.csv"))))
    path = os.path.join(root, "doc", "stability.md")
    text = open(path).read()

    groups = collections.OrderedDict()
    for r in rows:
        groups.setdefault(r["group"], []).append(r)
    for group, members in groups.items():
        # The table right under "### group": from its header line to the
        # first line that is not a table row.
        # Rows of cases the CSV lacks (run separately, e.g. STABILITY_HUGE)
        # stay, after the CSV's.
        pattern = re.compile(r"(### %s\n\n)((?:\|.*\n)+)" % re.escape(group))
        names = {r["name"] for r in members}

        def replace(m):
            kept = [line + "\n" for line in m.group(2).splitlines()[2:]
                    if line.split("|")[1].strip() not in names]
            return (m.group(1) + HEADER + "".join(row(r) for r in members) +
                    "".join(kept))
        text, n = pattern.subn(replace, text)
        if n != 1:
            sys.exit("stability_tables.py: no table under '### %s' in %s"
                     % (group, path))

    kind = collections.Counter()
    for r in rows:
        v = r["verdict"]
        kind["ok" if v == "ok" else "reference" if v == "reference"
             else "reported" if v.startswith("reported") else "failed"] += 1
    counts = ("%d cases — **%d ok, %d reference runs, %d stopped with\n"
              "a message; %d hangs, crashes, NaN or wrong answers.**"
              % (len(rows), kind["ok"], kind["reference"], kind["reported"],
                 kind["failed"]))
    text, n = re.subn(r"\d+ cases — \*\*\d+ ok, \d+ reference runs, \d+ "
                      r"stopped with\na message; \d+ hangs, crashes, NaN or "
                      r"wrong answers\.\*\*", counts, text)
    if n != 1:
        sys.exit("stability_tables.py: no case count line in %s" % path)
    return path, text, "tables of %d groups, %s" % (
        len(groups), counts.replace("\n", " "))


def main():
    args = [a for a in sys.argv[1:] if a != "--check"]
    root = args[0] if args else os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "..")
    path, text, what = render(root)
    if "--check" in sys.argv[1:]:
        if open(path).read() != text:
            sys.exit("%s: its tables differ from doc/stability.csv; run "
                     "scripts/stability_tables.py" % path)
        print("%s: %s, as in doc/stability.csv" % (path, what))
        return
    open(path, "w").write(text)
    print("%s: %s" % (path, what))


if __name__ == "__main__":
    main()
