"""README.md and docs/: every relative link leads to a file that exists and,
where it names a heading (#anchor), to a heading that exists there, under
the anchor GitHub derives from it; README stays a short entry point."""

import re
import unittest
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
PAGES = [ROOT / "README.md", *sorted((ROOT / "docs").rglob("*.md"))]
LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)\)")
FENCE = re.compile(r"^(    |\t)")


def prose(path):
    """The page's lines outside indented code blocks."""
    return [line for line in path.read_text().splitlines() if not FENCE.match(line)]


def anchor(heading):
    """GitHub's anchor for a heading: lower case, punctuation dropped, spaces to hyphens."""
    text = heading.strip().lower()
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def anchors(path):
    return {anchor(line.lstrip("#")) for line in prose(path) if re.match(r"#{1,6} ", line)}


def links(path):
    for number, line in enumerate(path.read_text().splitlines(), 1):
        if FENCE.match(line):
            continue
        for target in LINK.findall(line):
            if not re.match(r"[a-z]+:", target):
                yield number, target


class Links(unittest.TestCase):
    def test_every_relative_link_resolves(self):
        broken = []
        for page in PAGES:
            for number, target in links(page):
                file, _, heading = target.partition("#")
                resolved = (page.parent / file).resolve() if file else page
                where = f"{page.relative_to(ROOT)}:{number}: {target}"
                if not resolved.exists():
                    broken.append(f"{where}: no such file")
                elif heading and resolved.suffix == ".md" and heading not in anchors(resolved):
                    broken.append(f"{where}: no such heading")
        self.assertEqual(broken, [])

    def test_every_page_is_reached_from_the_readme(self):
        reached, queue = {PAGES[0]}, [PAGES[0]]
        while queue:
            page = queue.pop()
            for _, target in links(page):
                file = target.partition("#")[0]
                resolved = (page.parent / file).resolve() if file else page
                if resolved.suffix == ".md" and resolved.exists() and resolved not in reached:
                    reached.add(resolved)
                    queue.append(resolved)
        self.assertEqual(sorted(str(p.relative_to(ROOT)) for p in set(PAGES) - reached), [])

    def test_the_readme_is_short(self):
        self.assertLess(len(PAGES[0].read_text().splitlines()), 300)

    def test_anchors_follow_githubs_rule(self):
        self.assertEqual(anchor(" Fog, smoke and light under the surface (participating media)"),
                         "fog-smoke-and-light-under-the-surface-participating-media")
        self.assertEqual(anchor(" What a scene calls for (`caustica info`)"), "what-a-scene-calls-for-caustica-info")


if __name__ == "__main__":
    unittest.main()
