#!/usr/bin/env python3
"""Checks a gallery written by `make reproduce-figures`, reading only what a user sees: figures/index.html and
the files it links. Every figure of `scripts/reproduce list` must have its section, an entry in the contents
table, a PNG image that exists and a link to its .dat table; every link inside the page (#anchors) must name an
element that exists, every id must be unique, every relative link must name a file of the folder; the
headline counts must equal the claim rows; and the gallery must name no figure that could not be made.
(verification/support/browser_gallery.py checks the same page in a real browser.)

  check_gallery.py FIGURES_DIR
"""

import collections
import html.parser
import os
import subprocess
import sys
import urllib.parse
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


class Gallery(html.parser.HTMLParser):
    """The figure sections, contents entries, ids, links, image sources, claim rows, headline counts and error
    marks of index.html."""

    def __init__(self):
        super().__init__()
        self.sections, self.contents, self.images, self.errors = set(), set(), set(), 0
        self.ids, self.links = collections.Counter(), []
        self.claim_rows, self.headline, self.counting = collections.Counter(), {}, None

    def handle_starttag(self, tag, attrs):
        attributes = dict(attrs)
        classes = (attributes.get("class") or "").split()
        if "id" in attributes:
            self.ids[attributes["id"]] += 1
        if tag == "h3" and "figure" in classes and "id" in attributes:
            self.sections.add(attributes["id"])
        if tag == "tr" and "entry" in classes:
            self.contents.add(attributes.get("data-figure"))
        if tag == "tr" and "claim" in classes:
            self.claim_rows[attributes.get("data-verdict")] += 1
        if tag == "span" and "count" in classes:
            self.counting = attributes.get("data-verdict")
        if tag == "img":
            self.images.add(attributes.get("src", ""))
        if tag == "a" and "href" in attributes:
            self.links.append(attributes["href"])
        if "ERROR" in classes:
            self.errors += 1

    def handle_data(self, data):
        if self.counting is not None:
            self.headline[self.counting] = int(data)
            self.counting = None


def link_problems(figures_dir, gallery):
    """Anchors that name no element, ids used twice, relative links to files that do not exist."""
    found = [f"id '{i}' is used {n} times" for i, n in gallery.ids.items() if n > 1]
    for link in sorted(set(gallery.links)):
        if link.startswith("#"):
            if urllib.parse.unquote(link[1:]) not in gallery.ids:
                found.append(f"link {link} names no element")
        elif not urllib.parse.urlsplit(link).scheme:
            path = urllib.parse.unquote(urllib.parse.urlsplit(link).path)
            if Path(path).is_absolute() or os.path.normpath(path).startswith(".."):
                found.append(f"link {link} leaves the folder {figures_dir}")
            elif not (figures_dir / path).is_file():
                found.append(f"link {link}: {figures_dir / path} does not exist")
    return found


def problems(figures_dir):
    index = figures_dir / "index.html"
    if not index.is_file():
        return [f"{index} was not written"]
    gallery = Gallery()
    gallery.feed(index.read_text())
    listed = subprocess.run([sys.executable, str(ROOT / "scripts" / "reproduce"), "list"], check=True,
                            capture_output=True, text=True).stdout.split()
    found = []
    for name in listed:
        paper, _, figure_id = name.partition("/")
        image = f"{paper}/{figure_id}.png"
        if figure_id not in gallery.sections:
            found.append(f"{name}: no section in index.html")
        elif figure_id not in gallery.contents:
            found.append(f"{name}: no entry in the contents table")
        elif image not in gallery.images:
            found.append(f"{name}: index.html shows no image {image}")
        elif not (figures_dir / image).is_file():
            found.append(f"{name}: {image} does not exist")
        elif not (figures_dir / image).read_bytes().startswith(PNG_SIGNATURE):
            found.append(f"{name}: {image} is not a PNG image")
        elif f"{paper}/{figure_id}.dat" not in gallery.links:
            found.append(f"{name}: index.html links no table {paper}/{figure_id}.dat")
    found += link_problems(figures_dir, gallery)
    verdicts = ("as expected", "known disagreement", "regression", "undecided")
    if set(gallery.headline) != set(verdicts):
        found.append(f"the headline counts {sorted(gallery.headline)}, not {list(verdicts)}")
    for verdict in verdicts:
        if gallery.headline.get(verdict) != gallery.claim_rows[verdict]:
            found.append(f"the headline counts {gallery.headline.get(verdict)} claims '{verdict}', the figures "
                         f"show {gallery.claim_rows[verdict]}")
    if gallery.errors:
        found.append(f"index.html marks {gallery.errors} elements as errors (figures that could not be made)")
    return found if listed else ["scripts/reproduce list names no figure"]


def main():
    figures_dir = Path(sys.argv[1])
    found = problems(figures_dir)
    for problem in found:
        print(f"check_gallery: {problem}", file=sys.stderr)
    if not found:
        print(f"check_gallery: {figures_dir / 'index.html'} shows every figure of 'reproduce list' with its image, "
              "contents entry and table; every link resolves; the headline counts equal the claim rows")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
