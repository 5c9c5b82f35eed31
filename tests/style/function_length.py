"""No function in a source folder is longer than a limit (issue #26: "no function in meshing/ over
120 lines"): long builders are to read as a list of named steps, each a function of its own.

A function is a brace block opened, outside any other function, after a head holding a ')'
(namespaces, classes, structs, enums and initialiser lists are not functions). Its length is the
number of lines from the line of its '{' to the line of its '}'. Comments, string literals and
preprocessor lines are blanked first, so braces in them do not count.

  function_length.py --max LINES FOLDER...    exit 1 listing every longer function
  function_length.py --self-test              the scanner on made-up sources, exit 1 if it errs
"""
import argparse
import os
import re
import sys


def blank_comments_and_strings(src):
    """The source with comments, string and character literals replaced by blanks (newlines kept)."""
    out, i, n = [], 0, len(src)
    while i < n:
        if src.startswith("//", i):
            end = src.find("\n", i)
            i = n if end < 0 else end
        elif src.startswith("/*", i):
            end = src.find("*/", i + 2) + 2
            out.append("\n" * src.count("\n", i, end))
            i = end
        elif src.startswith('R"', i) and (i == 0 or not (src[i - 1].isalnum() or src[i - 1] == "_")):
            delimiter = re.match(r'R"([^(\s]*)\(', src[i:]).group(1)
            end = src.find(")" + delimiter + '"', i) + len(delimiter) + 2
            out.append('""' + "\n" * src.count("\n", i, end))
            i = end
        elif src[i] == '"' or (src[i] == "'" and not (i > 0 and src[i - 1].isalnum())):  # not 1'000
            quote, j = src[i], i + 1
            while j < n and src[j] != quote:
                j += 2 if src[j] == "\\" else 1
            out.append('""')
            i = j + 1
        else:
            out.append(src[i])
            i += 1
    return re.sub(r"(?m)^[ \t]*#.*$", "", "".join(out))


def block_kind(head):
    """What a '{' opens, from the text since the last ';', '{' or '}' (its head)."""
    head = re.sub(r"\btemplate\s*<[^{]*?>\s*", "", head.strip())
    if re.match(r"(namespace|extern)\b", head):
        return "scope"
    if re.search(r"\b(class|struct|union|enum)\b[^()]*$", head):
        return "scope"
    if ")" in head and not head.endswith("="):
        return "function"
    return "other"


def functions(src):
    """(first line, last line, head) of every function in a C++ source text."""
    text = blank_comments_and_strings(src)
    stack, found, head_start, line = [], [], 0, 1
    for i, c in enumerate(text):
        if c == "\n":
            line += 1
        elif c == "{":
            outside_functions = all(kind == "scope" for kind, _, _ in stack)
            kind = block_kind(text[head_start:i]) if outside_functions else "inner"
            stack.append((kind, line, " ".join(text[head_start:i].split())[-90:]))
            head_start = i + 1
        elif c == "}":
            if stack:
                kind, first, head = stack.pop()
                if kind == "function":
                    found.append((first, line, head))
            head_start = i + 1
        elif c == ";":
            head_start = i + 1
    return found


def too_long(folders, max_lines):
    """(lines, path, first line, head) of every function over max_lines in the folders' sources."""
    out = []
    for folder in folders:
        for root, _, files in os.walk(folder):
            for name in sorted(files):
                if name.endswith((".cpp", ".hpp", ".h")):
                    path = os.path.join(root, name)
                    with open(path, encoding="utf-8") as f:
                        for first, last, head in functions(f.read()):
                            if last - first + 1 > max_lines:
                                out.append((last - first + 1, path, first, head))
    return sorted(out, reverse=True)


def self_test():
    body = "\n".join("  x += %d;" % k for k in range(10))
    src = ("#include <x> // {\nnamespace a {\nnamespace {\nstruct S {\n  int f() const {\n" + body + "\n  }\n};\n"
           "}  // namespace\n/* { */ const char* s = \"{\";\nint g(int x) {\n  auto h = [&](int y) { return y; };\n"
           + body + "\n  return h(x);\n}\nint v[] = {1, 2};\n}  // namespace a\n")
    got = [(last - first + 1) for first, last, _ in functions(src)]
    want = [12, 14]  # S::f: its '{' line, 10 body lines, '}'; g: the same with a lambda and a return
    if got != want:
        print("FAIL: self-test found functions of %s lines, expected %s" % (got, want))
        return 1
    print("self-test: ok (%s)" % got)
    return 0


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--max", type=int, default=120)
    parser.add_argument("--self-test", action="store_true")
    parser.add_argument("folders", nargs="*")
    args = parser.parse_args()
    if args.self_test:
        return self_test()
    longer = too_long(args.folders, args.max)
    for lines, path, first, head in longer:
        print("FAIL: %s:%d: %d lines (limit %d): %s" % (path, first, lines, args.max, head))
    if not longer:
        print("ok: no function over %d lines in %s" % (args.max, ", ".join(args.folders)))
    return 1 if longer else 0


if __name__ == "__main__":
    sys.exit(main())
