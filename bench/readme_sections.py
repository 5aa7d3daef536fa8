"""readme_sections.py - write generated tables into marked sections of bench/README.md.

A section is the text between the lines
    <!-- BEGIN <script> <name> ... -->
    <!-- END <script> <name> -->
(anything may follow the name on the BEGIN line, e.g. which CSV it comes from). The
generators (sdf_tables.py, pt_tables.py, lp_tables.py) call write_sections with --write FILE;
tests/readme.sh runs them on a copy of bench/README.md and diffs, so a table edited by hand or
a CSV changed without regenerating fails there.
"""
import os
import re
import sys

README = os.path.join(os.path.dirname(os.path.abspath(__file__)), "README.md")


def read_csv(path):
    """The rows of a benchmark CSV as dicts keyed by its header line."""
    import csv
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def write_sections(path, script, sections):
    """Replace each section named in `sections` (name -> list of lines) of `path`; exit 1 when
    a section's markers are missing or repeated."""
    with open(path) as fh:
        text = fh.read()
    for name, lines in sections.items():
        begin = re.compile(r"^<!-- BEGIN %s %s(?:[: ][^\n]*)? -->\n" % (re.escape(script), re.escape(name)), re.M)
        end = re.compile(r"^<!-- END %s %s -->$" % (re.escape(script), re.escape(name)), re.M)
        b = list(begin.finditer(text))
        e = list(end.finditer(text))
        if len(b) != 1 or len(e) != 1 or e[0].start() < b[0].end():
            sys.stderr.write("%s: %s: need one '<!-- BEGIN %s %s -->' line and one '<!-- END %s %s -->' line after it\n"
                             % (script, path, script, name, script, name))
            sys.exit(1)
        body = "\n".join(lines).strip("\n") + "\n"
        text = text[:b[0].end()] + body + text[e[0].start():]
    with open(path, "w") as fh:
        fh.write(text)


def target(argv):
    """'--write FILE' (FILE defaults to bench/README.md when omitted) -> FILE, else None;
    the option is removed from argv."""
    if "--write" not in argv:
        return None
    i = argv.index("--write")
    del argv[i]
    if i < len(argv) and not argv[i].startswith("-") and argv[i].endswith(".md"):
        return argv.pop(i)
    return README
