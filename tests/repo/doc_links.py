#!/usr/bin/env python3
"""Every relative link and image in README.md and docs/*.md must name a file or folder of the
repository: Markdown links and images ([text](path), ![alt](path), [label]: path) and HTML
src/href attributes, outside fenced code blocks and inline code. Web addresses and in-page
anchors are not checked; a path that leaves the repository (../shared/...) is broken, since a
clone does not have it. Prints each broken link and exits 1; run by CTest as repo.doc_links.
Usage: doc_links.py SOURCE_DIR"""
import re
import sys
from pathlib import Path

INLINE = re.compile(r"!?\[[^\]]*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
REFERENCE = re.compile(r"^\s{0,3}\[[^\]]+\]:\s*<?(\S+?)>?(?:\s|$)")
HTML = re.compile(r"""(?:src|href)\s*=\s*["']([^"']+)["']""")
CODE_SPAN = re.compile(r"`+[^`]*`+")


def targets(text):
    fenced = False
    for number, line in enumerate(text.splitlines(), 1):
        if line.lstrip().startswith(("```", "~~~")):
            fenced = not fenced
            continue
        if fenced:
            continue
        line = CODE_SPAN.sub("", line)
        for pattern in (INLINE, REFERENCE, HTML):
            for m in pattern.finditer(line):
                yield number, m.group(1)


def main():
    root = Path(sys.argv[1]).resolve()
    files = [root / "README.md"] + sorted((root / "docs").glob("*.md"))
    broken = []
    checked = 0
    for md in files:
        for number, target in targets(md.read_text(encoding="utf-8")):
            if re.match(r"^[a-z][a-z0-9+.-]*:", target, re.I) or target.startswith("#"):
                continue  # a web address, mail address or an anchor in the same page
            checked += 1
            path = (md.parent / target.split("#")[0]).resolve()
            where = f"{md.relative_to(root)}:{number}: {target}"
            if root not in path.parents and path != root:
                broken.append(where + " (outside the repository)")
            elif not path.exists():
                broken.append(where + " (no such file)")
    for b in broken:
        print(b)
    print(f"{len(files)} pages, {checked} relative links checked, {len(broken)} broken")
    return 1 if broken or checked == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
