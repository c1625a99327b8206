# SPDX-License-Identifier: LGPL-2.1-or-later
"""The one way to change entries of a deal.II ParameterHandler file.

Tests and benchmarks run viscoslide on a parameter file with a few entries
changed (the output folder, the solver, the speeds). That was done with
sed in bash and with regular expressions or string replacement in Python,
each blind to subsections. Here an entry is named by its path,
'Subsection/Entry' (or 'Outer/Inner/Entry'), as in the program's
documentation, and

    override(text, {'Sliding/Solver': 'transient', 'Output/Write fields': None})

sets it where the file sets it (every such line of that subsection, the
indentation kept, a comment on the line dropped with the old value),
removes it for None, and adds an entry the file does not set at the end of
its subsection's last block, or, in a file with an `include` (whose
entries a later block must override), in a new block at the end.
value(text, path) reads an entry back. Standard library only.

    python3 -m viscoslide.prm FILE 'Sliding/Solver=transient' ...

prints FILE with the changes (for shell scripts), `--get PATH` one value."""
import re
import sys

_SUBSECTION = re.compile(r'^(\s*)subsection\s+(.*?)\s*$')
_END = re.compile(r'^\s*end\s*$')
_SET = re.compile(r'^(\s*)set\s+([^=]*?)\s*=\s*(.*?)\s*$')
_INCLUDE = re.compile(r'^\s*include\s')


def _name(text):
    """An entry or subsection name with its white space folded."""
    return ' '.join(text.split())


def _path(path):
    """'A/B/Entry' as (('A', 'B'), 'Entry')."""
    parts = [_name(p) for p in path.split('/')]
    return tuple(parts[:-1]), parts[-1]


def _code(line):
    """A line without its comment."""
    return line.split('#', 1)[0]


def entries(text):
    """(line index, subsection path, entry, value, indentation) of each
    `set` line, and the index of each subsection block's `end` line."""
    found, ends, stack = [], {}, []
    for i, line in enumerate(text.splitlines()):
        code = _code(line)
        if m := _SUBSECTION.match(code):
            stack.append((_name(m.group(2)), m.group(1)))
        elif _END.match(code) and stack:
            ends[tuple(s for s, _ in stack)] = (i, stack[-1][1])
            stack.pop()
        elif m := _SET.match(code):
            found.append((i, tuple(s for s, _ in stack), _name(m.group(2)),
                          m.group(3), m.group(1)))
    return found, ends


def value(text, path, default=None):
    """The value the text gives the entry at path (its last `set`), else
    default."""
    section, entry = _path(path)
    values = [v for _, s, e, v, _ in entries(text)[0] if (s, e) == (section, entry)]
    return values[-1] if values else default


def _block(section, lines):
    """A block that sets lines (already indented) in nested subsections."""
    head = [' ' * 2 * k + f'subsection {s}' for k, s in enumerate(section)]
    tail = [' ' * 2 * k + 'end' for k in reversed(range(len(section)))]
    return head + lines + tail


def override(text, changes, must_exist=False):
    """The text with changes ({'Subsection/Entry': value or None}) made.
    With must_exist, an entry the text does not set is an error."""
    lines = text.splitlines()
    found, ends = entries(text)
    include = any(_INCLUDE.match(_code(l)) for l in lines)
    inserts, appended = {}, {}
    for path, new in changes.items():
        section, entry = _path(path)
        where = [(i, indent) for i, s, e, _, indent in found if (s, e) == (section, entry)]
        if must_exist and not where:
            raise KeyError(f'{path}: not set in the parameter file')
        for i, indent in where:
            lines[i] = None if new is None else f'{indent}set {entry} = {new}'
        if where or new is None:
            continue
        if section in ends and not include:
            end, indent = ends[section]
            inserts.setdefault(end, []).append(f'{indent}  set {entry} = {new}')
        else:
            depth = ' ' * 2 * len(section)
            appended.setdefault(section, []).append(f'{depth}set {entry} = {new}')
    out = []
    for i, line in enumerate(lines):
        out += inserts.get(i, [])
        if line is not None:
            out.append(line)
    for section, new_lines in appended.items():
        out += _block(section, new_lines)
    return '\n'.join(out) + '\n'


def override_file(source, target, changes, must_exist=False):
    """Writes source's text with changes made to target; returns target."""
    with open(source) as f:
        text = f.read()
    with open(target, 'w') as f:
        f.write(override(text, changes, must_exist))
    return target


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    if len(argv) == 3 and argv[1] == '--get':
        with open(argv[0]) as f:
            print(value(f.read(), argv[2], ''))
        return
    if not argv or any('=' not in a for a in argv[1:]):
        sys.exit('usage: python3 -m viscoslide.prm FILE [PATH=VALUE ...] | FILE --get PATH')
    changes = dict(a.split('=', 1) for a in argv[1:])
    with open(argv[0]) as f:
        sys.stdout.write(override(f.read(), {k.strip(): v.strip() for k, v in changes.items()}))


if __name__ == '__main__':
    main()
