"""checkTables.py: compares the entries each coupling class accepts (Test-couplingKeys' output) with the property tables of its header; exits 1 on any difference.

Usage: python3 checkTables.py KEYS HEADER_DIR

KEYS holds one line per header: its file name and the entries its class
accepts. The header is found by name below HEADER_DIR (lnInclude and build
folders are skipped; the name must be unique). Its property tables are the
\\table ... \\endtable blocks whose first row starts with "Property"; the
first column of every other row is a documented entry. Every accepted
entry must be documented, and every documented entry accepted.
"""

import os
import re
import sys


def find_headers(top):
    """{file name: [paths]} of the headers below top."""
    found = {}
    for root, dirs, files in os.walk(top):
        dirs[:] = [d for d in dirs if d != "lnInclude"
                   and not d.startswith("linux64")]
        for f in files:
            if f.endswith(".H"):
                found.setdefault(f, []).append(os.path.join(root, f))
    return found


def documented(path):
    """The first column of the rows of the header's property tables."""
    text = open(path, encoding="utf-8").read()
    names = set()
    for block in re.findall(r"\\table\n(.*?)\\endtable", text, re.S):
        rows = [r.strip() for r in block.splitlines() if r.strip()]
        if not rows or not rows[0].startswith("Property"):
            continue
        for row in rows[1:]:
            names.add(row.split("|")[0].strip())
    return names


def main(argv):
    if len(argv) != 3:
        sys.stderr.write(__doc__)
        return 2
    headers = find_headers(argv[2])
    problems = []
    lines = [l.split() for l in open(argv[1]) if l.strip()]
    if not lines:
        problems.append("%s lists no header" % argv[1])
    for fields in lines:
        name, keys = fields[0], set(fields[1:])
        paths = headers.get(name, [])
        if len(paths) != 1:
            problems.append("%s: %d headers of that name below %s"
                            % (name, len(paths), argv[2]))
            continue
        table = documented(paths[0])
        for key in sorted(keys - table):
            problems.append("%s: entry '%s' is read but not in its "
                            "property table" % (paths[0], key))
        for key in sorted(table - keys):
            problems.append("%s: entry '%s' is in its property table but "
                            "not read" % (paths[0], key))
        if keys <= table and table <= keys:
            print("ok    %s: %s" % (name, " ".join(sorted(keys))))
    for p in problems:
        print("FAIL  " + p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
