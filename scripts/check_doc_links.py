#!/usr/bin/env python3
"""Checks that every relative link in the repository's Markdown resolves inside the repository.

Usage: python3 scripts/check_doc_links.py [REPO_ROOT]  (default: the folder above scripts/)
       python3 scripts/check_doc_links.py --self-test  (plants broken links, checks each is found)

Reads every *.md file git tracks or would track (every *.md under the root when it is not a git
checkout) and checks, outside fenced code blocks:
  - relative Markdown links and images, [text](path) and [label]: path: the path, taken from the
    file's folder, must exist inside the repository; a #fragment on a Markdown target must name
    one of its headings (GitHub's anchor rule); a bare #fragment names a heading of the file;
  - repository paths written in backticks (`docs/cli.md`, `examples/pour_box.json`): a token
    whose first folder is a top-level folder of the repository must exist, taken from the
    repository root or from the file's folder. Tokens with wildcards or placeholders (*, <, {,
    NNN, an upper-case part such as NAME or DIR) are not paths and are skipped.
Links to other sites (http:, https:, mailto:) are not checked: the test must not need a network.

Prints FILE:LINE: problem for each broken link and exits 1 if there is any, else 0.
"""
import os
import re
import subprocess
import sys

LINK = re.compile(r"!?\[(?:[^\[\]]|\[[^\]]*\])*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
REFERENCE = re.compile(r"^\s{0,3}\[[^\]]+\]:\s*<?(\S+?)>?(?:\s+\".*\")?\s*$")
CODE_SPAN = re.compile(r"(`+)(.+?)\1")
FENCE = re.compile(r"^\s{0,3}(```|~~~)")
HEADING = re.compile(r"^\s{0,3}#{1,6}\s+(.*?)\s*#*\s*$")
PATH_TOKEN = re.compile(r"^[\w.\-]+(?:/[\w.\-]+)*/?$")
PATH_EXTENSIONS = (".md", ".cc", ".h", ".json", ".csv", ".sh", ".py", ".txt", ".stl", ".svg",
                   ".html", ".in", ".jsonl")
EXTERNAL = ("http:", "https:", "mailto:", "ftp:")
PLACEHOLDERS = ("*", "<", ">", "{", "}", "NNN", "...", "…")
PLACEHOLDER_PART = re.compile(r"^[A-Z][A-Z_]+$")


def markdown_files(root):
    """Every *.md git tracks or would track; every *.md under root outside a git checkout."""
    try:
        out = subprocess.run(["git", "-C", root, "ls-files", "-z", "--cached", "--others",
                              "--exclude-standard", "--", "*.md"],
                             check=True, capture_output=True).stdout.decode()
        files = [f for f in out.split("\0") if f]
        if files:
            return sorted(files)
    except (OSError, subprocess.CalledProcessError):
        pass
    found = []
    for folder, dirs, names in os.walk(root):
        dirs[:] = [d for d in dirs if not d.startswith(".") and d != "build"]
        found += [os.path.relpath(os.path.join(folder, n), root)
                  for n in names if n.endswith(".md")]
    return sorted(found)


def repository_folders(root):
    """Top-level folders that hold repository files (not build/ or out/ of a local run)."""
    try:
        out = subprocess.run(["git", "-C", root, "ls-files", "-z"],
                             check=True, capture_output=True).stdout.decode()
        folders = {f.split("/")[0] for f in out.split("\0") if "/" in f}
        if folders:
            return folders
    except (OSError, subprocess.CalledProcessError):
        pass
    return {d for d in os.listdir(root) if os.path.isdir(os.path.join(root, d)) and
            not d.startswith(".") and d not in ("build", "out")}


def rendered_text(heading):
    """The text GitHub renders for a heading: links by their text, no code or emphasis marks."""
    text = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", heading)
    return text.replace("`", "").replace("*", "")


def slug(heading):
    """GitHub's anchor for a heading: lower case, punctuation dropped, spaces to hyphens."""
    text = rendered_text(heading).strip().lower()
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def lines_outside_fences(text):
    """(line number, line) for every line that is not inside a fenced code block."""
    inside = None
    for number, line in enumerate(text.split("\n"), 1):
        fence = FENCE.match(line)
        if fence:
            if inside is None:
                inside = fence.group(1)
            elif fence.group(1) == inside:
                inside = None
            continue
        if inside is None:
            yield number, line


def anchors_of(path, cache):
    """The anchors of every heading of a Markdown file (a repeated heading gets -1, -2, ...)."""
    if path not in cache:
        seen = {}
        anchors = set()
        with open(path, encoding="utf-8") as f:
            for _, line in lines_outside_fences(f.read()):
                heading = HEADING.match(line)
                if not heading:
                    continue
                base = slug(heading.group(1))
                count = seen.get(base, 0)
                seen[base] = count + 1
                anchors.add(base if count == 0 else f"{base}-{count}")
        cache[path] = anchors
    return cache[path]


def inside(root, path):
    root = os.path.realpath(root)
    return os.path.commonpath([root, os.path.realpath(path)]) == root


def check_link(root, source, target, anchor_cache):
    """None if the link resolves, else what is wrong with it."""
    if target.startswith(EXTERNAL) or "://" in target:
        return None
    path_part, _, fragment = target.partition("#")
    path_part = path_part.split("?")[0]
    if path_part.startswith("/"):
        return f"absolute path '{target}' (write it relative to {os.path.dirname(source) or '.'}/)"
    here = os.path.dirname(os.path.join(root, source))
    resolved = (os.path.normpath(os.path.join(here, path_part)) if path_part
                else os.path.join(root, source))
    if not inside(root, resolved):
        return f"'{target}' points outside the repository"
    if not os.path.exists(resolved):
        return f"'{target}' does not exist (looked for {os.path.relpath(resolved, root)})"
    if fragment and resolved.endswith(".md") and os.path.isfile(resolved):
        if fragment not in anchors_of(resolved, anchor_cache):
            return (f"'{target}': no heading with anchor #{fragment} in "
                    f"{os.path.relpath(resolved, root)}")
    return None


def check_code_path(root, source, token, top_folders):
    """None if a backticked repository path exists (or is not one), else what is wrong."""
    token = token.strip()
    if any(p in token for p in PLACEHOLDERS) or not PATH_TOKEN.match(token):
        return None
    parts = token.rstrip("/").split("/")
    if len(parts) < 2 or parts[0] not in top_folders:
        return None  # a bare name such as `report.md` is usually an output, not a repository file
    if any(PLACEHOLDER_PART.match(part) for part in parts):
        return None  # `datasets/NAME/workflow.json`: NAME stands for any name
    basename = parts[-1]
    if not token.endswith("/") and "." in basename and not basename.endswith(PATH_EXTENSIONS):
        return None  # a kind of file the docs name loosely (a build output, a checkpoint)
    here = os.path.dirname(os.path.join(root, source))
    for base in (root, here):
        candidate = os.path.normpath(os.path.join(base, token))
        if inside(root, candidate) and os.path.exists(candidate):
            return None
    return f"`{token}` does not exist in the repository"


def check_file(root, source, top_folders, anchor_cache):
    problems = []
    with open(os.path.join(root, source), encoding="utf-8") as f:
        text = f.read()
    for number, line in lines_outside_fences(text):
        spans = [m.group(2) for m in CODE_SPAN.finditer(line)]
        prose = CODE_SPAN.sub(lambda m: " " * len(m.group(0)), line)
        targets = [m.group(1) for m in LINK.finditer(prose)]
        reference = REFERENCE.match(prose)
        if reference:
            targets.append(reference.group(1))
        for target in targets:
            problem = check_link(root, source, target, anchor_cache)
            if problem:
                problems.append(f"{source}:{number}: {problem}")
        for token in spans:
            problem = check_code_path(root, source, token, top_folders)
            if problem:
                problems.append(f"{source}:{number}: {problem}")
    return problems


def self_test():
    """Builds a small repository with known good and broken links; passes only if exactly the
    broken ones are reported, so a checker that reports nothing cannot pass."""
    import tempfile
    with tempfile.TemporaryDirectory() as root:
        os.makedirs(os.path.join(root, "docs"))
        os.makedirs(os.path.join(root, "core"))
        open(os.path.join(root, "core", "engine.h"), "w").close()
        with open(os.path.join(root, "docs", "a.md"), "w") as f:
            f.write("# Title\n\n## Time step (Δt)\n\n"
                    "[ok](b.md) [ok](b.md#b-heading) [ok](#time-step-δt) [web](https://x.org/y)\n"
                    "`core/engine.h` `docs/b.md` `core/NAME/x.h` `out/report.md` `report.md`\n"
                    "```\n[inside a fence](nowhere.md) `core/gone.h`\n```\n"
                    "[broken](missing.md)\n"
                    "[broken anchor](b.md#no-such-heading)\n"
                    "[outside](../../etc/passwd)\n"
                    "`core/gone.h`\n"
                    "[ref]: ../docs/c.md\n")
        with open(os.path.join(root, "docs", "b.md"), "w") as f:
            f.write("# B heading\n[up](../docs/a.md#title)\n")
        anchors = {}
        top = {"docs", "core"}
        got = (check_file(root, "docs/a.md", top, anchors) +
               check_file(root, "docs/b.md", top, anchors))
    want = ["docs/a.md:10:", "docs/a.md:11:", "docs/a.md:12:", "docs/a.md:13:", "docs/a.md:14:"]
    if sorted(p.split(" ")[0] for p in got) != want:
        print("check_doc_links self-test FAILED: expected problems at", want, "got:")
        for p in got:
            print("  " + p)
        return 1
    print("check_doc_links self-test: the 5 planted broken links are reported, nothing else")
    return 0


def main(argv):
    if len(argv) > 1 and argv[1] == "--self-test":
        return self_test()
    root = os.path.abspath(argv[1] if len(argv) > 1 else
                           os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
    top_folders = repository_folders(root)
    anchor_cache = {}
    files = markdown_files(root)
    problems = []
    for source in files:
        problems += check_file(root, source, top_folders, anchor_cache)
    for problem in problems:
        print(problem)
    print(f"check_doc_links: {len(files)} Markdown files, {len(problems)} broken link(s)",
          file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
