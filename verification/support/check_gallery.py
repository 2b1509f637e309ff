#!/usr/bin/env python3
"""Checks a gallery written by `make reproduce-figures`, reading only what a user sees: figures/index.html and
the images it links. Every figure of `scripts/reproduce list` must have its section and a PNG image that
exists, and the gallery must name no figure that could not be made.

  check_gallery.py FIGURES_DIR
"""

import html.parser
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


class Gallery(html.parser.HTMLParser):
    """The section anchors, image sources and error marks of index.html."""

    def __init__(self):
        super().__init__()
        self.sections, self.images, self.errors = set(), set(), 0

    def handle_starttag(self, tag, attrs):
        attributes = dict(attrs)
        if tag == "h2" and "id" in attributes:
            self.sections.add(attributes["id"])
        if tag == "img":
            self.images.add(attributes.get("src", ""))
        if "ERROR" in (attributes.get("class") or "").split():
            self.errors += 1


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
        elif image not in gallery.images:
            found.append(f"{name}: index.html shows no image {image}")
        elif not (figures_dir / image).is_file():
            found.append(f"{name}: {image} does not exist")
        elif not (figures_dir / image).read_bytes().startswith(PNG_SIGNATURE):
            found.append(f"{name}: {image} is not a PNG image")
    if gallery.errors:
        found.append(f"index.html marks {gallery.errors} elements as errors (figures that could not be made)")
    return found if listed else ["scripts/reproduce list names no figure"]


def main():
    figures_dir = Path(sys.argv[1])
    found = problems(figures_dir)
    for problem in found:
        print(f"check_gallery: {problem}", file=sys.stderr)
    if not found:
        print(f"check_gallery: {figures_dir / 'index.html'} shows every figure of 'reproduce list' with its image")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
