#!/usr/bin/python3
"""Write doc/parameters.md from the executable's own listing of its entries.

usage: generate_parameters_doc.py EXECUTABLE [--output FILE]

Every entry, with its default, its documentation and its pattern (the
allowed values), comes from `EXECUTABLE --print-parameters-json`, the
defaults (no parameter file) in deal.II's JSON format: an object per
section, keyed by the names of its entries and subsections, with the
value, default_value, documentation and pattern_description of each
entry. deal.II 9.4.1 writes the names as they are (should a version write
them mangled, each character but a letter or a digit as _ and two hex
digits, they are demangled) and in the order of the PRM listing: the
entries of a section, then its subsections, each alphabetically. The units
note, which only the PRM listing has, comes from `EXECUTABLE
--print-parameters`. The two runs take about a second each, side by side.

The file it writes is entirely generated: edit the doc strings in the
source (the declare() functions of the parameter structs), or the preamble
below, and run this script again. tests/parameters_doc.sh checks that
doc/parameters.md is what this script makes of the executable.
Standard library only.
"""
import argparse
import concurrent.futures
import json
import os
import re
import subprocess
import sys
import tempfile

PREAMBLE = """\
This page lists every entry of a parameter file: its section, its default,
the values its pattern accepts and its documentation. The executable
prints the same with `ddcontact --print-parameters` (the defaults) or
`ddcontact --print-parameters FILE.prm` (the values of a scene).
[doc/scenes.md](scenes.md) explains how a scene is written and how to
choose the solver, the contact formulation and the adaptation;
[doc/running.md](running.md) covers the command line.

Sections are entered with `subsection NAME` ... `end` and entries set with
`set NAME = VALUE`. `--set "Section/Entry=value"` on the command line
overrides one entry. `Body <name>` and `Contact pair <name>` stand for one
section per name listed in `Bodies` and `Contact pairs`.

"Allowed" is what the parameter reader accepts before the scene's own
checks. The documentation often narrows it (E > 0, say), and the scene
checks refuse a value outside that in one line. "any text" means the
documentation gives the format.

A mistake is refused in one line that names the file, the line and the
entry with its section, and says what to write: a misspelled entry or
subsection gets the closest declared one ("did you mean 'Young's
modulus'?"), an entry written in the wrong subsection the subsections that
declare it, a selection outside its list the list (selections are written
as listed, in lower case), a number with units, a percentage or a decimal
comma the number to write, a subsection without its `end` its line.
Numbers are written without units. Every expression knows `x`, `y`, `pi`
(unless the scene's `Constants` define their own) and the constants; the
load parameter `t` only in the boundary conditions and the body force.
Entries that the chosen law leaves unused (a `Friction coefficient` with
`Friction = none`, a `Gap` with `Gap type = geometric`) are warned about.
"""


def fail(message):
    sys.exit("generate_parameters_doc.py: " + message)


def run(executable, arguments):
    """The standard output of a successful run of the executable."""
    with tempfile.TemporaryDirectory(prefix="parameters_doc.") as workdir:
        try:
            result = subprocess.run([executable] + arguments, cwd=workdir,
                                    stdin=subprocess.DEVNULL,
                                    capture_output=True, text=True,
                                    timeout=120)
        except OSError as error:
            fail("cannot run %s: %s" % (executable, error))
        except subprocess.TimeoutExpired:
            fail("%s %s took more than 120 s"
                 % (executable, " ".join(arguments)))
    if result.returncode != 0:
        fail("%s %s failed (exit %d):\n%s"
             % (executable, " ".join(arguments), result.returncode,
                result.stderr.strip()))
    return result.stdout


def parse_units(text):
    """The units note: the comment lines before the PRM listing."""
    units = []
    for line in text.splitlines():
        if line.startswith("# Listing of Parameters"):
            return " ".join(units)
        units.append(line[1:].strip() if line.startswith("#") else line)
    fail("no '# Listing of Parameters' in the output of --print-parameters")


def mangled(tree):
    """Whether the keys of tree are mangled: no key has a character that
    mangling replaces (deal.II 9.4.1 writes the names as they are)."""
    keys = []

    def collect(node):
        for key, child in node.items():
            keys.append(key)
            if isinstance(child, dict) and "value" not in child:
                collect(child)

    collect(tree)
    return all(re.fullmatch(r"(?:[A-Za-z0-9]|_[0-9a-f]{2})*", key)
               for key in keys)


