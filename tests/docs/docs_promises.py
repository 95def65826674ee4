#!/usr/bin/env python3
"""docs.promises and docs.anchors: the docs promise only what a test checks, and link only to what exists.

  docs_promises.py promises ROOT BUILD   every sentence of README.md and docs/*.md that promises
                                         behaviour -- it says "refused", "rejects", "never",
                                         "always", "every(thing)", "cannot", "can't", "won't",
                                         "must not", "exits N" -- cites the tests that check it in
                                         a comment right after it, "<!-- test: NAME -->" or
                                         "<!-- tests: NAME, NAME -->", or says why it needs none,
                                         "<!-- no test: WHY -->" (it describes the book, an
                                         algorithm, a figure, or says itself what no test
                                         covers); a WHY that starts "UNTESTED" marks a promise
                                         no test checks yet, and fails the check like a missing
                                         citation; and every NAME cited is a test of
                                         `ctest -N` in BUILD (a NAME may end in '*': then at least
                                         one test starts with the part before it); no page shows a
                                         citation in its visible text, "(test: NAME)"
  docs_promises.py anchors ROOT          every link from these pages to a page of the repository
                                         names a file that exists, and its #anchor a heading of
                                         that page (GitHub's anchors: lower case, punctuation out,
                                         spaces to '-', repeats numbered -1, -2, ...)
  docs_promises.py list ROOT             prints every promise sentence, "PAGE:LINE: sentence"

Prints each problem on a line of its own and exits 1 when there is one.
"""
import pathlib
import re
import subprocess
import sys

PROMISE = re.compile(r"\b(refused|refuses|rejects|never|always|every|everything|cannot|can't|won't|must not|"
                     r"exits? (with )?(code )?[0-9])\b", re.IGNORECASE)
CITATION = re.compile(r"<!-- tests?:\s+([^>]*?)\s*-->")
VISIBLE_CITATION = re.compile(r"\(tests?:\s|\btests?:\s+[\w*-]+\.[\w*]")
NO_TEST = re.compile(r"<!-- no test: [^>]*[a-z][^>]*-->")
ATTACHED = re.compile(r"<!-- (no test|tests?): [^>]*-->")


def pages(root):
    return [root / "README.md"] + sorted((root / "docs").rglob("*.md"))


def prose_blocks(text):
    """Yields (first line number, text) for each paragraph, list item or table row outside code
    blocks; headings and listing markers left out."""
    block, start, fenced = [], 0, False
    for number, line in enumerate(text.split("\n"), 1):
        if line.lstrip().startswith("```"):
            if block:
                yield start, "\n".join(block)
            block, fenced = [], not fenced
            continue
        if fenced:
            continue
        stripped = line.strip()
        new_item = re.match(r"^(\s*[-*+] |\s*[0-9]+\. |\|)", line) is not None
        if not stripped or stripped.startswith("#") or new_item or re.match(r"^<!-- (listing|options-for)", stripped):
            if block:
                yield start, "\n".join(block)
            block = []
            if not stripped or stripped.startswith("#") or stripped.startswith("<!-- listing"):
                continue
        if not block:
            start = number
        block.append(line)
    if block and not fenced:
        yield start, "\n".join(block)


def sentences(block):
    """Splits a block into sentences; a sentence keeps the comments and citations that follow it."""
    # Code spans and link targets may hold dots: mask them while splitting.
    def mask(m):
        text = m.group(0)
        if text.startswith("<!--"):  # the comment's text, not its "<!--"
            return "<!--" + re.sub(r"[.!?:]", "\0", text[4:-3]) + "-->"
        return re.sub(r"[.!?]", "\0", text)

    masked = re.sub(r"`[^`]*`|\]\([^)]*\)|<!--.*?-->|\([^()]*\)", mask, block, flags=re.DOTALL)
    parts, begin = [], 0
    for m in re.finditer(r"[.!?:](?=\s+(?:[A-Z0-9(`*\[]|<!--|$))|[.!?]$", masked):
        end = m.end()
        # A comment right after the sentence belongs to it.
        after = re.match(r"\s*(<!--.*?-->)", block[end:], re.DOTALL)
        if after and ATTACHED.fullmatch(after.group(1)):
            end += after.end()
        parts.append((begin, block[begin:end]))
        begin = end
    if block[begin:].strip():
        parts.append((begin, block[begin:]))
    return parts


def promises(root):
    """(page, line, sentence, citations, exempt) for every sentence with a promise word."""
    found = []
    for page in pages(root):
        text = page.read_text(encoding="utf-8")
        for start, block in prose_blocks(text):
            for offset, sentence in sentences(block):
                words = re.sub(r"`[^`]*`|<!--.*?-->|\]\([^)]*\)", "", sentence, flags=re.DOTALL)
                if not PROMISE.search(words):
                    continue
                line = start + block[:offset + len(sentence) - len(sentence.lstrip())].count("\n")
                outside_code = re.sub(r"`[^`]*`", "", sentence)
                cited = [name.strip() for group in CITATION.findall(outside_code) for name in group.split(",")]
                found.append((page.relative_to(root), line, " ".join(sentence.split()), cited,
                              NO_TEST.search(outside_code) is not None))
    return found


