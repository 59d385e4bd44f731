#!/usr/bin/env python3
"""Checks the links of README.md and docs/*.md: every relative link names a file that exists, and
every #anchor names a heading of its target page, as GitHub makes heading anchors (lower case,
punctuation dropped, spaces to hyphens, -1, -2 ... for repeats). Links to the web are not fetched.

usage: check-doc-links.py [ROOT]    (ROOT: the checkout, default the folder above this script)
Prints one line per broken link (page: link) and exits 1 if there is any, else 0.
"""
import os
import re
import sys

FENCED_CODE = re.compile(r"^```.*?^```", re.S | re.M)
HEADING = re.compile(r"^#{1,6} +(.*?) *#*$", re.M)
LINK = re.compile(r"\]\(([^)\s]+)(?: \"[^\"]*\")?\)")


def prose(text):
    """The page without its fenced code blocks, whose '#' lines are not headings."""
    return FENCED_CODE.sub("", text)


def slug(heading):
    text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", heading)  # a link in a heading: its text
    text = text.replace("`", "").strip().lower()
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def anchors_of(text):
    seen, anchors = {}, set()
    for match in HEADING.finditer(prose(text)):
        base = slug(match.group(1))
        repeat = seen.get(base, 0)
        seen[base] = repeat + 1
        anchors.add(base if repeat == 0 else "%s-%d" % (base, repeat))
    return anchors


def pages(root):
    docs = os.path.join(root, "docs")
    names = sorted(f for f in os.listdir(docs) if f.endswith(".md")) if os.path.isdir(docs) else []
    return ["README.md"] + [os.path.join("docs", f) for f in names]


def broken_links(root):
    texts = {page: open(os.path.join(root, page), encoding="utf-8").read() for page in pages(root)}
    anchors = {}
    broken = []
    for page, text in texts.items():
        for match in LINK.finditer(prose(text)):
            link = match.group(1)
            if re.match(r"[a-z][a-z0-9+.-]*:", link):  # http:, https:, mailto:
                continue
            path, _, fragment = link.partition("#")
            target = os.path.normpath(os.path.join(os.path.dirname(page), path)) if path else page
            if not os.path.exists(os.path.join(root, target)):
                broken.append("%s: %s (no such file)" % (page, link))
                continue
            if not fragment or not target.endswith(".md"):
                continue
            if target not in anchors:
                anchors[target] = anchors_of(texts.get(target) or open(os.path.join(root, target), encoding="utf-8").read())
            if fragment not in anchors[target]:
                broken.append("%s: %s (no such heading in %s)" % (page, link, target))
    return broken


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
    broken = broken_links(root)
    for line in broken:
        print(line)
    print("check-doc-links: %d pages, %d broken links" % (len(pages(root)), len(broken)))
    return 1 if broken else 0


if __name__ == "__main__":
    sys.exit(main())