def demangle(key):
    """deal.II's name of a mangled key: _XX is the byte with hex code XX
    (of UTF-8 for a character beyond ASCII)."""
    try:
        return re.sub(rb"_([0-9a-f]{2})",
                      lambda m: bytes([int(m.group(1), 16)]),
                      key.encode("ascii")).decode("utf-8")
    except UnicodeError:
        fail("cannot demangle the key '%s' of --print-parameters-json" % key)


def utf8(text):
    """text as written: boost's JSON writer may escape each byte of a UTF-8
    character on its own (\\u00XX), which json reads as Latin-1."""
    try:
        return text.encode("latin-1").decode("utf-8")
    except UnicodeError:
        return text


def parse_json(text):
    """The entries of --print-parameters-json in its order: a list of
    (section path as a tuple, name, default, documentation, pattern)."""
    try:
        tree = json.loads(text)
    except ValueError as error:
        fail("cannot read the output of --print-parameters-json: %s" % error)
    if not isinstance(tree, dict):
        fail("the output of --print-parameters-json is no JSON object")
    name_of = demangle if mangled(tree) else (lambda key: key)
    entries = []

    def visit(path, node):
        if not isinstance(node, dict):
            fail("unexpected %s in section %s of --print-parameters-json"
                 % (type(node).__name__, "/".join(path) or "(top level)"))
        for key, child in node.items():
            name = name_of(key)
            if isinstance(child, dict) and "value" in child:
                try:
                    entries.append((path, name,
                                    utf8(child["default_value"]).strip(),
                                    utf8(child["documentation"]),
                                    utf8(child["pattern_description"])))
                except KeyError as missing:
                    fail("entry %s has no %s in --print-parameters-json"
                         % ("/".join(path + (name,)), missing))
            elif isinstance(child, dict) and "alias" in child:
                continue  # an alias is no entry of its own
            else:
                visit(path + (name,), child)

    visit((), tree)
    return entries


INT_MAX = "2147483647"
UINT_MAX = "4294967295"


def describe_count(low, high):
    if low == high:
        return low
    if high == UINT_MAX:
        return "any number of" if low == "0" else "at least " + low
    return "%s to %s" % (low, high)


def split_pattern(text):
    """The text inside the outermost <...> at the start of text, and the
    rest after it."""
    if not text.startswith("<"):
        raise ValueError(text)
    depth = 0
    for i, c in enumerate(text):
        depth += {"<": 1, ">": -1}.get(c, 0)
        if depth == 0:
            return text[1:i], text[i + 1:]
    raise ValueError(text)


def describe(pattern):
    """Plain words for a deal.II pattern description; the description
    itself where it has no known form."""
    try:
        return describe_inner(pattern)
    except ValueError:
        return "`%s`" % pattern


def describe_inner(pattern):
    if not (pattern.startswith("[") and pattern.endswith("]")):
        raise ValueError(pattern)
    body = pattern[1:-1].strip()
    if body == "Anything":
        return "any text"
    if body == "Bool":
        return "`true` or `false`"
    if body.startswith("Selection "):
        options = body[len("Selection "):].split("|")
        return "one of " + ", ".join("`%s`" % o.strip() for o in options)
    m = re.fullmatch(r"Integer range (-?\d+)\.\.\.(-?\d+) \(inclusive\)", body)
    if m:
        low, high = m.groups()
        if high == INT_MAX:
            return "an integer >= %s" % low
        return "an integer from %s to %s" % (low, high)
    m = re.fullmatch(r"Double (\S+)\.\.\.(\S+) \(inclusive\)", body)
    if m:
        low, high = m.groups()
        if low == "-MAX_DOUBLE" and high == "MAX_DOUBLE":
            return "a number"
        if high == "MAX_DOUBLE":
            return "a number >= %s" % low
        if low == "-MAX_DOUBLE":
            return "a number <= %s" % high
        return "a number from %s to %s" % (low, high)
    if body.startswith("List of "):
        element, rest = split_pattern(body[len("List of "):])
        m = re.fullmatch(r" of length (\d+)\.\.\.(\d+) \(inclusive\)"
                         r"(?: separated by <(.*)>)?", rest)
        if not m:
            raise ValueError(pattern)
        low, high, separator = m.groups()
        return "a list of %s values separated by `%s`, each %s" % (
            describe_count(low, high), separator or ",",
            describe_inner(element))
    if body.startswith("Map of "):
        key, rest = split_pattern(body[len("Map of "):])
        m = re.fullmatch(r"(.)(<.*)", rest)
        if not m:
            raise ValueError(pattern)
        key_separator = m.group(1)
        value, rest = split_pattern(m.group(2))
        m = re.fullmatch(r" of length (\d+)\.\.\.(\d+) \(inclusive\)"
                         r"(?: separated by <(.*)>)?", rest)
        if not m:
            raise ValueError(pattern)
        low, high, separator = m.groups()
        return ("a list of %s `key%svalue` separated by `%s`; key: %s; "
                "value: %s" % (describe_count(low, high), key_separator,
                               separator or ",", describe_inner(key),
                               describe_inner(value)))
    raise ValueError(pattern)


