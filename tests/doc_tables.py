#!/usr/bin/env python3
"""The study tables of the documentation are their CSVs': the tables of
doc/stability.md are what scripts/stability_tables.py makes of
doc/stability.csv, and doc/contact-solvers.md holds the table that
scripts/contact_solver_table.py makes of doc/contact-solvers.csv. A table
edited by hand, or a CSV rerun without its table, fails here.

usage: doc_tables.py SOURCE_DIR
"""
import os
import subprocess
import sys

source = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
    os.path.dirname(os.path.abspath(__file__)), "..")
failed = 0

check = subprocess.run([sys.executable,
                        os.path.join(source, "scripts", "stability_tables.py"),
                        "--check", source],
                       capture_output=True, text=True)
print((check.stdout + check.stderr).strip())
failed += check.returncode != 0

table = subprocess.run([sys.executable,
                        os.path.join(source, "scripts",
                                     "contact_solver_table.py"),
                        os.path.join(source, "doc", "contact-solvers.csv")],
                       capture_output=True, text=True, check=True).stdout
document = os.path.join(source, "doc", "contact-solvers.md")
if table in open(document).read():
    print("%s: holds the table of doc/contact-solvers.csv" % document)
else:
    print("%s: does not hold the table that scripts/contact_solver_table.py "
          "makes of doc/contact-solvers.csv; paste its output into "
          "section 3" % document)
    failed += 1
sys.exit(1 if failed else 0)
