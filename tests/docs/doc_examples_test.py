#!/usr/bin/env python3
"""What the docs show holds: every ```cpp and ```c block of the given
Markdown files is built as its own translation unit against the installed
headers' directories, with warnings as errors (so a dropped [[nodiscard]]
gab::Status fails), and linked into a shared object against libgab.so with no
undefined symbol (so it uses exported API only). Every ```python block is
byte-compiled. A block must therefore be complete: its includes, and
statements inside a function. Every relative link outside the code blocks
must name a file that exists. With --gab, the first synopsis of each command
in a file's code (a line "gab NAME ..." and the lines indented under it) must
have the words of the usage that `gab NAME` prints.

  doc_examples_test.py --cxx CXX --cc CC --library LIBGAB.so --work DIR
                       [--include DIR]... [--flag FLAG]... [--no-link] [--gab GAB] FILE.md...

Exit 0 when every check passes, 1 (naming the file and line of each failure,
with the compiler's output) otherwise.
"""

import argparse
import os
import re
import subprocess
import sys

FENCE = re.compile(r"^```\s*([A-Za-z0-9+]*)\s*$")
LINK = re.compile(r"\]\(([^)\s]+)\)")
LANGUAGES = {"cpp": "cpp", "c++": "cpp", "c": "c", "python": "python"}


def code_blocks(path, links):
    """(language, first line number, text) of each fenced block in path; the
    (line number, target) of each Markdown link outside them go to links."""
    blocks, language, start, lines = [], None, 0, None
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            match = FENCE.match(line.rstrip("\n"))
            if lines is None:
                if match:
                    language, start, lines = match.group(1).lower(), number + 1, []
                else:
                    links.extend((number, target) for target in LINK.findall(line))
            elif line.rstrip("\n").strip() == "```":
                blocks.append((language, start, "".join(lines)))
                lines = None
            else:
                lines.append(line)
    if lines is not None:
        raise SystemExit(f"{path}:{start - 1}: code block never closed")
    return blocks


def code_lines(path):
    """(line number, indentation, text) of each line inside a fenced block or an
    indented (4 spaces) code block of path."""
    out, inside = [], False
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            line = line.rstrip("\n")
            if FENCE.match(line) or (inside and line.strip() == "```"):
                inside = not inside
                continue
            indent = len(line) - len(line.lstrip(" "))
            if line.strip() and (inside or indent >= 4):
                out.append((number, indent, line.strip()))
    return out


def usage(gab, command, cache={}):
    """The words of `gab COMMAND`'s usage, or None when it is no command."""
    if command not in cache:
        result = subprocess.run([gab, command, "--no-such-option"], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                text=True)
        at = result.stderr.find("usage: gab " + command)
        cache[command] = result.stderr[at + 7:].split() if result.returncode == 2 and at >= 0 else None
    return cache[command]


def synopsis_failures(gab, path, checked):
    """Checks the first synopsis of each command in path's code; returns the
    failures, appends the commands checked to checked."""
    failures, seen, lines = 0, set(), code_lines(path)
    for i, (number, indent, text) in enumerate(lines):
        words = text.split()
        if len(words) < 2 or words[0] != "gab" or words[1] in seen or usage(gab, words[1]) is None:
            continue
        seen.add(words[1])
        checked.append(words[1])
        for later_number, later_indent, later_text in lines[i + 1:]:
            if later_number != number + 1 or later_indent <= indent:
                break
            words += later_text.split()
            number = later_number
        if words != usage(gab, words[1]):
            print(f"FAIL {path}:{lines[i][0]}: shows {' '.join(words)}\n  gab prints {' '.join(usage(gab, words[1]))}")
            failures += 1
    return failures


def build(args, language, source, output):
    """The compiler's command for one C or C++ block."""
    if language == "cpp":
        command = [args.cxx, "-std=c++17", "-Wall", "-Wextra", "-Wpedantic", "-Werror", "-Werror=unused-result"]
    else:
        command = [args.cc, "-std=c99", "-Wall", "-Wextra", "-pedantic", "-Werror"]
    command += args.flag + [f"-I{d}" for d in args.include]
    if args.no_link:
        return command + ["-fsyntax-only", source]
    return command + ["-fPIC", "-shared", "-o", output, source, args.library, "-Wl,--no-undefined"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--cxx", required=True)
    parser.add_argument("--cc", required=True)
    parser.add_argument("--library", required=True, help="libgab.so")
    parser.add_argument("--work", required=True, help="directory for the extracted sources")
    parser.add_argument("--include", action="append", default=[])
    parser.add_argument("--flag", action="append", default=[], help="one more compiler flag")
    parser.add_argument("--no-link", action="store_true", help="compile only")
    parser.add_argument("--gab", help="the gab tool: check the commands' synopses")
    parser.add_argument("files", nargs="+")
    args = parser.parse_args()
    os.makedirs(args.work, exist_ok=True)

    failures, counts, synopses = 0, {"cpp": 0, "c": 0, "python": 0}, []
    for path in args.files:
        stem = os.path.splitext(os.path.basename(path))[0]
        links = []
        if args.gab:
            failures += synopsis_failures(args.gab, path, synopses)
        for language, line, text in code_blocks(path, links):
            language = LANGUAGES.get(language)
            if language is None:
                continue
            counts[language] += 1
            where = f"{path}:{line}"
            if language == "python":
                try:
                    compile(text, where, "exec")
                except SyntaxError as error:
                    print(f"FAIL {where}: python block: {error}")
                    failures += 1
                continue
            source = os.path.join(args.work, f"{stem}_{line}.{language}")
            with open(source, "w", encoding="utf-8") as f:
                f.write(f'#line {line} "{path}"\n' + text)
            command = build(args, language, source, os.path.join(args.work, f"{stem}_{line}.so"))
            result = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
            if result.returncode != 0:
                print(f"FAIL {where}: {language} block does not build:\n  {' '.join(command)}\n{result.stdout}")
                failures += 1
            else:
                print(f"ok   {where}: {language} block")
        for line, target in links:
            if re.match(r"^[a-z]+:", target) or target.startswith("#"):
                continue
            if not os.path.exists(os.path.join(os.path.dirname(path), target.split("#")[0])):
                print(f"FAIL {path}:{line}: link to {target}, which does not exist")
                failures += 1
    print(f"{counts['cpp']} C++, {counts['c']} C and {counts['python']} Python blocks, "
          f"{len(synopses)} command synopses; {failures} failures")
    if counts["cpp"] + counts["c"] == 0:
        print("FAIL: no C or C++ block found")
        return 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