def escape(text):
    """Markdown that shows text as it is: no HTML tags from <name>, no
    strike-through from ~, no emphasis from * or a word-edge _."""
    text = text.replace("\\", "\\\\").replace("`", "\\`")
    text = text.replace("*", "\\*").replace("<", "\\<").replace("~", "\\~")
    return re.sub(r"(?<![A-Za-z0-9])_|_(?![A-Za-z0-9])", r"\\_", text)


def starts_block(word):
    """Whether a line starting with word would start a list, quote,
    heading, table row or underline instead of continuing the text."""
    return (word in ("-", "+", "*", "|") or word.startswith((">", "#"))
            or re.fullmatch(r"\d+[.)]|[-=]+", word) is not None)


def wrap(text, indent, first_indent=None, width=78):
    """text in lines of at most width characters where the words allow,
    none of them starting a Markdown block."""
    lines, line = [], ""
    prefix = indent if first_indent is None else first_indent
    for word in text.split():
        if line and len(prefix) + len(line) + 1 + len(word) > width \
                and not starts_block(word):
            lines.append(prefix + line)
            prefix, line = indent, word
        else:
            line = word if not line else line + " " + word
    if line:
        lines.append(prefix + line)
    return lines


def anchor(heading):
    """GitHub's anchor of a heading."""
    text = heading.lower().replace("`", "")
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def render(units, entries):
    sections = []
    for section, name, default, documentation, pattern in entries:
        if not sections or sections[-1][0] != section:
            sections.append((section, []))
        sections[-1][1].append((name, default, documentation, pattern))

    out = ["# Parameters", "",
           "<!-- Generated by scripts/generate_parameters_doc.py from "
           "`ddcontact --print-parameters-json`;",
           "     do not edit: change the doc strings in source/ and run the "
           "script again",
           "     (checked by tests/parameters_doc.sh). -->", ""]
    out += PREAMBLE.rstrip("\n").split("\n") + [""]
    out += ["Units, as the executable states them:", ""]
    out += wrap(escape(units), "> ") + [""]
    out += ["## Sections", ""]
    headings = []
    for section, items in sections:
        title = "/".join(section) if section else "Top level"
        heading = "`%s`" % title if section else title
        headings.append(heading)
        out.append("- [%s](#%s): %d %s" % (
            heading, anchor(heading), len(items),
            "entry" if len(items) == 1 else "entries"))
    out.append("")
    for (section, items), heading in zip(sections, headings):
        out += ["## " + heading, ""]
        if section:
            out += wrap("In `subsection %s`%s." % (
                section[-1], "" if len(section) == 1 else
                ", inside `%s`" % "/".join(section[:-1])), "") + [""]
        for name, default, documentation, pattern in items:
            value = "`%s`" % default if default else "empty"
            out += wrap("**`%s`**: default %s; allowed: %s." % (
                name, value, describe(pattern)), "  ", "- ")
            if documentation:
                out += wrap(escape(documentation), "  ")
        out.append("")
    return "\n".join(out).rstrip("\n") + "\n"


def main():
    parser = argparse.ArgumentParser(
        description="Write doc/parameters.md from ddcontact "
        "--print-parameters-json.")
    parser.add_argument("executable", help="the ddcontact executable")
    parser.add_argument("--output", default=os.path.normpath(os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "..", "doc",
        "parameters.md")),
        help="the file to write (default doc/parameters.md)")
    arguments = parser.parse_args()
    executable = os.path.abspath(arguments.executable)

    # The two runs at once: a second each in a Debug build.
    with concurrent.futures.ThreadPoolExecutor(2) as pool:
        listing_json, listing = pool.map(
            lambda option: run(executable, [option]),
            ["--print-parameters-json", "--print-parameters"])
    entries = parse_json(listing_json)
    if not entries:
        fail("no entries in the output of --print-parameters-json")
    units = parse_units(listing)
    text = render(units, entries)
    with open(arguments.output, "w") as out:
        out.write(text)
    print("generate_parameters_doc.py: wrote %s (%d entries in %d sections)"
          % (arguments.output, len(entries),
             len({entry[0] for entry in entries})))


if __name__ == "__main__":
    main()
