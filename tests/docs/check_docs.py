#!/usr/bin/python3
"""Docs check: every page states what is true now and names only what exists.

Usage: check_docs.py ROOT                 print the offences of ROOT's pages; exit 1 if there is one
       check_docs.py --expect FILE ROOT   exit 0 only if ROOT has offences and they are exactly FILE's lines

Pages: every *.md under ROOT (not build*/, runs/, hidden folders, tests/docs/fixture/). For each page:
  (a) every relative link [..](path) exists (relative to the page), and every repository path the page names
      in backticks (inline or fenced code) exists: a token with a '/' whose first folder is a top-level folder
      of ROOT (relative to ROOT or to the page), or a folder beside the page (relative to the page). Skipped:
      tokens with a placeholder or glob (< > * ? { } $ ...); outputs: runs/..., build/... (but build/bin/X is a
      command, (b)), the path after --out, -o, > and the like, and in a fenced block a path whose last name an
      earlier line of the block gives (a command there creates it);
  (b) every command named in code as brash-xxx (or build/bin/brash-xxx, $B/brash-xxx) is an executable that
      a CMakeLists.txt under ROOT defines (add_executable); a file name (brash-x.log), a job name
      (--job-name=brash-x) or a log prefix ([brash-x]) is not a command;
  (c) no reference outside the repository (a ../name anywhere on the page, a link or a path that leaves ROOT), no `git show`
      citation, no work-period label (session N, "(session", "this session", "sessions", issue N [item M])
      and no machine-history phrase ("lost with", "the old machine", "since replaced", "on a quiet machine"), no
      date (YYYY-MM-DD: when a result was found is history, not a fact about the project).
Prints each offence as FILE:LINE: problem.
"""
import os
import re
import sys

SKIP_DIRS = {"runs", "__pycache__", "generated", "node_modules"}
FIXTURE = os.path.join("tests", "docs", "fixture")
PLACEHOLDER = re.compile(r"[<>*?{}$\[\]|]|\.\.\.")
TOKEN_SPLIT = re.compile(r"[\s=,;()\"']+")
LINK = re.compile(r"(?<!!)\[[^\]]*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")
INLINE_CODE = re.compile(r"`([^`]+)`")
COMMAND = re.compile(r"(?<![\w.=\[-])brash-[a-z0-9][a-z0-9-]*")
OUTPUT_OPTIONS = {"--out", "-o", "--output", ">", ">>", "--runs-root", "--prefix"}
# (c): a parent-folder reference anywhere on a line (prose or code), checked against where it leads
PARENT_REF = re.compile(r"(?<![\w./-])((?:\.\./)+[\w.-]+)")
ADD_EXE = re.compile(r"add_executable\(\s*([A-Za-z0-9_.-]+)")

# (c): text that is never true "now" for a reader of the repository.
FORBIDDEN = [
    (re.compile(r"\bgit show\b"), "git show citation (state the fact, name its source in the repository)"),
    (re.compile(r"\bsessions?\s+\d+", re.I), "work-period label (session N)"),
    (re.compile(r"\(session\b", re.I), "work-period label ((session ...)"),
    (re.compile(r"\b(this|each|a|one|the|that|every|next|previous|last|earlier|later|its)\s+session('s)?\b", re.I),
     "work-period label (session)"),
    (re.compile(r"\bsessions\b", re.I), "work-period label (sessions)"),
    (re.compile(r"\bissue\s+#?\d+(\s+item\s+\d+|'s)?", re.I), "work-period label (issue N as provenance)"),
    (re.compile(r"\blost with\b", re.I), "machine-history phrase (lost with)"),
    (re.compile(r"\b(the\s+)?old machine\b", re.I), "machine-history phrase (the old machine)"),
    (re.compile(r"\bmachine since replaced\b|\bsince replaced\b", re.I), "machine-history phrase (since replaced)"),
    (re.compile(r"\b20\d\d-[01]\d-[0-3]\d\b"), "date label (a page states what is true now; when it was found is history)"),
    (re.compile(r"\bon a quiet machine\b|\bthe shared 2-core host\b|\bthis (loaded )?host\b", re.I),
     "machine-history phrase (which machine, when)"),
]


def pages(root):
    for dirpath, dirnames, filenames in os.walk(root):
        rel = os.path.relpath(dirpath, root)
        dirnames[:] = sorted(d for d in dirnames
                             if not d.startswith(".") and d not in SKIP_DIRS
                             and not (rel == "." and d.startswith("build"))
                             and os.path.normpath(os.path.join(rel, d)) != FIXTURE)
        for f in sorted(filenames):
            if f.endswith(".md"):
                yield os.path.normpath(os.path.join(rel, f))


def executables(root):
    found = set()
    for dirpath, dirnames, filenames in os.walk(root):
        rel = os.path.relpath(dirpath, root)
        dirnames[:] = [d for d in dirnames if not d.startswith(".") and d not in SKIP_DIRS
                       and not (rel == "." and d.startswith("build"))
                       and os.path.normpath(os.path.join(rel, d)) != FIXTURE]
        if "CMakeLists.txt" in filenames:
            with open(os.path.join(dirpath, "CMakeLists.txt"), encoding="utf-8") as f:
                found.update(ADD_EXE.findall(f.read()))
    return found


def top_folders(root):
    return {d for d in os.listdir(root) if os.path.isdir(os.path.join(root, d)) and not d.startswith(".")
            and not d.startswith("build") and d not in SKIP_DIRS}