def ctest_names(build):
    out = subprocess.run(["ctest", "--test-dir", str(build), "-N"], capture_output=True, text=True, check=True)
    return {m.group(1) for m in re.finditer(r"^\s*Test\s+#\d+: (\S+)$", out.stdout, re.MULTILINE)}


def visible_citations(root):
    """(page, line) of each "(test: ...)" in a page's visible text (code blocks and spans aside)."""
    found = []
    for page in pages(root):
        for start, block in prose_blocks(page.read_text(encoding="utf-8")):
            visible = re.sub(r"`[^`]*`|<!--.*?-->", lambda m: re.sub(r"[^\n]", " ", m.group(0)), block, flags=re.DOTALL)
            for m in VISIBLE_CITATION.finditer(visible):
                found.append((page.relative_to(root), start + visible[:m.start()].count("\n")))
    return found


def check_promises(root, build, problem):
    names = ctest_names(build)
    for page, line in visible_citations(root):
        problem(f"{page}:{line}: a citation in the visible text: write it as <!-- tests: NAME --> after the sentence")
    for page, line, sentence, cited, exempt in promises(root):
        if not cited and not exempt:
            problem(f"{page}:{line}: a promise with no <!-- tests: ... --> and no <!-- no test: ... -->: {sentence[:160]}")
        if re.search(r"no test: untested", sentence, re.IGNORECASE):
            problem(f"{page}:{line}: a promise marked UNTESTED: test it, or say only what is tested: {sentence[:160]}")
        for name in cited:
            if not name:
                problem(f"{page}:{line}: an empty test name in a citation")
            elif name.endswith("*"):
                if not any(n.startswith(name[:-1]) for n in names):
                    problem(f"{page}:{line}: cites {name}, and no test of ctest -N starts with {name[:-1]}")
            elif name not in names:
                problem(f"{page}:{line}: cites {name}, which is not a test of ctest -N")


def github_anchor(heading, seen):
    anchor = heading.strip().lower()
    anchor = re.sub(r"<[^>]*>", "", anchor)
    anchor = re.sub(r"[^\w\- ]", "", anchor)
    anchor = anchor.replace(" ", "-")
    count = seen.get(anchor, 0)
    seen[anchor] = count + 1
    return anchor if count == 0 else f"{anchor}-{count}"


def anchors_of(page):
    seen, result, fenced = {}, set(), False
    for line in page.read_text(encoding="utf-8").split("\n"):
        if line.lstrip().startswith("```"):
            fenced = not fenced
        elif not fenced and re.match(r"^#{1,6} ", line):
            # The heading's text as GitHub renders it: code spans and links by their text.
            text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", line.lstrip("#").strip())
            result.add(github_anchor(text.replace("`", ""), seen))
    return result


def check_anchors(root, problem):
    for page in pages(root) + [root / "tests/data/README.md"]:
        text = page.read_text(encoding="utf-8")
        text = re.sub(r"```.*?```", lambda m: "\n" * m.group(0).count("\n"), text, flags=re.DOTALL)
        for number, line in enumerate(text.split("\n"), 1):
            # [text](target), [text](target "title"), and reference definitions "[name]: target".
            targets = re.findall(r"\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)", line)
            targets += re.findall(r"^\s*\[[^\]]+\]:\s+(\S+)", line)
            for target in targets:
                if re.match(r"^[a-z]+:", target):
                    continue  # https:, mailto:
                path, _, anchor = target.partition("#")
                linked = (page.parent / path).resolve() if path else page
                where = f"{page.relative_to(root)}:{number}"
                if not linked.exists():
                    problem(f"{where}: links to {target}: no such file")
                elif anchor and linked.suffix == ".md" and anchor not in anchors_of(linked):
                    problem(f"{where}: links to {target}: {linked.name} has no heading with that anchor")


def main():
    if len(sys.argv) < 3 or sys.argv[1] not in ("promises", "anchors", "list"):
        print("usage: docs_promises.py promises ROOT BUILD | anchors ROOT | list ROOT", file=sys.stderr)
        return 2
    mode, root = sys.argv[1], pathlib.Path(sys.argv[2]).resolve()
    problems = []
    if mode == "list":
        for page, line, sentence, cited, exempt in promises(root):
            mark = "cited" if cited else "no-test" if exempt else "UNCITED"
            print(f"{page}:{line}: [{mark}] {sentence}")
        return 0
    if mode == "promises":
        check_promises(root, pathlib.Path(sys.argv[3]), problems.append)
    else:
        check_anchors(root, problems.append)
    for p in problems:
        print(p)
    if problems:
        print(f"{len(problems)} problem(s)")
        return 1
    print(f"docs_promises.py {mode}: no problem")
    return 0


if __name__ == "__main__":
    sys.exit(main())
