#!/usr/bin/python3
"""Regenerates one generated section of a hand-written doc page: the lines between
`<!-- BEGIN name -->` and `<!-- END name -->` are replaced, the rest of the page is kept.
A page without the markers gets the section appended at its end."""

import argparse
import os


def markers(name):
    return "<!-- BEGIN %s (generated, do not edit by hand) -->" % name, "<!-- END %s -->" % name


def replace_section(text, name, body):
    """`text` with the section `name` replaced by the lines `body` (a list of str). Raises
    ValueError when the markers are there but out of order or repeated."""
    begin, end = markers(name)
    lines = text.split("\n")
    starts = [k for k, l in enumerate(lines) if l.strip() == begin]
    ends = [k for k, l in enumerate(lines) if l.strip() == end]
    section = [begin] + list(body) + [end]
    if not starts and not ends:
        while lines and lines[-1] == "":
            lines.pop()
        return "\n".join(lines + [""] + section) + "\n"
    if len(starts) != 1 or len(ends) != 1 or ends[0] < starts[0]:
        raise ValueError("section %s: expected one %r before one %r" % (name, begin, end))
    return "\n".join(lines[:starts[0]] + section + lines[ends[0] + 1:])


def write_section(path, name, body):
    """Replaces the section `name` of the page at `path` (created if missing)."""
    text = open(path).read() if os.path.exists(path) else ""
    new = replace_section(text, name, body)
    with open(path + ".partial", "w") as f:
        f.write(new)
    os.replace(path + ".partial", path)


def command_parser(doc, default_page):
    """The argument parser of a command that writes a section: its description and epilog
    from the module docstring `doc` (first paragraph, the rest), and --page."""
    parser = argparse.ArgumentParser(
        description=doc.split("\n\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter,
        epilog="\n\n".join(doc.split("\n\n")[1:]))
    add_page_option(parser, default_page)
    return parser


def default_work_dir(name):
    """Where a command keeps its replay outputs unless told: $SF_WS/results/<name> (the
    current directory when SF_WS is not set)."""
    return os.path.join(os.environ.get("SF_WS", os.getcwd()), "results", name)


def add_page_option(parser, default):
    """The --page option of a command that writes a section ('-': print only)."""
    parser.add_argument("--page", default=default, help="page whose section is rewritten "
                        "(default %(default)s); '-' writes no page")


def publish(page, name, body):
    """Prints the section `name` and, unless `page` is '-', writes it into `page`."""
    print()
    print("\n".join(body))
    if page != "-":
        write_section(page, name, body)
        print("\nwrote section %s of %s" % (name, page))