def inside(root, path):
    real_root = os.path.realpath(root)
    real = os.path.realpath(path)
    return real == real_root or real.startswith(real_root + os.sep)


def code_spans(lines):
    """(line number, code text, earlier lines of its fenced block) for every inline code span and fenced line."""
    fenced = False
    block = ""
    for n, line in enumerate(lines, 1):
        stripped = line.strip()
        if stripped.startswith("```") or stripped.startswith("~~~"):
            fenced = not fenced
            block = ""
            continue
        if fenced:
            yield n, line, block
            block += line + "\n"
        else:
            for m in INLINE_CODE.finditer(line):
                yield n, m.group(1), ""


def check_path_token(root, page_dir, token, tops):
    """None if fine or not a repository path; else the problem."""
    token = token.lstrip("(").rstrip(".:;,!)/")
    if "/" not in token or "://" in token or token.startswith("/") or PLACEHOLDER.search(token):
        return None
    if token.startswith("~") or token.startswith("-"):
        return None
    t = token[2:] if token.startswith("./") else token
    first = t.split("/", 1)[0]
    if first == "..":
        target = os.path.normpath(os.path.join(root, page_dir, t))
        if not inside(root, target):
            return "path outside the repository: %s" % token
        return None if os.path.exists(target) else "no such file: %s" % token
    if first in ("runs", "build") or "generated" in t.split("/"):
        return None  # outputs (build/bin/X is checked as a command; a case's generated/ is written by brash-pack)
    if first in tops:
        if os.path.exists(os.path.join(root, t)) or (page_dir and os.path.exists(os.path.join(root, page_dir, t))):
            return None
        return "no such file: %s" % token
    if page_dir and os.path.isdir(os.path.join(root, page_dir, first)):
        return None if os.path.exists(os.path.join(root, page_dir, t)) else "no such file: %s" % token
    return None


def check_page(root, page, exes, tops):
    problems = []
    page_dir = os.path.dirname(page)
    with open(os.path.join(root, page), encoding="utf-8") as f:
        lines = f.read().split("\n")
    fenced = False
    for n, line in enumerate(lines, 1):
        if line.strip().startswith("```"):
            fenced = not fenced
        for pattern, what in FORBIDDEN:
            if pattern.search(line):
                problems.append((n, what))
        for m in PARENT_REF.finditer(line):
            if not inside(root, os.path.join(root, page_dir, m.group(1))):
                problems.append((n, "reference outside the repository: %s" % m.group(1)))
        if fenced:
            continue
        for m in LINK.finditer(INLINE_CODE.sub("", line)):
            target = m.group(1).split("#", 1)[0]
            if not target or re.match(r"^[a-z]+:", target):
                continue
            full = os.path.normpath(os.path.join(root, page_dir, target))
            if not inside(root, full):
                problems.append((n, "link outside the repository: %s" % target))
            elif not os.path.exists(full):
                problems.append((n, "broken link: %s" % target))
    seen = set()
    for n, code, block in code_spans(lines):
        previous = ""
        for token in TOKEN_SPLIT.split(code):
            if not token:
                continue
            output = previous in OUTPUT_OPTIONS
            previous = token
            if output:
                continue  # what a command writes (--out DIR, > FILE)
            problem = check_path_token(root, page_dir, token, tops)
            last = token.rstrip(".:;,!)/").rsplit("/", 1)[-1]
            if problem and problem.startswith("no such file") and re.search(r"(?<![\w.-])%s(?![\w.-])" % re.escape(last), block):
                continue  # in a code block, a path that an earlier command of the block creates
            if problem and (n, problem) not in seen:
                seen.add((n, problem))
                problems.append((n, problem))
        for m in COMMAND.finditer(code):
            before = code[:m.start()]
            if before.endswith("/") and not re.search(r"(^|[\s$])(\$\w+|[\w./]*bin)/$", before):
                continue  # part of a path that is not a bin folder
            name = m.group(0)
            after = code[m.end():m.end() + 2]
            if after[:1] in ("/", "_") or re.match(r"\.\w", after):
                continue  # a file or folder name (brash-x.log, brash-x/), not a command
            if name not in exes and (n, name) not in seen:
                seen.add((n, name))
                problems.append((n, "no such command: %s (no add_executable defines it)" % name))
    return sorted(problems)


def offences(root):
    exes = executables(root)
    tops = top_folders(root)
    return ["%s:%d: %s" % (page, n, problem)
            for page in pages(root) for n, problem in check_page(root, page, exes, tops)]


def main():
    args = sys.argv[1:]
    expect = None
    if len(args) == 3 and args[0] == "--expect":
        expect, args = args[1], args[2:]
    if len(args) != 1:
        print(__doc__)
        return 2
    found = offences(args[0])
    for line in found:
        print(line)
    print("%d offence(s)" % len(found))
    if expect is None:
        return 1 if found else 0
    with open(expect, encoding="utf-8") as f:
        wanted = [line for line in f.read().split("\n") if line and not line.endswith("offence(s)")]
    if found and found == wanted:
        print("as expected (%s)" % expect)
        return 0
    for line in wanted:
        if line not in found:
            print("expected, not found: " + line)
    for line in found:
        if line not in wanted:
            print("found, not expected: " + line)
    return 1


if __name__ == "__main__":
    sys.exit(main())
