#!/usr/bin/python3
"""Checks a gallery written by `make reproduce-figures` in a real browser: opens FIGURES_DIR/index.html in
headless Chromium through Selenium and checks that
  - every <img> loaded (naturalWidth > 0);
  - every claim row shows its reference, our value (numbers) and its outcome (PASS, FAIL or UNDECIDED);
  - the headline counts equal the claim rows of each outcome;
  - every link inside the page (#anchors: figures, claims, decisions) names an element, and every relative link
    (.png, .dat, summary.json, ...) names a file that exists;
  - at a narrow window (420 px) the body does not overflow sideways (wide tables scroll in their own box);
and saves a screenshot of the top of the page as FIGURES_DIR/screenshot.png (and screenshot-narrow.png).

  browser_gallery.py FIGURES_DIR

Exit status: 0 all checks pass; 1 a check failed (each failure named on stderr); 77 Chromium, chromedriver or
Selenium is missing (`scripts/install-deps --browser` installs them), which ctest reports as skipped.
Run it with Debian's /usr/bin/python3, for which python3-selenium is installed.
"""

import shutil
import sys
import urllib.parse
from pathlib import Path

SKIP = 77
NARROW = 420
OUTCOMES = ("PASS", "FAIL", "UNDECIDED")

try:
    from selenium import webdriver
    from selenium.common.exceptions import WebDriverException
    from selenium.webdriver.chrome.service import Service
except ImportError:
    webdriver = None


def browser():
    """Headless Chromium, or None (with the reason) when it cannot be started."""
    chromium = next((shutil.which(n) for n in ("chromium", "chromium-browser", "google-chrome") if shutil.which(n)),
                    None)
    driver = shutil.which("chromedriver") or next(
        (p for p in ("/usr/bin/chromedriver", "/usr/lib/chromium/chromedriver") if Path(p).is_file()), None)
    if webdriver is None:
        return None, "python module selenium is missing (scripts/install-deps --browser; run with /usr/bin/python3)"
    if chromium is None or driver is None:
        return None, "chromium or chromedriver is missing (scripts/install-deps --browser)"
    options = webdriver.ChromeOptions()
    options.binary_location = chromium
    for argument in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                     "--allow-file-access-from-files", "--hide-scrollbars", "--window-size=1200,900"):
        options.add_argument(argument)
    try:
        return webdriver.Chrome(service=Service(driver), options=options), None
    except WebDriverException as error:
        return None, f"chromium did not start: {error.msg}"


# Everything the checks need, read from the page in one call: a page of 89 figures has thousands of elements.
READ_PAGE = """
const text = e => e.textContent.replace(/\\s+/g, ' ').trim();
return {
  images: [...document.images].map(i => [i.getAttribute('src'), i.complete, i.naturalWidth]),
  rows: [...document.querySelectorAll('tr.claim')].map(r => [r.id, r.dataset.verdict,
                                                              [...r.cells].map(c => text(c))]),
  headline: Object.fromEntries([...document.querySelectorAll('#headline .count')].map(
                                 s => [s.dataset.verdict, text(s)])),
  ids: [...document.querySelectorAll('[id]')].map(e => e.id),
  links: [...document.querySelectorAll('a[href]')].map(a => a.getAttribute('href')),
  figures: [...document.querySelectorAll('h3.figure')].map(h => h.id),
  title: document.title,
};
"""


def is_number(text):
    try:
        float(text)
        return True
    except ValueError:
        return False


def check(page, folder):
    """The failures of the page read by READ_PAGE, each as one line."""
    found = []
    if not page["figures"]:
        found.append("the page shows no figure section (h3.figure)")
    for src, complete, width in page["images"]:
        if not complete or width <= 0:
            found.append(f"image {src} did not load (naturalWidth {width})")
    counted = {}
    for row_id, verdict, cells in page["rows"]:
        counted[verdict] = counted.get(verdict, 0) + 1
        if len(cells) != 7:
            found.append(f"claim {row_id}: {len(cells)} cells, not 7")
            continue
        reference, ours, outcome = cells[2], cells[3], cells[6]
        if not is_number(reference) or not is_number(ours):
            found.append(f"claim {row_id}: reference '{reference}' and ours '{ours}' are not both numbers")
        if not outcome.startswith(OUTCOMES) or not verdict or verdict not in outcome:
            found.append(f"claim {row_id}: outcome '{outcome}' does not show a status and its verdict '{verdict}'")
    verdicts = ("as expected", "known disagreement", "regression", "undecided")
    for verdict in verdicts:
        shown = page["headline"].get(verdict)
        if shown is None:
            found.append(f"the headline shows no count of '{verdict}' claims")
        elif int(shown) != counted.get(verdict, 0):
            found.append(f"the headline counts {shown} claims '{verdict}', the page has {counted.get(verdict, 0)} rows")
    for verdict in set(counted) - set(verdicts):
        found.append(f"{counted[verdict]} claim rows have the unknown verdict '{verdict}'")
    ids = set(page["ids"])
    for link in sorted(set(page["links"])):
        parts = urllib.parse.urlsplit(link)
        if link.startswith("#"):
            if urllib.parse.unquote(link[1:]) not in ids:
                found.append(f"link {link} names no element of the page")
        elif not parts.scheme:
            target = folder / urllib.parse.unquote(parts.path)
            if not target.is_file():
                found.append(f"link {link}: {target} does not exist")
    return found


def main():
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    folder = Path(sys.argv[1]).resolve()
    index = folder / "index.html"
    if not index.is_file():
        print(f"browser_gallery: {index} does not exist", file=sys.stderr)
        return 1
    driver, reason = browser()
    if driver is None:
        print(f"browser_gallery: skipped: {reason}", file=sys.stderr)
        return SKIP
    try:
        driver.set_page_load_timeout(300)
        driver.get(index.as_uri())
        page = driver.execute_script(READ_PAGE)
        found = check(page, folder)
        driver.save_screenshot(str(folder / "screenshot.png"))
        driver.set_window_size(NARROW, 900)
        overflow = driver.execute_script(
            "window.scrollTo(0, 0); const b = document.body, d = document.documentElement;"
            "return [b.scrollWidth, d.scrollWidth, d.clientWidth];")
        if max(overflow[0], overflow[1]) > overflow[2]:
            found.append(f"at a window {NARROW} px wide the page is {max(overflow[0], overflow[1])} px wide, "
                         f"wider than the {overflow[2]} px it has: it overflows sideways")
        driver.save_screenshot(str(folder / "screenshot-narrow.png"))
    finally:
        driver.quit()
    for failure in found:
        print(f"browser_gallery: {failure}", file=sys.stderr)
    if found:
        print(f"browser_gallery: {index}: {len(found)} failures", file=sys.stderr)
        return 1
    print(f"browser_gallery: {index}: {len(page['figures'])} figures, {len(page['images'])} images loaded, "
          f"{len(page['rows'])} claim rows matching the headline, {len(set(page['links']))} links resolve, "
          f"no sideways overflow at {NARROW} px; screenshots {folder / 'screenshot.png'}, "
          f"{folder / 'screenshot-narrow.png'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
